// An assessment's run log as --resume reads it (a campaign of 50 runs seeded 7): damaged lines are
// dropped with a note, foreign ones refused with InputError.
#include <vector>

#include "FuzzFile.hpp"
#include "libassess/RunLog.hpp"
#include "libstand/InputError.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sylva;
    std::vector<std::string> notes;
    try {
        assess::RunLog log(fuzz::file("runs.csv", fuzz::text(data, size)), 50, 7, notes);
        log.missingRuns();
    } catch (const InputError&) {
    }
    return 0;
}
