// The contact bookkeeping shared by every kind of forest contact: a contact found again keeps its
// history, one not found again ends, and the order in which contacts began (the order forces are
// summed in) survives every sweep.
#include <gtest/gtest.h>

#include <vector>

#include "libdem/ContactSet.hpp"

using namespace sylva::dem;

namespace {
struct Touch {
    int history;
    bool touching;
};
std::vector<int> histories(const ContactSet<Touch>& set) {
    std::vector<int> h;
    for (const Touch& t : set) h.push_back(t.history);
    return h;
}
}  // namespace

TEST(ContactSet, FoundAgainKeepsItsHistoryNotFoundEndsOrderIsKept) {
    ContactSet<Touch> set;
    const ContactKey a{1, 2, 3, 0}, b{1, 2, 4, 0}, c{7, 0, 0, 0}, d{7, 0, 0, 1};
    set.beginDetection();
    for (const auto& [key, h] : {std::pair{a, 10}, {b, 20}, {c, 30}}) {
        ASSERT_EQ(set.find(key), nullptr);
        set.add(key, Touch{h, true});
    }
    set.sweep();
    EXPECT_EQ(histories(set), (std::vector<int>{10, 20, 30}));

    // Next step: b is not found again, a and c are, d begins.
    set.beginDetection();
    for (const ContactKey& key : {c, a}) {
        Touch* t = set.find(key);
        ASSERT_NE(t, nullptr);
        t->touching = true;
        t->history += 1;
    }
    EXPECT_EQ(set.find(d), nullptr);
    set.add(d, Touch{40, true});
    set.sweep();
    EXPECT_EQ(histories(set), (std::vector<int>{11, 31, 40}));  // b gone, a before c before d
    EXPECT_EQ(set.find(b), nullptr);
    ASSERT_NE(set.find(c), nullptr);
    EXPECT_EQ(set.find(c)->history, 31) << "the index follows the contacts as they move up";
    EXPECT_EQ(set.find(d)->history, 40);

    // A stem put to sleep takes its contacts with it.
    set.eraseIf([](const Touch& t) { return t.history > 30; });
    EXPECT_EQ(histories(set), (std::vector<int>{11}));
    EXPECT_EQ(set.find(a)->history, 11);
    EXPECT_EQ(set.find(d), nullptr);
    EXPECT_EQ(set.size(), 1u);
}

// A stem breaking under a block's contact makes the part above a piece of its own, and the contact's
// key (block sphere, tree, piece) changes while its history goes on (ForestMotion::detectBlockStem):
// found by the new key only, with its history, in the order it began.
TEST(ContactSet, ARekeyedContactKeepsItsHistoryAndPlace) {
    ContactSet<Touch> set;
    const ContactKey a{0, 5, 0, 0}, b{1, 5, 0, 0}, aAbove{0, 5, 3, 0};
    set.add(a, Touch{10, true});
    set.add(b, Touch{20, true});
    set.rekey([&](Touch& t, ContactKey key) { return t.history == 10 ? aAbove : key; });
    EXPECT_EQ(set.find(a), nullptr);
    ASSERT_NE(set.find(aAbove), nullptr);
    EXPECT_EQ(set.find(aAbove)->history, 10);
    EXPECT_EQ(set.find(b)->history, 20);
    EXPECT_EQ(histories(set), (std::vector<int>{10, 20}));
    // Swept after, the index still follows the new key.
    set.beginDetection();
    set.find(aAbove)->touching = true;
    set.sweep();
    EXPECT_EQ(histories(set), (std::vector<int>{10}));
    EXPECT_EQ(set.find(aAbove)->history, 10);
}
