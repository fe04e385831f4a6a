#include "libassess/BlockVolumes.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "libcommon/InputError.hpp"

namespace sylva::assess {

std::vector<BlockVolumeClass> parseBlockVolumes(const std::string& text) {
    std::vector<BlockVolumeClass> classes;
    std::stringstream list(text);
    for (std::string item; std::getline(list, item, ',');) {
        BlockVolumeClass c;
        const auto colon = item.find(':');
        const auto number = [&](const std::string& s, const char* what) {
            std::size_t used = 0;
            double v = std::nan("");
            try {
                v = std::stod(s, &used);
            } catch (const std::exception&) {
            }
            if (used != s.size() || !std::isfinite(v))
                throw InputError("--block-volumes '" + text + "': " + what + " '" + s + "' is not a number (expected V1,V2,... or V1:W1,V2:W2,...)");
            return v;
        };
        c.volumeM3 = number(item.substr(0, colon), "volume");
        if (colon != std::string::npos) c.weight = number(item.substr(colon + 1), "weight");
        if (!(c.volumeM3 > 0 && c.volumeM3 <= 1000))
            throw InputError("--block-volumes '" + text + "': a volume of " + readableNumber(c.volumeM3) + " m3 is not in (0, 1000]");
        if (!(c.weight > 0)) throw InputError("--block-volumes '" + text + "': a weight of " + readableNumber(c.weight) + " is not positive");
        classes.push_back(c);
    }
    if (classes.empty()) throw InputError("--block-volumes: empty list (expected V1,V2,... or V1:W1,V2:W2,...)");
    // std::getline drops an empty last item: "1," would read as "1".
    if (text.back() == ',') throw InputError("--block-volumes '" + text + "': an empty item after the last comma");
    // Weights on some classes and not others mean nothing clear; the mix is also what a decimal comma
    // gives ("2,5:1" for 2.5 m3 of weight 1 read as 2 m3 and 5 m3).
    const std::size_t weighted = std::count(text.begin(), text.end(), ':');
    if (weighted > 0 && weighted < classes.size())
        throw InputError("--block-volumes '" + text + "': " + std::to_string(weighted) + " of the " + std::to_string(classes.size()) +
                         " classes have a weight: give every class one (V1:W1,V2:W2,...) or none (V1,V2,...); decimals take a point, "
                         "2.5 not 2,5");
    for (std::size_t i = 0; i < classes.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (classes[i].volumeM3 == classes[j].volumeM3)
                throw InputError("--block-volumes '" + text + "': the volume " + readableNumber(classes[i].volumeM3) +
                                 " m3 is listed twice: give each class once, with a weight (V:W) for its share");
    // The shares are the weights over their sum, which must not overflow.
    double total = 0;
    for (const auto& c : classes) total += c.weight;
    if (!std::isfinite(total)) throw InputError("--block-volumes '" + text + "': the weights' sum overflows; they are relative, give smaller ones");
    return classes;
}

BlockVolumeScenes::BlockVolumeScenes(const dem::Scene& scene, const std::vector<BlockVolumeClass>& classes) {
    if (classes.empty()) {
        scenes_.push_back(&scene);
        return;
    }
    double total = 0;
    for (const auto& c : classes) total += c.weight;
    double sum = 0;
    for (const auto& c : classes) {
        resized_.push_back(scene.withBlockVolume(c.volumeM3));
        upTo_.push_back((sum += c.weight) / total);
    }
    upTo_.back() = 1;
    for (const auto& r : resized_) scenes_.push_back(&r);
}

std::size_t BlockVolumeScenes::of(double u) const {
    std::size_t k = 0;
    while (k + 1 < upTo_.size() && u >= upTo_[k]) ++k;
    return k;
}

}  // namespace sylva::assess
