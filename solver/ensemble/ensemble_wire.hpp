// The executors' shared pieces: the result cache, and a member's result as the MPI executor sends it between ranks (JSON text: doubles are written
// with enough digits to read back bit for bit, nlohmann::json's round-trip formatting).
#pragma once
#include <nlohmann/json.hpp>
#include <optional>

#include "ensemble/ensemble.hpp"

namespace kolsky::ensemble {

/// The member's result from the cache (ok and cached set), or nothing: no cache, no key, or
/// no file under its key.
std::optional<MemberResult> cached_result(const EnsembleMember& member, const std::string& cache_dir, int rank);
/// Stores a result under its key, atomically (no-op without a cache or key).
void cache_store(const std::string& cache_dir, const std::string& key, const nlohmann::json& value);

inline nlohmann::json to_wire(const MemberResult& r) {
  return {{"label", r.label}, {"key", r.key},       {"ok", r.ok},     {"cached", r.cached},
          {"error", r.error}, {"wall_s", r.wall_s}, {"rank", r.rank}, {"value", r.value}};
}

inline MemberResult from_wire(const nlohmann::json& j) {
  MemberResult r;
  r.label = j.at("label").get<std::string>();
  r.key = j.at("key").get<std::string>();
  r.ok = j.at("ok").get<bool>();
  r.cached = j.at("cached").get<bool>();
  r.error = j.at("error").get<std::string>();
  r.wall_s = j.at("wall_s").get<double>();
  r.rank = j.at("rank").get<int>();
  r.value = j.at("value");
  return r;
}

}  // namespace kolsky::ensemble
