// Rng: the one source of randomness (STYLE.md §7). PCG32 (O'Neill) seeded through SplitMix64,
// so results are identical on every platform and compiler: std distributions are not.
#pragma once

#include <cstdint>

namespace grass {

class Rng {
public:
    explicit Rng(std::uint64_t seed, std::uint64_t stream = 0) {
        mInc = (splitMix(stream) << 1u) | 1u;
        mState = 0;
        nextU32();
        mState += splitMix(seed);
        nextU32();
    }

    std::uint32_t nextU32() {
        const std::uint64_t old = mState;
        mState = old * 6364136223846793005ULL + mInc;
        const auto xorShifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorShifted >> rot) | (xorShifted << ((32u - rot) & 31u));
    }

    // Uniform in [0, 1): 24 random bits, so every value is exactly representable as float.
    float uniform() { return static_cast<float>(nextU32() >> 8) * (1.0f / 16777216.0f); }
    float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }
    double uniformDouble() {
        const std::uint64_t hi = nextU32() >> 5, lo = nextU32() >> 6;
        return static_cast<double>(hi * 67108864ULL + lo) * (1.0 / 9007199254740992.0);
    }
    // Uniform integer in [0, n), n > 0 (Lemire's multiply-shift; the tiny bias is irrelevant here).
    std::uint32_t below(std::uint32_t n) {
        return static_cast<std::uint32_t>((static_cast<std::uint64_t>(nextU32()) * n) >> 32u);
    }

    static std::uint64_t splitMix(std::uint64_t x) {
        x += 0x9E3779B97F4A7C15ULL;
        x = (x ^ (x >> 30u)) * 0xBF58476D1CE4E5B9ULL;
        x = (x ^ (x >> 27u)) * 0x94D049BB133111EBULL;
        return x ^ (x >> 31u);
    }

private:
    std::uint64_t mState = 0;
    std::uint64_t mInc = 1;
};

}  // namespace grass
