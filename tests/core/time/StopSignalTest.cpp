// The signals that stop a run (StopSignal.hpp), each in a child process (gtest's death tests):
// the first is recorded and the run goes on; a second aborts; after the run, the process ends
// by the caught signal's default action, so that a calling script sees 130 (SIGINT) or 143
// (SIGTERM) rather than success. Time's part (write at the next step, then stop) is in
// TimeTest.cpp.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>

#include "core/time/StopSignal.hpp"

namespace isph {
namespace {

TEST(StopSignalDeathTest, TheFirstSignalIsRecordedAndTheProcessGoesOn) {
  EXPECT_EXIT(
      {
        stopSignal::install();
        const bool before = stopSignal::caught() == 0;
        std::raise(SIGHUP);  // a closed terminal: as SIGTERM
        std::exit(before && stopSignal::caught() == SIGHUP ? 0 : 1);
      },
      testing::ExitedWithCode(0), "Signal caught: writing at the end of the next time step");
}

TEST(StopSignalDeathTest, SecondSignalAborts) {
  EXPECT_EXIT(
      {
        stopSignal::install();
        std::raise(SIGINT);
        std::raise(SIGINT);
        std::exit(0);
      },
      testing::KilledBySignal(SIGINT), "");
}

TEST(StopSignalDeathTest, AfterTheRunTheProcessEndsByTheCaughtSignal) {
  EXPECT_EXIT(
      {
        stopSignal::install();
        std::raise(SIGTERM);
        stopSignal::exitIfCaught();
        std::exit(0);
      },
      testing::KilledBySignal(SIGTERM), "");
}

TEST(StopSignalDeathTest, WithoutASignalExitIfCaughtReturns) {
  EXPECT_EXIT(
      {
        stopSignal::install();
        stopSignal::exitIfCaught();
        std::exit(stopSignal::caught() == 0 ? 0 : 1);
      },
      testing::ExitedWithCode(0), "");
}

TEST(StopSignalDeathTest, ASignalAnotherRankCaughtCountsAsCaught) {
  EXPECT_EXIT(
      {
        stopSignal::setCaught(SIGINT);
        std::exit(stopSignal::caught() == SIGINT ? 0 : 1);
      },
      testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace isph
