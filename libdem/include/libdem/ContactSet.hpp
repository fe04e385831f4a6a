#pragma once
// The contacts of one kind (block/stem, stem/stem, stem/soil) that persist from step to step with
// their histories, keyed by the features that touch (e.g. block sphere, tree, piece). Written once
// for every kind: each step's detection marks what it finds (`find`, else `add`), then `sweep`
// forgets the contacts that were not found again. Lookups go by hash; the contacts keep the order in
// which they began, which fixes the order their forces are summed in (same results whatever else).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace sylva::dem {

using ContactKey = std::array<std::uint32_t, 4>;

struct ContactKeyHash {
    std::size_t operator()(const ContactKey& k) const {
        std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the four words
        for (std::uint32_t w : k) h = (h ^ w) * 1099511628211ull;
        return static_cast<std::size_t>(h);
    }
};

// Touch: a contact record with a `bool touching` (found at this step's detection).
template <class Touch>
class ContactSet {
public:
    using iterator = typename std::vector<Touch>::iterator;
    using const_iterator = typename std::vector<Touch>::const_iterator;

    // Before a detection: nothing is touching until found again.
    void beginDetection() {
        for (Touch& t : touches_) t.touching = false;
    }
    Touch* find(const ContactKey& key) {
        const auto it = index_.find(key);
        return it == index_.end() ? nullptr : &touches_[it->second];
    }
    // A contact that began at this step.
    Touch& add(const ContactKey& key, Touch touch) {
        index_.emplace(key, touches_.size());
        keys_.push_back(key);
        touches_.push_back(std::move(touch));
        return touches_.back();
    }
    // Gives each contact the key `keyOf(touch, key)` returns: the features a contact is known by
    // changed (a stem broke under it) while its history goes on.
    template <class KeyOf>
    void rekey(KeyOf keyOf) {
        bool changed = false;
        for (std::size_t i = 0; i < touches_.size(); ++i) {
            const ContactKey key = keyOf(touches_[i], keys_[i]);
            changed = changed || key != keys_[i];
            keys_[i] = key;
        }
        if (!changed) return;
        index_.clear();
        for (std::size_t i = 0; i < keys_.size(); ++i) index_.emplace(keys_[i], i);
    }
    // After a detection: the contacts not found again have ended.
    void sweep() {
        eraseIf([](const Touch& t) { return !t.touching; });
    }
    // The same, telling `ended` of each first (ContactLaw::end books what their last forces did).
    template <class OnEnd>
    void sweep(OnEnd ended) {
        for (Touch& t : touches_)
            if (!t.touching) ended(t);
        sweep();
    }
    template <class Predicate>
    void eraseIf(Predicate ended) {
        std::size_t kept = 0;
        for (std::size_t i = 0; i < touches_.size(); ++i) {
            if (ended(touches_[i])) continue;
            if (kept != i) {
                touches_[kept] = std::move(touches_[i]);
                keys_[kept] = keys_[i];
            }
            ++kept;
        }
        if (kept == touches_.size()) return;
        touches_.resize(kept);
        keys_.resize(kept);
        index_.clear();
        for (std::size_t i = 0; i < kept; ++i) index_.emplace(keys_[i], i);
    }

    iterator begin() { return touches_.begin(); }
    iterator end() { return touches_.end(); }
    const_iterator begin() const { return touches_.begin(); }
    const_iterator end() const { return touches_.end(); }
    std::size_t size() const { return touches_.size(); }
    bool empty() const { return touches_.empty(); }

private:
    std::vector<Touch> touches_;
    std::vector<ContactKey> keys_;  // of touches_, to rebuild the index after erasing
    std::unordered_map<ContactKey, std::size_t, ContactKeyHash> index_;
};

}  // namespace sylva::dem
