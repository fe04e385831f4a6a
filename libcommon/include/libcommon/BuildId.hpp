#pragma once
// The commit this program was built from (`git describe --always --dirty`; "unknown" outside a git
// clone). Stores of runs record it: runs made by another build need not be the same runs.
#include <string>
#include <vector>

namespace sylva {

const char* buildId();

// The comment line a store of runs keeps among its inputs: "# made by sylvarock build <id>".
std::string madeByLine();

// What a resume should tell the user about the build that made a store's runs, given the store's
// lines (its inputs or design): nothing when this build made them, otherwise a note naming both builds
// and what to do (`what` is what a new --out starts, "campaign" or "map"). Stores from before builds
// were recorded have no such line; those of 28 Nov. 2026 wrote "# made by sylvarock <id>".
std::string otherBuildNote(const std::string& where, const std::vector<std::string>& storedLines, const std::string& what);

}  // namespace sylva
