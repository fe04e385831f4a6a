#pragma once
// Which law governs a contact between two kinds of body. Adding a law = writing one ContactLaw
// type and registering it here for a pair of kinds; detection and the step loop stay unchanged.
#include <array>
#include <memory>

#include "libdem/ContactLaw.hpp"

namespace sylva::dem {

enum class BodyKind : unsigned char { Block, Soil, Stem, Count };

class ContactLawTable {
public:
    void set(BodyKind a, BodyKind b, std::shared_ptr<const ContactLaw> law);
    // Throws std::logic_error if no law was registered for the pair (a scene-building bug).
    const ContactLaw& get(BodyKind a, BodyKind b) const;

private:
    static constexpr std::size_t kKinds = static_cast<std::size_t>(BodyKind::Count);
    std::array<std::shared_ptr<const ContactLaw>, kKinds * kKinds> laws_{};
};

}  // namespace sylva::dem
