// A forest file (x, y, dbh_cm[, stool]) as `simulate --forest` reads it.
#include "FuzzFile.hpp"
#include "libstand/Forest.hpp"
#include "libcommon/InputError.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sylva;
    try {
        stand::readForestCsv(fuzz::file("forest.csv", fuzz::text(data, size)));
    } catch (const InputError&) {
    }
    return 0;
}
