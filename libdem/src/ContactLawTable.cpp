#include "libdem/ContactLawTable.hpp"

#include <stdexcept>

namespace sylva::dem {

namespace {
std::size_t slot(BodyKind a, BodyKind b, std::size_t n) { return static_cast<std::size_t>(a) * n + static_cast<std::size_t>(b); }
}  // namespace

void ContactLawTable::set(BodyKind a, BodyKind b, std::shared_ptr<const ContactLaw> law) {
    laws_[slot(a, b, kKinds)] = law;
    laws_[slot(b, a, kKinds)] = std::move(law);
}

const ContactLaw& ContactLawTable::get(BodyKind a, BodyKind b) const {
    const auto& law = laws_[slot(a, b, kKinds)];
    if (!law) throw std::logic_error("no contact law registered for this pair of body kinds");
    return *law;
}

}  // namespace sylva::dem
