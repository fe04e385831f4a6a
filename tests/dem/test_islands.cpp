// Stems in contact rest and sleep as one island (Islands.hpp, ForestMotion::sleep): one that may not
// keeps every stem it touches, directly or through others, and nothing else; and stems that all may
// go together (asked stem by stem, two stems leaning on each other kept each other stepped for ever:
// docs/performance.md, "Islands").
#include <gtest/gtest.h>

#include <vector>

#include "libdem/Islands.hpp"

using namespace sylva::dem;

namespace {

// Five stems: 0-1-2 in a chain of contacts, 3 alone, 4 alone.
Islands chainOfThreeAndTwoAlone() {
    Islands islands;
    islands.reset(5);
    islands.join(0, 1);
    islands.join(2, 1);
    return islands;
}

std::vector<bool> allowed(Islands& islands, std::size_t n) {
    std::vector<bool> out;
    for (std::size_t i = 0; i < n; ++i) out.push_back(islands.allowed(i));
    return out;
}

}  // namespace

TEST(Islands, TouchingStemsShareAnIslandAndOthersDoNot) {
    Islands islands = chainOfThreeAndTwoAlone();
    EXPECT_EQ(islands.root(0), islands.root(2));  // through stem 1
    EXPECT_NE(islands.root(0), islands.root(3));
    EXPECT_NE(islands.root(3), islands.root(4));
    for (std::size_t i = 0; i < 5; ++i) EXPECT_LT(islands.root(i), 5u);
}

// One stem that may not (the block touches it, or it is held) keeps its whole island, at the far end
// of a chain too, and no other island; allowing all again starts afresh.
TEST(Islands, OneStemThatMayNotKeepsItsWholeIslandOnly) {
    Islands islands = chainOfThreeAndTwoAlone();
    islands.allowAll();
    islands.forbid(2);
    islands.forbid(4);
    EXPECT_EQ(allowed(islands, 5), (std::vector<bool>{false, false, false, true, false}));
    islands.allowAll();
    EXPECT_EQ(allowed(islands, 5), std::vector<bool>(5, true));
}
