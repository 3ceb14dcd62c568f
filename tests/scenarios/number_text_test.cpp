// Strict reading of command-line numbers and the range messages (ferro/scenarios/number_text.hpp).
#include "ferro/scenarios/number_text.hpp"

#include <gtest/gtest.h>

#include <climits>
#include <cmath>

namespace ferro::scenarios {
namespace {

TEST(StrictNumber, OneWholeFiniteNumberOnly) {
  EXPECT_EQ(strict_number("1.5"), 1.5);
  EXPECT_EQ(strict_number("-2e-3"), -2e-3);
  for (const char* bad : {"", "nan", "inf", "-inf", "1x", "1.5 m", "1e400"})
    EXPECT_TRUE(std::isnan(strict_number(bad))) << bad;
}

TEST(NumberRange, BoundsOpenAndClosedInTextAndCheck) {
  const NumberRange mu{0.0, 2.0, false, true, ""};
  EXPECT_EQ(mu.text(), "in [0, 2)");
  EXPECT_EQ(mu.problem("0"), "");
  EXPECT_EQ(mu.problem("1.999"), "");
  EXPECT_EQ(mu.problem("2"), "must be in [0, 2), got '2'");
  EXPECT_EQ(mu.problem("-1e-9"), "must be in [0, 2), got '-1e-9'");
  const NumberRange length{0.0, INFINITY, true, true, "m"};
  EXPECT_EQ(length.text(), "> 0 m");
  EXPECT_EQ(length.problem("0"), "must be > 0 m, got '0'");
  EXPECT_EQ(length.problem("1e300"), "");
  const NumberRange upper{-INFINITY, 1.0, true, false, ""};
  EXPECT_EQ(upper.text(), "<= 1");
  const NumberRange any{-INFINITY, INFINITY, true, true, ""};
  EXPECT_EQ(any.text(), "a finite number");
  EXPECT_EQ(any.problem("nan"), "must be a finite number, got 'nan'");
}

TEST(CountRange, WholeNumbersWithinTheRange) {
  const CountRange jobs{1, 1024};
  EXPECT_EQ(jobs.text(), "in 1..1024");
  EXPECT_EQ(jobs.problem("1"), "");
  EXPECT_EQ(jobs.problem("1024"), "");
  EXPECT_EQ(jobs.problem("1025"), "must be a whole number in 1..1024, got '1025'");
  EXPECT_EQ(jobs.problem("2.5"), "must be a whole number in 1..1024, got '2.5'");
  EXPECT_EQ(jobs.problem(""), "must be a whole number in 1..1024, got ''");
  const CountRange open{0, LONG_MAX};
  EXPECT_EQ(open.text(), ">= 0");
  EXPECT_NE(open.problem("99999999999999999999999"), "");  // beyond long: refused
}

}  // namespace
}  // namespace ferro::scenarios
