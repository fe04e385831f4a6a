#pragma once
// The commit this program was built from (`git describe --always --dirty`; "unknown" outside a git
// clone). Stores of runs record it: runs made by another build need not be the same runs.
namespace sylva {
const char* buildId();
}  // namespace sylva
