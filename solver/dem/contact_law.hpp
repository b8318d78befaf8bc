// Contact-law families (architecture.md, "model families are std::variants"): one variant for
// grain-grain laws and one for grain-wall laws, each dispatched once around its contact loop
// (std::visit outside the loop). The name tables are the single lists of valid names (the
// scene's `specimen.contact_law` choices are kContactLawNames).
//
// Every law has the same small interface, checked at compile time below, so that DemSystem
// visits the variants without naming a type (adding a law adds an alternative here and its
// parameters to the scene; nothing in dem_system.cpp changes):
//   using Params = ...;                       its parameter struct (defaults: the sources')
//   pair(a, b).force(g, history, dt)          one contact (wall laws: pair(a))
//   double stable_dt(const LawLimits&) const  its stable step (contact_pieces.hpp)
//   bool fits(int n_materials) const          built for that many materials?
//   void validate(const std::string& path) const   InputError(path.<field>) for bad values
// and a grain law is built from its parameters by make_law(materials, params).
#pragma once
#include <array>
#include <concepts>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "dem/contact_hertz_mindlin.hpp"
#include "dem/contact_linear.hpp"

namespace kolsky::dem {

/// Grain-grain contact laws.
using ContactLaw = std::variant<HertzMindlin, LinearSpring, LsDynaLinear>;
/// Their parameters, in the same order: alternative k builds alternative k (make_contact_law).
using ContactLawParams = std::variant<HertzMindlinParams, LinearParams, LsDynaParams>;
/// Names (scene `specimen.contact_law`), in the order of the ContactLaw alternatives.
inline constexpr std::array<std::string_view, 3> kContactLawNames = {"hertz_mindlin", "linear",
                                                                     "ls_dyna_linear"};

/// Grain-wall contact laws: PFC-style linear springs (the dissertation's walls, Table 4.1) or
/// Hertz-Mindlin against a wall material (E = +inf: a rigid plane).
using WallLaw = std::variant<LinearSpring, HertzMindlinWall>;
inline constexpr std::array<std::string_view, 2> kWallLawNames = {"linear", "hertz_mindlin"};

inline std::string_view name_of(const ContactLaw& law) { return kContactLawNames[law.index()]; }
inline std::string_view name_of(const WallLaw& law) { return kWallLawNames[law.index()]; }

/// The grain laws from their parameters (each validates them, paths "dem.contact_law.<field>").
inline HertzMindlin make_law(const std::vector<Material>& m, const HertzMindlinParams& p) {
  return HertzMindlin(m, p);
}
inline LinearSpring make_law(const std::vector<Material>&, const LinearParams& p) {
  validate(p, "dem.contact_law");
  return linear_spring(p);
}
inline LsDynaLinear make_law(const std::vector<Material>& m, const LsDynaParams& p) {
  return LsDynaLinear(m, p);
}
/// The law the parameters select, built for `materials`.
inline ContactLaw make_contact_law(const std::vector<Material>& materials,
                                   const ContactLawParams& params) {
  return std::visit([&](const auto& p) -> ContactLaw { return make_law(materials, p); }, params);
}
/// Default parameters of the law called `name` (one of kContactLawNames); throws
/// std::out_of_range for another name.
ContactLawParams default_law_params(std::string_view name);

/// The law interface (see the top of this file).
template <class L>
concept LawCommon = requires(const L& l, const LawLimits& lim, const std::string& path, int n) {
  typename L::Params;
  { l.stable_dt(lim) } -> std::same_as<double>;
  { l.fits(n) } -> std::same_as<bool>;
  { l.validate(path) } -> std::same_as<void>;
};
template <class L>
concept GrainLaw = LawCommon<L> && requires(const L& l, const ContactGeometry& g, Vec3& h,
                                            double dt, const typename L::Params& p) {
  { l.pair(0, 0).force(g, h, dt) } -> std::same_as<ContactResult>;
  { make_law(std::vector<Material>{}, p) } -> std::same_as<L>;
};
template <class L>
concept WallContactLaw = LawCommon<L> && requires(const L& l, const ContactGeometry& g, Vec3& h,
                                                  double dt) {
  { l.pair(0).force(g, h, dt) } -> std::same_as<ContactResult>;
};

namespace detail {
template <class... L, class... P>
constexpr bool grain_family(std::variant<L...>*, std::variant<P...>*) {
  return (GrainLaw<L> && ...) && (std::same_as<typename L::Params, P> && ...);
}
template <class... L>
constexpr bool wall_family(std::variant<L...>*) {
  return (WallContactLaw<L> && ...);
}
}  // namespace detail
static_assert(detail::grain_family(static_cast<ContactLaw*>(nullptr),
                                   static_cast<ContactLawParams*>(nullptr)),
              "every grain law has the law interface, and ContactLawParams matches ContactLaw");
static_assert(std::variant_size_v<ContactLaw> == kContactLawNames.size());
static_assert(detail::wall_family(static_cast<WallLaw*>(nullptr)),
              "every wall law has the law interface");
static_assert(std::variant_size_v<WallLaw> == kWallLawNames.size());

}  // namespace kolsky::dem
