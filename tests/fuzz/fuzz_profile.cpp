// A slope profile (x, z) CSV.
#include "FuzzFile.hpp"
#include "libdem/SlopeProfile.hpp"
#include "libcommon/InputError.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sylva;
    try {
        dem::SlopeProfile::readCsv(fuzz::file("profile.csv", fuzz::text(data, size)));
    } catch (const InputError&) {
    }
    return 0;
}
