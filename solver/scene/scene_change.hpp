// Changes of a scene and the identity of a changed scene, for every program that runs a scene
// with some keys changed: the reproduction sets' case pipeline (reproductions/harness) and
// `kolsky sweep` (solver/sweep). A change is a dotted key and the JSON value it takes
// ("specimen.breakage.sigma_lim0=2e9"); it is applied to the scene's JSON before the scene
// reader sees it, so the reader's rules (unknown keys, ranges) judge the changed scene as they
// judge a file. The content key is the identity by which the ensembles cache a member's result:
// the same final scene from the same binary has the same key, however its changes were written.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace kolsky::scene {

/// One change of a scene: `key` a dotted path ("specimen.rolling_factor"), `value` the JSON it
/// takes (the objects on its path are created); null removes the key (a key another change
/// makes unused, e.g. the tube_* keys of an FE tube set to rigid).
struct SceneChange {
  std::string key;
  nlohmann::json value;
};

/// "dotted.key=JSON" (a study's --set, KOLSKY_CH4_SET) as a change. Throws InputError naming
/// `origin` and the item for an item without '=', an empty key, or a value that is not JSON.
SceneChange parse_change(const std::string& item, const std::string& origin);

/// Applies one change to a scene's JSON, creating the objects on its path (null removes the
/// key; removing a key that is not there does nothing). InputError(file, key, ...) for a path
/// with an empty part or one that goes through a value that is not an object.
void apply_change(nlohmann::json& scene, const SceneChange& change, const std::string& file);

/// An RFC 7386 merge patch (the Chapter 3 studies file writes its variants so) as the changes
/// that make it: one per leaf, in key order; a nested object is descended, anything else
/// (arrays included) replaces the key whole, null removes it. InputError for a key holding a
/// '.' (it could not be told from a path) or a patch that is not an object.
std::vector<SceneChange> changes_from_patch(const nlohmann::json& patch);

/// "kolsky <version> <commit>": the binary a scene's results come from.
std::string binary_version();

/// FNV-1a 64 (core/hash.hpp) of binary_version(), `context` (when not empty) and the scene's
/// JSON text (nlohmann's dump: keys sorted, numbers round-tripping) with
/// specimen.packing_cache removed (it says where packings are kept, not what is run), as 16
/// hex digits. Files the scene names by a relative path enter by that path, not their bytes;
/// `context` is where a caller adds what else makes a result (e.g. the folder such paths
/// resolve against).
std::string content_key(const nlohmann::json& scene, std::string_view context = {});

}  // namespace kolsky::scene
