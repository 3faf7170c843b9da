// The seeded RNG must give the same numbers everywhere: crowds and images depend on it.
#include <gtest/gtest.h>

#include <set>

#include "throng/core/rng.h"

namespace {

TEST(Rng, SameSeedGivesSameSequence) {
    throng::Rng a(42), b(42);
    for (int i = 0; i < 1000; ++i) ASSERT_EQ(a.nextU32(), b.nextU32());
}

TEST(Rng, DifferentSeedsDiffer) {
    throng::Rng a(1), b(2);
    int same = 0;
    for (int i = 0; i < 100; ++i) same += a.nextU32() == b.nextU32() ? 1 : 0;
    EXPECT_LT(same, 3);
}

TEST(Rng, UniformStaysInRangeAndCoversIt) {
    throng::Rng rng(7);
    float lo = 1, hi = 0;
    for (int i = 0; i < 10000; ++i) {
        const float u = rng.uniform();
        ASSERT_GE(u, 0.0F);
        ASSERT_LT(u, 1.0F);
        lo = std::min(lo, u);
        hi = std::max(hi, u);
    }
    EXPECT_LT(lo, 0.01F);
    EXPECT_GT(hi, 0.99F);
}

TEST(Rng, BelowHitsEveryValueAndNothingElse) {
    throng::Rng rng(3);
    std::set<std::uint32_t> seen;
    for (int i = 0; i < 1000; ++i) {
        const std::uint32_t v = rng.below(7);
        ASSERT_LT(v, 7U);
        seen.insert(v);
    }
    EXPECT_EQ(seen.size(), 7U);
}

}  // namespace
