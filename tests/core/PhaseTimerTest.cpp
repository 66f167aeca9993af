#include "core/PhaseTimer.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <sstream>
#include <string>
#include <thread>

namespace isph {
namespace {

// The seconds on a table's row named `phase` (the first number after the name); -1 if absent.
double rowSeconds(const std::string& table, const std::string& phase) {
  std::istringstream in(table);
  for (std::string line; std::getline(in, line);) {
    const auto at = line.find(phase);
    if (at == std::string::npos) continue;
    return std::stod(line.substr(at + phase.size()));
  }
  return -1;
}

TEST(PhaseTimer, AddsTimesOfAPhaseAndKeepsTheOrderOfFirstUse) {
  PhaseTimer timer;
  timer.add("PPE solve", 2.0);
  timer.add("neighbour search", 1.0);
  timer.add("PPE solve", 0.5);
  EXPECT_DOUBLE_EQ(timer.seconds("PPE solve"), 2.5);
  EXPECT_DOUBLE_EQ(timer.totalSeconds(), 3.5);
  const std::string table = timer.table();
  EXPECT_LT(table.find("PPE solve"), table.find("neighbour search"));
  EXPECT_DOUBLE_EQ(rowSeconds(table, "total"), 3.5);
}

// Against the loop's wall time, the time in no phase is a row of its own and the rows add up
// to the loop: the table accounts for the time the user waited (issue 56).
TEST(PhaseTimer, AgainstTheLoopTheTimeInNoPhaseIsARowAndTheTotalIsTheLoop) {
  PhaseTimer timer;
  timer.add("viscous solve", 6.0);
  timer.add("PPE solve", 2.0);
  const std::string table = timer.table(10.0);
  EXPECT_DOUBLE_EQ(rowSeconds(table, "other (in no phase)"), 2.0);
  EXPECT_DOUBLE_EQ(rowSeconds(table, "total"), 10.0);
  EXPECT_NE(table.find("60.0%"), std::string::npos) << table;  // shares of the loop, not of the phases
}

TEST(PhaseTimer, AScopeAddsAtLeastTheWallTimeItWasOpen) {
  PhaseTimer timer;
  {
    auto t = timer.scope("output");
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_GE(timer.seconds("output"), 0.020);  // (no upper bound: a loaded machine may stretch it)
  EXPECT_DOUBLE_EQ(timer.seconds("not used"), 0.0);
}

}  // namespace
}  // namespace isph
