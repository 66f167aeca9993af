// stepWithRetry with a stand-in for the solver's step: a PPE that fails at the first step
// size and converges at half of it is redone once from the step start, with a warning; one
// that fails at both stops the run with a message naming both attempts.
#include "isph/solvers/StepWithRetry.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace isph {
namespace {

namespace fs = std::filesystem;

class StepWithRetryTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / fmt::format("isphStepWithRetry_{}", ::getpid());
    fs::create_directories(dir_ / "system");
  }
  void TearDown() override { fs::remove_all(dir_); }
  void controlDict(const std::string& text) { std::ofstream(dir_ / "system/controlDict") << text; }
  fs::path dir_;
};

// A step whose PPE (field p) or implicit viscous solve (field U) converges only when deltaT is
// at most `largest`; counts its calls. A failed viscous solve leaves the PPE unsolved (the real
// step returns before it).
struct FakeStep {
  double largest;
  std::string field = "p";
  int calls = 0;
  StepReport operator()(const Time& time) {
    ++calls;
    const bool converged = time.deltaT() <= largest;
    const auto perf = [](const std::string& name, const std::string& f, bool ok, double residual, int iterations) {
      return SolverPerformance{.solverName = name, .field = f, .finalResidual = ok ? 1e-10 : residual,
                               .iterations = iterations, .converged = ok};
    };
    StepReport r;
    if (field == "U") {
      r.viscous.push_back(perf("fakeU", "U", converged, 1.6e-4, 200));
      if (converged) r.ppe = perf("fake", "p", true, 0, 1);
    } else {
      r.ppe = perf("fake", "p", converged, 0.5, 1);
    }
    return r;
  }
};

TEST_F(StepWithRetryTest, ConvergedStepIsTakenOnce) {
  controlDict("startFrom startTime; startTime 0; endTime 1; deltaT 0.1; writeInterval 10;\n");
  Time time(dir_);
  ++time;
  FakeStep step{1.0};
  EXPECT_TRUE(stepWithRetry(time, std::ref(step)).ppe.converged);
  EXPECT_EQ(step.calls, 1);
  EXPECT_DOUBLE_EQ(time.value(), 0.1);
}

TEST_F(StepWithRetryTest, RetryWithHalfTheStepThenTheFixedStepAgain) {
  controlDict("startFrom startTime; startTime 0; endTime 1; deltaT 0.1; writeInterval 10;\n");
  Time time(dir_);
  ++time;
  ++time;  // 0.2: the failing step is the second, from 0.1
  FakeStep step{0.06};
  const int warnings = warningCount();
  EXPECT_TRUE(stepWithRetry(time, std::ref(step)).ppe.converged);
  EXPECT_EQ(step.calls, 2);
  EXPECT_EQ(warningCount(), warnings + 1) << "a warning says that the step is retried";
  EXPECT_DOUBLE_EQ(time.value(), 0.15) << "redone from 0.1 with half of 0.1";
  EXPECT_EQ(time.timeIndex(), 2);
  EXPECT_DOUBLE_EQ(time.deltaT(), 0.1) << "a fixed-step run goes back to its deltaT";
}

TEST_F(StepWithRetryTest, AdjustableStepKeepsTheHalfStep) {
  controlDict("startFrom startTime; startTime 0; endTime 1; deltaT 0.1; writeInterval 10; adjustTimeStep yes;\n");
  Time time(dir_);
  ++time;
  FakeStep step{0.06};
  EXPECT_TRUE(stepWithRetry(time, std::ref(step)).ppe.converged);
  EXPECT_DOUBLE_EQ(time.value(), 0.05);
  EXPECT_DOUBLE_EQ(time.deltaT(), 0.05) << "the next step grows from the half step (maxGrowth)";
}

TEST_F(StepWithRetryTest, SecondFailureIsFatalAndNamesBothAttempts) {
  controlDict("startFrom startTime; startTime 0; endTime 1; deltaT 0.1; writeInterval 10;\n");
  Time time(dir_);
  ++time;
  FakeStep step{0.01};
  try {
    stepWithRetry(time, std::ref(step));
    FAIL() << "expected a FatalError";
  } catch (const FatalError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("after one retry with a smaller step"), std::string::npos) << m;
    EXPECT_NE(m.find("first attempt: time 0.1 (deltaT 0.1): fake residual 0.5 after 1 iterations"), std::string::npos)
        << m;
    EXPECT_NE(m.find("retry:         time 0.05 (deltaT 0.05)"), std::string::npos) << m;
    EXPECT_NE(m.find("last written time directory is intact"), std::string::npos) << m;
  }
  EXPECT_EQ(step.calls, 2) << "one retry, no more";
}

TEST_F(StepWithRetryTest, ViscousFailureIsRetriedWithHalfTheStep) {
  controlDict("startFrom startTime; startTime 0; endTime 1; deltaT 0.1; writeInterval 10;\n");
  Time time(dir_);
  ++time;
  FakeStep step{0.06, "U"};
  const int warnings = warningCount();
  const StepReport r = stepWithRetry(time, std::ref(step));
  EXPECT_EQ(r.failedSolve(), nullptr);
  EXPECT_EQ(step.calls, 2);
  EXPECT_EQ(warningCount(), warnings + 1);
  EXPECT_DOUBLE_EQ(time.value(), 0.05);
}

TEST_F(StepWithRetryTest, SecondViscousFailureIsFatalAndSaysWhichSolve) {
  controlDict("startFrom startTime; startTime 0; endTime 1; deltaT 0.1; writeInterval 10;\n");
  Time time(dir_);
  ++time;
  FakeStep step{0.01, "U"};
  try {
    stepWithRetry(time, std::ref(step));
    FAIL() << "expected a FatalError";
  } catch (const FatalError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("the implicit viscous step (field U) did not converge, after one retry"), std::string::npos) << m;
    EXPECT_NE(m.find("first attempt: time 0.1 (deltaT 0.1): fakeU residual 0.00016 after 200 iterations"),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("another preconditioner for U"), std::string::npos) << "where to act\n" << m;
  }
  EXPECT_EQ(step.calls, 2);
}

}  // namespace
}  // namespace isph
