// A soil types' table (name,code[,kn_n_m,kappa,damping_ratio|restitution,friction_deg]) as
// `sylvarock hazard --soil-types` reads it.
#include "FuzzFile.hpp"
#include "libassess/SoilMap.hpp"
#include "libcommon/InputError.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sylva;
    try {
        assess::readSoilTypes(fuzz::file("soils.csv", fuzz::text(data, size)), dem::SoilContactParams{});
    } catch (const InputError&) {
    }
    return 0;
}
