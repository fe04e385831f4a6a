#pragma once
// Bodies that touch one another, grouped into islands (union-find with path halving): stems in contact
// rest and sleep together or not at all, as touching bodies do in Box2D's and Jolt's island sleeping.
// Reset once per use; at the forest's sizes (tens of awake stems) it costs less than one node-step.
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
    // Per body: whether every body of its island `may` (rest, sleep): an island goes as a whole.
    std::vector<bool> whole(const std::vector<bool>& may) {
        const std::size_t n = parent_.size();
        std::vector<bool> islandMay(n, true), out(n);
        for (std::size_t i = 0; i < n; ++i)
            if (!may[i]) islandMay[root(i)] = false;
        for (std::size_t i = 0; i < n; ++i) out[i] = islandMay[root(i)];
        return out;
    }

private:
    std::vector<std::size_t> parent_;
};

}  // namespace sylva::dem
