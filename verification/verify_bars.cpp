// GoogleTest front of the bar and coupled-specimen verification checks (verification/checks/):
// each check carries its closed form and the reason for its tolerance; a failure prints both.
#include <gtest/gtest.h>

#include "checks/check.hpp"

namespace kolsky::verify {

TEST(VerifyBars, ClosedForms) {
  for (const auto& c : bar_checks()) EXPECT_TRUE(c.pass()) << c;
}

TEST(VerifySpecimen, EnergyLoopAndConvergence) {
  for (const auto& c : specimen_checks()) EXPECT_TRUE(c.pass()) << c;
}

TEST(VerifyFeCoupling, EnergyAndConfinedModulus) {
  for (const auto& c : fe_coupling_checks()) EXPECT_TRUE(c.pass()) << c;
}

TEST(VerifyDemCoupling, EnergyBalance) {
  for (const auto& c : dem_coupling_checks()) EXPECT_TRUE(c.pass()) << c;
}

}  // namespace kolsky::verify
