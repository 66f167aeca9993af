// The figures of a force history (issue 49): the filtered peak and its time, the late force
// (the filtered trace's mean over the last lateForceWindow seconds), the raw maximum; and
// the filtered table of a set, every column but Time and nWall filtered.
#include "postProcessing/forces/ForceFigures.hpp"

#include <gtest/gtest.h>

#include "core/Error.hpp"
#include "postProcessing/forces/FilteredForces.hpp"

namespace isph {
namespace {

TEST(ForceFigures, PeakLateForceAndRawMaximum) {
  const std::vector<double> t{0, 0.1, 0.2, 0.3, 0.4, 0.5};
  const std::vector<double> raw{0, 50, 500, 80, 40, 40};
  const std::vector<double> filtered{0, 100, 200, 90, 40, 40};
  const ForceFigures f = forceFigures(t, raw, filtered, 0.25);
  EXPECT_EQ(f.filteredPeak, 200);
  EXPECT_EQ(f.filteredPeakTime, 0.2);
  EXPECT_EQ(f.rawMax, 500);
  EXPECT_EQ(f.rawMaxTime, 0.2);
  EXPECT_NEAR(f.lateFrom, 0.25, 1e-12);
  EXPECT_NEAR(f.lateTo, 0.5, 1e-12);
  // Over [0.25, 0.5], the trapezoids of the filtered trace (145 at 0.25 s, halfway from 200 to 90).
  EXPECT_NEAR(f.lateForce, ((145 + 90) / 2.0 * 0.05 + (90 + 40) / 2.0 * 0.1 + 40 * 0.1) / 0.25, 1e-9);
  EXPECT_THROW(forceFigures({}, {}, {}, 0.25), FatalError);
  EXPECT_THROW(forceFigures(t, raw, filtered, 0), FatalError);

  const std::string text = forceFiguresText(f, "set 'barrier'", "N", CentredMovingAverage(0.01), 0.25);
  for (const char* line : {"\nfilterWindow 0.01 s\n", "\nfilteredPeak 200 N\n", "\nfilteredPeakTime 0.2 s\n",
                           "\nlateForceWindow 0.25 s\n", "\nrawMax 500 N\n", "\nrawMaxTime 0.2 s\n"}) {
    EXPECT_NE(text.find(line), std::string::npos) << line << " in\n" << text;
  }
}

// A set's table at 1 ms steps over 0.5 s: Fn 100 with a one-step spike of 1100 at 0.05 s. The filtered
// table keeps Time and nWall, filters every force column (the spike's 1000 N over 1 ms reads
// 100 N more over 10 ms), and its figures are of Fn.
TEST(FilteredForces, FiltersEveryForceColumnAndTakesTheFiguresOfFn) {
  ForceSet set;
  set.name = "barrier";
  set.patchNames = {"barrier"};
  const ForceTable table(set, 2);
  const std::size_t nCols = table.columns().size(), fn = table.column("Fn") - 1, nWall = table.column("nWall") - 1;
  ForceRows rows;
  for (int k = 0; k <= 500; ++k) {
    std::vector<double> r(nCols, 1.0);
    r[0] = 0.001 * k;
    r[fn] = k == 50 ? 1100 : 100;
    r[nWall] = 7;
    rows.push_back(r);
  }
  const FilteredForces f = filterForces(set, table, rows);
  ASSERT_EQ(f.rows.size(), rows.size());
  EXPECT_NEAR(f.rows[50][fn], 200, 1e-9);
  EXPECT_NEAR(f.rows[50][0], 0.05, 1e-15);
  EXPECT_EQ(f.rows[50][nWall], 7);
  EXPECT_NEAR(f.rows[50][1], 1.0, 1e-12);
  EXPECT_NEAR(f.figures.filteredPeak, 200, 1e-9);
  EXPECT_NEAR(f.figures.filteredPeakTime, 0.05, 0.0045) << "on the plateau of the spike's box, 0.046-0.054 s";
  EXPECT_EQ(f.figures.rawMax, 1100);
  EXPECT_NEAR(f.figures.lateForce, 100, 1e-9) << "the last 0.25 s, after the spike";

  const std::string text = filteredForceText(set, table, "# raw header\n", f.rows);
  EXPECT_EQ(text.rfind("# Filtered: every force and moment column below is the centred moving average over 0.01 s",
                       0),
            0u)
      << text.substr(0, 200);
  EXPECT_EQ(readForceRows(text).size(), rows.size());
  EXPECT_NEAR(readForceRows(text)[50][fn], 200, 1e-6);

  rows[3].pop_back();
  EXPECT_THROW(filterForces(set, table, rows), FatalError) << "a short row";
  EXPECT_THROW(filterForces(set, table, {}), FatalError);
}

}  // namespace
}  // namespace isph
