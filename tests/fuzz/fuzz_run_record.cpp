// A finished run as an MPI rank sends it to the coordinator (one line of text with its checksum):
// a garbled line is refused (no value), never a crash or a half-read record.
#include <cstdlib>

#include "FuzzFile.hpp"
#include "libassess/RunRecord.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto record = sylva::assess::parseRunLine(sylva::fuzz::text(data, size));
    if (!record) return 0;
    // What is accepted is a whole record: written again, it reads back to the very same values.
    const std::string line = sylva::assess::formatRunLine(*record);
    const auto again = sylva::assess::parseRunLine(line);
    if (!again || sylva::assess::formatRunLine(*again) != line) std::abort();
    return 0;
}
