#pragma once
// Bodies that touch one another, grouped into islands (union-find with path halving): stems in contact
// rest and sleep together or not at all, as touching bodies do in Box2D's and Jolt's island sleeping.
// ForestMotion::sleep builds them afresh at every step, from that step's stem/stem contacts.
#include <cstddef>
#include <vector>

namespace sylva::dem {

class Islands {
public:
    // n bodies, each an island of its own.
    void reset(std::size_t n) {
        parent_.resize(n);
        for (std::size_t i = 0; i < n; ++i) parent_[i] = i;
    }
    void join(std::size_t a, std::size_t b) { parent_[root(a)] = root(b); }
    // The same for every body of an island, and an index in [0, n).
    std::size_t root(std::size_t i) {
        while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
        return i;
    }
    // An island goes (rests, sleeps) as a whole: allowed until any of its bodies forbids it.
    void allowAll() { islandMay_.assign(parent_.size(), true); }
    void forbid(std::size_t i) { islandMay_[root(i)] = false; }
    bool allowed(std::size_t i) { return islandMay_[root(i)]; }

private:
    std::vector<std::size_t> parent_;
    std::vector<bool> islandMay_;  // per root
};

}  // namespace sylva::dem
