// The one step check and the one energy check (core/stability_check.hpp): where they fire,
// where they must not, and what they say.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.hpp"
#include "core/stability_check.hpp"

using kolsky::check_energy_growth;
using kolsky::check_time_step;
using kolsky::EnergyLedger;
using kolsky::NumericalError;

namespace {

std::string message_of(double dt, double limit) {
  try {
    check_time_step(dt, limit, "dem", 2e-6, "Rayleigh step");
  } catch (const NumericalError& e) {
    EXPECT_EQ(e.time(), 2e-6);
    return e.what();
  }
  return "";
}

}  // namespace

TEST(StabilityCheck, StepAtTheLimitPassesAndAboveItFails) {
  EXPECT_EQ(message_of(1e-8, 1e-8), "");
  EXPECT_EQ(message_of(1e-8 * (1 + 1e-13), 1e-8), "");  // the slack for a re-summed limit
  const std::string m = message_of(1.01e-8, 1e-8);
  EXPECT_NE(m.find("dem: time step 1.01e-08 s is above the stable limit 1e-08 s at t = 2e-06 s"),
            std::string::npos) << m;
  EXPECT_NE(m.find("(Rayleigh step)"), std::string::npos) << m;
  EXPECT_NE(message_of(0.0, 1e-8), "");
  EXPECT_NE(message_of(-1.0, 1e-8), "");
}

TEST(StabilityCheck, EnergyCheckIsOneSidedAndScaled) {
  // 1 % of a 2 J scale: 0.02 J of created energy is the bound.
  EXPECT_NO_THROW(check_energy_growth({1.019, 1.0, 2.0}, 0.01, "bars and specimen", 0.0));
  EXPECT_THROW(check_energy_growth({1.021, 1.0, 2.0}, 0.01, "bars and specimen", 0.0), NumericalError);
  // Lost energy is not a blow-up (the verification checks bound it with their own tolerances).
  EXPECT_NO_THROW(check_energy_growth({0.5, 1.0, 2.0}, 0.01, "fe specimen", 0.0));
  // Nothing injected yet: not judged.
  EXPECT_NO_THROW(check_energy_growth({1e-3, 0.0, 0.0}, 0.01, "bars and specimen", 0.0));
  try {
    check_energy_growth({3.0, 1.0, 2.0}, 0.05, "meshed bars", 4e-4);
    ADD_FAILURE() << "growth not caught";
  } catch (const NumericalError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("meshed bars: energy grows: the model holds 3 J but only 1 J was supplied"),
              std::string::npos) << m;
    EXPECT_EQ(e.time(), 4e-4);
  }
  EXPECT_EQ((EnergyLedger{3.0, 1.0, 2.0}.excess()), 2.0);
}
