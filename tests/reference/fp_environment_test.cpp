// The floating-point environment check (hinge/core/fp_environment.hpp) and the reference's entry
// points: every setting that breaks exact arithmetic is named, and nothing is computed under it.
#include "hinge/core/fp_environment.hpp"

#include <gtest/gtest.h>

#include <string>

#include "hinge/core/errors.hpp"
#include "hinge/reference/assemble.hpp"
#include "hinge/reference/evaluate.hpp"
#include "support/fp_environment.hpp"

namespace {

using hinge::test::ScopedFpEnvironment;
using hinge::test::Setting;

const std::array<double, 12> kHinge = {0.125, 0.75,  -0.5,    -0.25, 0.0625, 0.0,
                                       1.0,   0.125, -0.0625, 0.625, -0.875, 0.375};

std::string message_under(Setting s) {
  ScopedFpEnvironment env(s);
  try {
    hinge::check_fp_environment();
  } catch (const hinge::EnvironmentError& e) {
    return e.what();
  }
  return "";
}

TEST(FpEnvironment, TheDefaultEnvironmentPasses) { EXPECT_NO_THROW(hinge::check_fp_environment()); }

TEST(FpEnvironment, EachBreakingSettingIsNamed) {
  EXPECT_NE(message_under(Setting::flush_to_zero).find("flush-to-zero is set"), std::string::npos);
  EXPECT_NE(message_under(Setting::denormals_are_zero).find("denormals-are-zero is set"), std::string::npos);
  EXPECT_NE(message_under(Setting::round_upward_sse).find("rounding is upward (MXCSR)"), std::string::npos);
  const std::string toward_zero = message_under(Setting::round_toward_zero_everywhere);
  EXPECT_NE(toward_zero.find("rounding is toward zero (MXCSR)"), std::string::npos) << toward_zero;
  EXPECT_NE(toward_zero.find("rounding is toward zero (x87, long double)"), std::string::npos) << toward_zero;
  EXPECT_NE(message_under(Setting::x87_double_precision).find("x87 precision control is below 64 bits"),
            std::string::npos);
}

TEST(FpEnvironment, TheEnvironmentIsRestoredAfterwards) {
  for (Setting s : hinge::test::kAllSettings) (void)message_under(s);
  EXPECT_NO_THROW(hinge::check_fp_environment());
}

TEST(FpEnvironment, ReferenceEntryPointsRefuseABrokenEnvironment) {
  for (Setting s : hinge::test::kAllSettings) {
    ScopedFpEnvironment env(s);
    EXPECT_THROW(hinge::reference::theta_derivatives<double>(kHinge), hinge::EnvironmentError);
    EXPECT_THROW(hinge::reference::theta_derivatives<long double>(kHinge), hinge::EnvironmentError);
  }
  EXPECT_NO_THROW(hinge::reference::theta_derivatives<double>(kHinge));
}

}  // namespace
