// Contact-law families (architecture.md, "model families are std::variants"): one variant for
// grain-grain laws and one for grain-wall laws, each dispatched once around its contact loop
// (std::visit outside the loop). The name table is the single list of valid JSON names.
#pragma once
#include <array>
#include <string_view>
#include <variant>

#include "dem/contact_hertz_mindlin.hpp"
#include "dem/contact_linear.hpp"

namespace kolsky::dem {

/// Grain-grain contact laws.
using ContactLaw = std::variant<HertzMindlin, LinearSpring, LsDynaLinear>;
/// JSON names, in the order of the ContactLaw alternatives.
inline constexpr std::array<std::string_view, 3> kContactLawNames = {
    "hertz_mindlin", "linear_spring", "ls_dyna_linear"};

/// Grain-wall contact laws: PFC-style linear springs (the dissertation's walls, Table 4.1) or
/// Hertz-Mindlin against a wall material (E = +inf: a rigid plane).
using WallLaw = std::variant<LinearSpring, HertzMindlinWall>;
inline constexpr std::array<std::string_view, 2> kWallLawNames = {"linear_spring",
                                                                  "hertz_mindlin"};

inline std::string_view name_of(const ContactLaw& law) { return kContactLawNames[law.index()]; }
inline std::string_view name_of(const WallLaw& law) { return kWallLawNames[law.index()]; }

}  // namespace kolsky::dem
