#pragma once
// Seeded random numbers that give the same sequence on every platform and compiler.
// (std::uniform_*_distribution is implementation-defined, so it is not used.)

#include <cstdint>

namespace throng {

/// PCG32 (O'Neill, pcg-random.org): small state, good statistics, fully specified output.
class Rng {
public:
    explicit Rng(std::uint64_t seed, std::uint64_t stream = 0x9e3779b97f4a7c15ULL) {
        increment_ = (stream << 1U) | 1U;
        nextU32();
        state_ += seed;
        nextU32();
    }

    std::uint32_t nextU32() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + increment_;
        const auto xorshifted = static_cast<std::uint32_t>(((old >> 18U) ^ old) >> 27U);
        const auto rot = static_cast<std::uint32_t>(old >> 59U);
        return (xorshifted >> rot) | (xorshifted << ((32U - rot) & 31U));
    }

    /// Uniform in [0, 1), 24 bits of resolution so the float is exact.
    float uniform() { return static_cast<float>(nextU32() >> 8U) * (1.0F / 16777216.0F); }

    /// Uniform in [lo, hi).
    float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }

    /// Uniform integer in [0, bound), bound > 0, without modulo bias (Lemire's method).
    std::uint32_t below(std::uint32_t bound) {
        std::uint64_t product = std::uint64_t{nextU32()} * bound;
        auto low = static_cast<std::uint32_t>(product);
        if (low < bound) {
            const std::uint32_t threshold = (0U - bound) % bound;
            while (low < threshold) {
                product = std::uint64_t{nextU32()} * bound;
                low = static_cast<std::uint32_t>(product);
            }
        }
        return static_cast<std::uint32_t>(product >> 32U);
    }

private:
    std::uint64_t state_ = 0;
    std::uint64_t increment_ = 0;
};

}  // namespace throng
