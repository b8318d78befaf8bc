// FNV-1a (64 bit) over bytes: a stable, build-independent digest for keys and file identities
// (the regression gate's baseline digest, the one-ulp perturbation's per-path direction).
#pragma once
#include <cstdint>
#include <string_view>

namespace kolsky {

inline constexpr std::uint64_t kFnv1aOffset = 1469598103934665603ull;

inline std::uint64_t fnv1a_64(std::string_view bytes, std::uint64_t h = kFnv1aOffset) {
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return h;
}

}  // namespace kolsky
