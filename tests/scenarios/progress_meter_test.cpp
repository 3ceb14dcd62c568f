// The progress text of a run (ferro/scenarios/progress_meter.hpp): what is shown when, and the
// fraction, times and ETA it states.
#include "ferro/scenarios/progress_meter.hpp"

#include <gtest/gtest.h>

#include <string>

namespace ferro::scenarios {
namespace {

TEST(ProgressMeter, PlainLinesAtEachTenPercentAfterTheFirstSecond) {
  ProgressMeter m(10.0, false);
  EXPECT_EQ(m.update(5.0, 0.5), "");  // the first second: silent
  // Half the run in 2 s: the other half takes 2 s more.
  EXPECT_EQ(m.update(5.0, 2.0), "progress: 50% (t = 5 s of 10 s, elapsed 2.0 s, ETA 2.0 s)\n");
  EXPECT_EQ(m.update(5.5, 2.2), "");  // same tenth
  EXPECT_EQ(m.update(8.0, 3.2), "progress: 80% (t = 8 s of 10 s, elapsed 3.2 s, ETA 0.8 s)\n");
  EXPECT_EQ(m.update(10.0, 4.0), "");  // the end is the run's own report
  EXPECT_EQ(m.finish(), "");
}

TEST(ProgressMeter, TerminalBarRedrawnAtMostEveryTenthOfASecond) {
  ProgressMeter m(4.0, true);
  EXPECT_EQ(m.update(1.0, 0.9), "");
  const std::string bar = m.update(1.0, 1.5);
  // A quarter: 7 of 30 cells filled; ETA = 1.5 s x 3.
  EXPECT_EQ(bar, "\r[" + std::string(7, '#') + std::string(23, '.') +
                     "]  25.0%  t = 1 / 4 s  elapsed 1.5 s  ETA 4.5 s   ");
  EXPECT_EQ(m.update(1.1, 1.55), "");
  EXPECT_NE(m.update(1.2, 1.65), "");
  EXPECT_EQ(m.finish(), "\n");
}

TEST(ProgressMeter, SecondsAndMinutes) {
  EXPECT_EQ(format_seconds(12.34), "12.3 s");
  EXPECT_EQ(format_seconds(125.0), "2m05s");
}

}  // namespace
}  // namespace ferro::scenarios
