// Fixed-algorithm pseudo-random numbers for reproducible particle samples: xoshiro256** 1.0
// (Blackman and Vigna, "Scrambled linear pseudorandom number generators", ACM TOMS 47, 2021),
// seeded through SplitMix64 (Steele, Lea and Flood, OOPSLA 2014), as the xoshiro authors advise.
// Why not <random> distributions: std::uniform_real_distribution's output is implementation-
// defined, so the same seed would give different specimens with different standard libraries.
// Both generators are pure integer arithmetic, so a seed gives the same stream everywhere.
#pragma once
#include <cstdint>

namespace kolsky {

/// SplitMix64: a 64-bit counter through a bijective mixer; used only to expand one seed into
/// the 256-bit xoshiro state (any seed, including 0, gives a non-zero state).
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }

 private:
  std::uint64_t state_;
};

/// xoshiro256**: period 2^256 - 1, passes BigCrush; next() is the reference algorithm.
class Xoshiro256ss {
 public:
  /// State from four SplitMix64 outputs of `seed`.
  explicit Xoshiro256ss(std::uint64_t seed) {
    SplitMix64 sm(seed);
    for (auto& w : s_) w = sm.next();
  }
  /// Explicit state (must not be all zero); used to check against the reference outputs.
  Xoshiro256ss(std::uint64_t s0, std::uint64_t s1, std::uint64_t s2, std::uint64_t s3)
      : s_{s0, s1, s2, s3} {}

  std::uint64_t next() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }

  /// Uniform double strictly inside (0, 1): the top 53 bits, offset by half a step, so that
  /// inverse-CDF transforms never see 0 or 1 (no infinite or end-point values).
  double uniform_open() { return (static_cast<double>(next() >> 11) + 0.5) * 0x1.0p-53; }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4];
};

}  // namespace kolsky
