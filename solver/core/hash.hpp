// FNV-1a (64 bit) over bytes: a stable, build-independent digest for keys and file identities
// (the breakage strength draws' stream keys, docs/breakage.md; the regression gate's baseline
// digest; the one-ulp perturbation's per-path direction).
#pragma once
#include <cstdint>
#include <string_view>

namespace kolsky {

/// The FNV-1a 64-bit offset basis (Fowler, Noll, Vo; IETF draft-eastlake-fnv).
inline constexpr std::uint64_t kFnv1aOffset = 14695981039346656037ull;

/// The basis with its last digit lost, which kolsky used until 2026-12-04. Kept, by name, only
/// where a hash is an identity already written down: the baseline digests logged in
/// reproductions/BASELINES.md, the one-ulp perturbation directions their tolerances were
/// measured with (changing either would orphan every logged baseline) and the packing cache's
/// keys. Nothing a user reproduces from the docs (the strength draws) uses it.
inline constexpr std::uint64_t kLegacyIdentityOffset = 1469598103934665603ull;

inline std::uint64_t fnv1a_64(std::string_view bytes, std::uint64_t h = kFnv1aOffset) {
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return h;
}

}  // namespace kolsky
