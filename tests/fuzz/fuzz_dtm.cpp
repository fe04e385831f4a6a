// An ESRI ASCII grid DTM.
#include "FuzzFile.hpp"
#include "libdem/ElevationGrid.hpp"
#include "libcommon/InputError.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sylva;
    try {
        dem::ElevationGrid::readAsc(fuzz::file("dtm.asc", fuzz::text(data, size)));
    } catch (const InputError&) {
    }
    return 0;
}
