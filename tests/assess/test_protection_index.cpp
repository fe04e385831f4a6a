// Eq. 26 on values whose medians are known by hand.
#include <gtest/gtest.h>

#include <stdexcept>

#include "libassess/ProtectionIndex.hpp"

namespace {

using sylva::assess::protectionIndex;

TEST(ProtectionIndex, HalvingTheMedianRunoutGivesOneHalf) {
    EXPECT_DOUBLE_EQ(protectionIndex(150.0, 300.0), 0.5);
    EXPECT_DOUBLE_EQ(protectionIndex(300.0, 300.0), 0.0);
}

TEST(ProtectionIndex, FromSamplesUsesTheirMedians) {
    // Medians: 120 (odd count, middle value) and 300 (even count, mean of 290 and 310): 1 - 120/300 = 0.6.
    EXPECT_DOUBLE_EQ(protectionIndex(std::vector<double>{200, 90, 120, 100, 400}, std::vector<double>{310, 250, 290, 500}), 0.6);
}

TEST(ProtectionIndex, RefusesANonPositiveBaseline) {
    EXPECT_THROW(protectionIndex(10.0, 0.0), std::invalid_argument);
}

}  // namespace
