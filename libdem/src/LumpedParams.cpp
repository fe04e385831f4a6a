#include "libdem/LumpedParams.hpp"

#include <stdexcept>
#include <string>

namespace sylva::dem {

// Rockyfor3D's soil types and their normal restitution (Dorren 2016, Table 2 of the model
// description; docs/lumped.md): mean and the half-width of the range R_n is drawn from.
SoilRestitution soilRestitution(int soilType) {
    static const SoilRestitution kTypes[] = {
        {0.0, 0.0, "river, swamp or material in which a rock penetrates completely"},
        {0.23, 0.02, "fine soil material (depth > ~100 cm)"},
        {0.28, 0.03, "fine soil material (depth < ~100 cm), or sand/gravel mix in the valley"},
        {0.33, 0.03, "scree (diameter < ~10 cm), medium compact soil with small rock fragments, or forest road"},
        {0.38, 0.04, "talus slope (diameter > ~10 cm), or compact soil with large rock fragments"},
        {0.43, 0.04, "bedrock with thin weathered material or soil cover"},
        {0.53, 0.05, "bedrock"},
        {0.35, 0.03, "asphalt road"},
    };
    if (soilType < 0 || soilType > 7)
        throw std::invalid_argument("Rockyfor3D soil type " + std::to_string(soilType) + ": expected 0 to 7");
    return kTypes[soilType];
}

}  // namespace sylva::dem
