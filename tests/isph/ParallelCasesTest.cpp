// The validation cases run in parallel as a user runs them (doc/parallel.md): coarse copies of
// hydrostaticTank, damBreak, granularAtRest and columnCollapse, each run serially and with
// `mpirun -np N isphLandslideFoam -parallel` on 1, 2 and 3 ranks (3 oversubscribed on a 2-core
// machine), then reconstructPar. Each run must give the serial run's figures (those of the
// case's own validation test) within tolerances set from the run-to-run noise, measured as the
// change of each figure when the serial run's linear solvers go from their tolerance (1e-8) to
// 1e-9 (the comments give it), and exactly the serial run's particles and mass. The 2-rank run
// starts from decomposePar's processor directories (the decompose -> run -> reconstruct round
// trip), the others decompose the start time in memory; one case runs HSFC, the others RCB.
// Each tolerance is about three times the noise (a parallel run's solves, whose AMG hierarchies
// and sums differ from the serial run's, differ from them at the solver tolerance as well).
// A restart on 2 ranks must equal the continuous 2-rank run as a serial restart does
// (RestartTest.cpp). OpenMPI refuses to run as root unless told (CI runs as root): the
// commands set OMPI_ALLOW_RUN_AS_ROOT.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "CaseRunner.hpp"
#include "core/time/TimeName.hpp"
#include "particles/CloudIO.hpp"
#include "postProcessing/sampling/RunOut.hpp"
#include "postProcessing/sampling/SurfaceProfile.hpp"

namespace {

using isph::test::CaseRunner;
using namespace isph;

const std::string mpiEnvironment = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1";

// Runs the solver of a case on n ranks (after decomposePar if `decompose`), then reconstructPar.
void runParallel(const CaseRunner& c, int n, bool decompose, const std::string& algorithm = "RCB") {
  std::ofstream(c.path() / "system" / "decomposeParDict")
      << "FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
      << "numberOfSubdomains " << n << ";\nmethod zoltan;\nzoltanCoeffs { algorithm " << algorithm << "; }\n";
  if (decompose) {
    ASSERT_EQ(c.run(DECOMPOSEPAR_EXE, "decomposePar"), 0) << "see " << c.path() / "log.decomposePar";
  }
  // (yield when idle: the ranks share the cores with each other and with other tests)
  const std::string ranks = "-np " + std::to_string(n) + " --oversubscribe --bind-to none --mca mpi_yield_when_idle 1 '" +
                            std::string(SOLVER_EXE) + "' -parallel";
  ASSERT_EQ(c.run(MPIRUN_EXE, "isphLandslideFoam", ranks, mpiEnvironment), 0)
      << "see " << c.path() / "log.isphLandslideFoam";
  ASSERT_EQ(c.run(RECONSTRUCTPAR_EXE, "reconstructPar"), 0) << "see " << c.path() / "log.reconstructPar";
}

// The material particles' count and mass, which a parallel run must keep exactly.
struct Inventory {
  std::size_t material = 0, all = 0;
  double mass = 0;
  bool operator==(const Inventory&) const = default;
};
Inventory inventory(const ParticleCloud& cloud) {
  Inventory n;
  std::map<label, double> byId;  // summed in origId order: the same sum whatever the order of the file
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.kind[i] == 0) byId[cloud.origId[i]] = cloud.mass[i];
  }
  for (const auto& [id, m] : byId) n.mass += m;
  n.material = byId.size();
  n.all = cloud.size();
  return n;
}

// A case's figures at its end, by name, from its time directories.
using Figures = std::map<std::string, double>;
using Measure = std::function<Figures(const CaseRunner&)>;

struct ParallelCase {
  std::string tutorial;
  std::function<void(CaseRunner&)> setUp;  // coarse copy: spacing, endTime, writeInterval
  std::string endTime;
  Measure measure;
  std::map<std::string, double> tolerance;  // |parallel - serial| per figure (absolute)
  std::string algorithm = "RCB";
};

// Serial, then 1, 2 (decomposePar) and 3 ranks; each run's figures against the serial's.
void checkOnRanks(const ParallelCase& pc) {
  std::map<int, std::unique_ptr<CaseRunner>> runs;
  for (const int n : {0, 1, 2, 3}) {
    runs[n] = std::make_unique<CaseRunner>(pc.tutorial, pc.tutorial + "-np" + std::to_string(n));
    pc.setUp(*runs[n]);
    ASSERT_EQ(runs[n]->run(PARTICLEMESH_EXE, "particleMesh"), 0);
  }
  ASSERT_EQ(runs[0]->run(SOLVER_EXE, "isphLandslideFoam", "", "OMP_NUM_THREADS=1"), 0)
      << "see " << runs[0]->path() / "log.isphLandslideFoam";
  const Figures serial = pc.measure(*runs[0]);
  const Inventory serialInventory = inventory(readCloud(runs[0]->path() / pc.endTime, "particles"));
  for (const int n : {1, 2, 3}) {
    ASSERT_NO_FATAL_FAILURE(runParallel(*runs[n], n, n == 2, pc.algorithm));
    const Figures got = pc.measure(*runs[n]);
    EXPECT_TRUE(inventory(readCloud(runs[n]->path() / pc.endTime, "particles")) == serialInventory)
        << n << " ranks: the particles or their mass differ from the serial run's";
    EXPECT_EQ(runs[n]->logValue("isphLandslideFoam", "Wall crossings in the run:"),
              runs[0]->logValue("isphLandslideFoam", "Wall crossings in the run:"));
    for (const auto& [name, value] : serial) {
      const double difference = got.at(name) - value;
      std::printf("%s on %d rank(s): %s %.8g (serial %.8g, difference %.3g)\n", pc.tutorial.c_str(), n, name.c_str(),
                  got.at(name), value, difference);
      EXPECT_LE(std::abs(difference), pc.tolerance.at(name)) << pc.tutorial << " on " << n << " ranks: " << name;
    }
  }
}

// A coarse copy of a case: its spacing, endTime and writeInterval.
std::function<void(CaseRunner&)> coarse(const std::string& spacing, const std::string& endTime,
                                        const std::string& writeInterval) {
  return [=](CaseRunner& c) {
    c.set("system/particleMeshDict", "spacing", spacing);
    c.set("system/controlDict", "endTime", endTime);
    c.set("system/controlDict", "writeInterval", writeInterval);
  };
}

ParticleCloud cloudAt(const CaseRunner& c, const std::string& time) { return readCloud(c.path() / time, "particles"); }

// The relative L2 error of the material's p against perDepth × (depth below the highest
// material particle), as the hydrostatic and lithostatic tests measure it.
double depthPressureError(const ParticleCloud& cloud, double perDepth) {
  double top = -1e300, e2 = 0, p2 = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.kind[i] == 0) top = std::max(top, cloud.positions[i].y());
  }
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.kind[i] != 0) continue;
    const double exact = perDepth * (top - cloud.positions[i].y());
    e2 += (cloud.p[i] - exact) * (cloud.p[i] - exact);
    p2 += exact * exact;
  }
  return std::sqrt(e2 / p2);
}

// Still water (HydrostaticTankTest.cpp): the L2 error of p against rho g depth, the peak speed,
// the wall force of the patchForces function object (rank 0 writes it from the ranks' sums).
ParallelCase hydrostaticTank() {
  ParallelCase pc{"hydrostaticTank",
                  coarse("0.02", "0.5", "0.5"),
                  "0.5",
                  [](const CaseRunner& c) {
                    const ParticleCloud cloud = cloudAt(c, "0.5");
                    double speed = 0;
                    for (std::size_t i = 0; i < cloud.size(); ++i) {
                      if (cloud.kind[i] == 0) speed = std::max(speed, cloud.U[i].norm());
                    }
                    std::ifstream in(c.path() / "postProcessing/rightWallForce/0/force.dat");
                    std::string line, last;
                    while (std::getline(in, line)) {
                      if (!line.empty() && line[0] != '#') last = line;
                    }
                    double t = 0, fx = 0;
                    std::istringstream(last) >> t >> fx;
                    return Figures{{"pL2", depthPressureError(cloud, 1000 * 9.81)}, {"peakSpeed", speed}, {"rightWallForce", fx}};
                  },
                  // noise (the Noise test below): pL2 1.3e-8, peak speed 7.4e-10 m/s, force 1e-5 N/m (the
                  // last of force.dat's 8 digits); measured on 2-3 ranks: 9.3e-9, 3.8e-10, 1e-5
                  {{"pL2", 5e-8}, {"peakSpeed", 3e-9}, {"rightWallForce", 3e-5}}};
  return pc;
}

TEST(ParallelCases, HydrostaticTankOnOneTwoAndThreeRanks) { checkOnRanks(hydrostaticTank()); }

// The surge front of the dam break (DamBreakTest.cpp) at every write time: x of the foremost
// material particle below half the column's height.
ParallelCase damBreak() {
  constexpr double a = 0.05715;
  ParallelCase pc{"damBreak",
                  [](CaseRunner& c) {
                    c.set("system/particleMeshDict", "spacing", std::to_string(a / 10));
                    c.set("system/controlDict", "endTime", "0.2");
                    c.set("system/controlDict", "writeInterval", "0.02");
                  },
                  "0.2",
                  [](const CaseRunner& c) {
                    Figures f;
                    for (int k = 1; k <= 10; ++k) {
                      std::ostringstream t;
                      t << 0.02 * k;
                      const ParticleCloud cloud = cloudAt(c, t.str());
                      double front = 0;
                      for (std::size_t i = 0; i < cloud.size(); ++i) {
                        if (cloud.kind[i] == 0 && cloud.positions[i].y() < 0.5 * a) {
                          front = std::max(front, cloud.positions[i].x());
                        }
                      }
                      f["front at " + t.str() + " s"] = front;
                    }
                    return f;
                  },
                  {}};
  // noise: 1e-13 m at 0.02 s growing to 1.4e-11 m at 0.2 s; measured on 2-3 ranks: up to 1.2e-11 m
  for (int k = 1; k <= 10; ++k) {
    std::ostringstream t;
    t << "front at " << 0.02 * k << " s";
    pc.tolerance[t.str()] = 5e-11;
  }
  return pc;
}

TEST(ParallelCases, DamBreakOnOneTwoAndThreeRanks) { checkOnRanks(damBreak()); }

// A sand layer at rest on a 20 degree slope (GranularAtRestTest.cpp): how far any particle moved,
// and the L2 error of p against rho |g| cos(beta) depth.
ParallelCase granularAtRest() {
  ParallelCase pc{"granularAtRest",
                  coarse("0.01", "0.5", "0.5"),
                  "0.5",
                  [](const CaseRunner& c) {
                    const double rho = 1800, g = 9.81, beta = 20 * M_PI / 180;
                    const ParticleCloud start = cloudAt(c, "0"), end = cloudAt(c, "0.5");
                    return Figures{{"maxDisplacement", isph::test::largestMaterialDisplacement(start, end)},
                                   {"pL2", depthPressureError(end, rho * g * std::cos(beta))}};
                  },
                  // noise: displacement 5.4e-11 m (of 5.2e-4 m), pL2 5.3e-10; on 2-3 ranks: 2.8e-11, 2e-10
                  {{"maxDisplacement", 2e-10}, {"pL2", 2e-9}}};
  return pc;
}

TEST(ParallelCases, GranularAtRestOnOneTwoAndThreeRanks) { checkOnRanks(granularAtRest()); }

// The Bui et al. granular column collapse (ColumnCollapseTest.cpp), at 5 mm to 0.6 s: the toe,
// the surface's height at the wall, the area under it and its RMS distance to the measured
// final surface. Partitioned by HSFC.
ParallelCase columnCollapse() {
  const auto measured = readProfileCsv(std::string(ISPH_TUTORIALS) +
                                       "/columnCollapse/validation/granular_collapse_bui2008_final_surface.csv");
  EXPECT_GE(measured.size(), 10u);
  ParallelCase pc{"columnCollapse",
                  coarse("0.005", "0.6", "0.6"),
                  "0.6",
                  [measured](const CaseRunner& c) {
                    const ParticleCloud end = cloudAt(c, "0.6");
                    RunOutSpec toe;
                    toe.minNeighbours = 2;
                    SurfaceSpec bins;
                    bins.binWidth = 0.005;
                    bins.xMin = 0;
                    bins.xMax = 0.6;
                    const SurfaceProfile surface = surfaceProfile(end, bins);
                    double area = 0;
                    for (const double h : surface.height) area += h * bins.binWidth;
                    return Figures{{"toe", runOut(end, toe).value_or(0.0)},
                                   {"heightAtWall", surface.height.front()},
                                   {"area", area},
                                   {"surfaceRms", rmsDistance(surface, measured)}};
                  },
                  // noise with the one granular scheme set of issue 48 (the Noise test below,
                  // 2026-12-06): toe 2.2e-8 m, height at the wall 7.9e-8 m, RMS 4.0e-7 m, area
                  // 2.0e-7 m^2 (before it: 1.8e-8, 2.3e-9, 8.3e-9, 3.2e-9: the shifting by the
                  // speed of deformation carries the solver's tolerance further); on 3 ranks:
                  // 2.1e-8, 7.9e-8, 4.0e-7, 2.0e-7 (the same alternative as the tighter tolerance)
                  {{"toe", 1e-7}, {"heightAtWall", 3e-7}, {"area", 6e-7}, {"surfaceRms", 1.2e-6}},
                  "HSFC"};
  return pc;
}

TEST(ParallelCases, ColumnCollapseOnOneTwoAndThreeRanks) { checkOnRanks(columnCollapse()); }

// How the tolerances above were set (by hand; it checks nothing):
//   build/tests/testIsphParallel --gtest_also_run_disabled_tests --gtest_filter='*Noise*'
// runs each case serially with its linear solvers at their tolerance and at a tenth of it, and
// prints how much each figure moves: the run-to-run noise a parallel run's solves (whose
// AMG hierarchies and sums differ from the serial run's at the solver tolerance) may show.
TEST(ParallelCases, DISABLED_NoiseOfTheSerialFiguresUnderATenTimesTighterSolverTolerance) {
  for (const ParallelCase& pc : {hydrostaticTank(), damBreak(), granularAtRest(), columnCollapse()}) {
    std::map<std::string, Figures> figures;
    for (const std::string tolerance : {"default", "tight"}) {
      CaseRunner c(pc.tutorial, pc.tutorial + "-" + tolerance);
      pc.setUp(c);
      if (tolerance == "tight") {  // every solver's tolerance (1e-8 in these cases) to 1e-9
        const auto file = c.path() / "system" / "isphSolution";
        const std::string text = isph::test::readText(file);
        const std::string tight = std::regex_replace(text, std::regex("(tolerance[ \t]+)1e-8;"), "$011e-9;");
        ASSERT_NE(tight, text) << "no tolerance 1e-8 in " << file;
        std::ofstream(file) << tight;
      }
      ASSERT_EQ(c.run(PARTICLEMESH_EXE, "particleMesh"), 0);
      ASSERT_EQ(c.run(SOLVER_EXE, "isphLandslideFoam", "", "OMP_NUM_THREADS=1"), 0);
      figures[tolerance] = pc.measure(c);
    }
    for (const auto& [name, value] : figures["default"]) {
      std::printf("%s: %s %.8g, with a tenth of the solver tolerance %.8g (difference %.3g; tolerance %.3g)\n",
                  pc.tutorial.c_str(), name.c_str(), value, figures["tight"].at(name), figures["tight"].at(name) - value,
                  pc.tolerance.at(name));
    }
  }
}

// A run stopped and restarted on 2 ranks from its processor directories (startFrom
// latestTime) matches the uninterrupted 2-rank run to the solvers' tolerance: the restart
// partitions anew, so its solves (AMG hierarchies, order of the sums) differ from the
// continuous run's at their tolerance, as a parallel run's differ from the serial run's.
// Measured: 1.2e-10 dx and 1.9e-11 m/s (the serial dam break's front moves by 1e-13 to
// 1.4e-11 m under a ten times tighter solver tolerance, above); checked within 1e-9 dx and
// 1e-10 m/s, about five to eight times that.
TEST(ParallelCases, RestartOnTwoRanksMatchesTheUninterruptedRun) {
  const double dx = 0.05715 / 10;
  CaseRunner whole("damBreak", "parallelRestartWhole"), split("damBreak", "parallelRestartSplit");
  for (CaseRunner* c : {&whole, &split}) {
    c->set("system/particleMeshDict", "spacing", std::to_string(dx));
    c->set("system/controlDict", "writeInterval", "0.02");
    ASSERT_EQ(c->run(PARTICLEMESH_EXE, "particleMesh"), 0);
  }
  whole.set("system/controlDict", "endTime", "0.06");
  ASSERT_NO_FATAL_FAILURE(runParallel(whole, 2, false));
  split.set("system/controlDict", "endTime", "0.04");
  ASSERT_NO_FATAL_FAILURE(runParallel(split, 2, false));
  split.set("system/controlDict", "endTime", "0.06");
  std::filesystem::remove(split.path() / "log.isphLandslideFoam");
  ASSERT_NO_FATAL_FAILURE(runParallel(split, 2, false));
  EXPECT_NE(isph::test::readText(split.path() / "log.isphLandslideFoam").find("Reading cloud 'particles' from 0.04"),
            std::string::npos) << "the second run must restart from 0.04";
  const ParticleCloud A = cloudAt(whole, "0.06"), B = cloudAt(split, "0.06");
  ASSERT_EQ(A.size(), B.size());
  const auto [maxDx, maxDu] = isph::test::largestDifference(A, B);
  std::printf("largest difference: position %.3g dx, velocity %.3g m/s\n", maxDx / dx, maxDu);
  EXPECT_LT(maxDx, 1e-9 * dx);
  EXPECT_LT(maxDu, 1e-10);
}

// Crash safety in a parallel run (issue 34's, in the processor directories): what interrupted
// writes left in processor<i>/ is recovered once, by rank 0, before the ranks read (a replace
// caught between its renames restored, an unfinished write and a purge's rest removed: the
// ranks raced on them before); purgeWrite purges each processor's own times. A time that one
// rank had written when the run was killed and another had not (removed here from processor1)
// is skipped by reconstructPar with a warning, and a restart (startFrom latestTime) starts from
// the latest time both processors hold.
TEST(ParallelCases, TwoRanksRecoverTheProcessorDirectoriesAndRestartFromTheLatestCommonTime) {
  CaseRunner c("damBreak", "parallelRecovery");
  c.set("system/particleMeshDict", "spacing", std::to_string(0.05715 / 10));
  c.set("system/controlDict", "endTime", "0.003");
  c.set("system/controlDict", "writeInterval", "0.001");
  c.set("system/controlDict", "purgeWrite", "2");
  ASSERT_EQ(c.run(PARTICLEMESH_EXE, "particleMesh"), 0);
  std::ofstream(c.path() / "system" / "decomposeParDict")
      << "FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
      << "numberOfSubdomains 2;\nmethod zoltan;\nzoltanCoeffs { algorithm RCB; }\n";
  ASSERT_EQ(c.run(DECOMPOSEPAR_EXE, "decomposePar"), 0);
  namespace fs = std::filesystem;
  const fs::path p0 = c.path() / "processor0", p1 = c.path() / "processor1";
  fs::rename(p1 / "0", p1 / ".0.old.4000000@otherhost");  // a replace of 0 killed between its renames
  fs::create_directories(p0 / ".0.002.tmp.4000000@otherhost" / "lagrangian");  // an unfinished write
  fs::create_directories(p0 / ".0.001.trash.4000000@otherhost" / "uniform");  // a purge's rest
  const std::string ranks = "-np 2 --oversubscribe --bind-to none --mca mpi_yield_when_idle 1 '" +
                            std::string(SOLVER_EXE) + "' -parallel";
  ASSERT_EQ(c.run(MPIRUN_EXE, "isphLandslideFoam", ranks, mpiEnvironment), 0)
      << "see " << c.path() / "log.isphLandslideFoam";
  const std::string log = isph::test::readText(c.path() / "log.isphLandslideFoam");
  const std::string report = "Interrupted writes in the case: 1 restored, 2 removed, 0 left alone";
  const auto at = log.find(report);
  EXPECT_NE(at, std::string::npos) << log.substr(0, 3000);
  EXPECT_EQ(log.find(report, at + 1), std::string::npos) << "reported once, by rank 0";
  auto listing = [](const fs::path& dir) {
    std::string names;
    for (const auto& t : listTimes(dir)) names += (names.empty() ? "" : " ") + t.name;
    for (const auto& e : fs::directory_iterator(dir)) {
      if (e.path().filename().string()[0] == '.') names += " hidden:" + e.path().filename().string();
    }
    return names;
  };
  for (const fs::path& p : {p0, p1}) {
    EXPECT_EQ(listing(p), "0 0.002 0.003") << p << ": the start time, the last two (purgeWrite 2), nothing hidden";
  }

  fs::remove_all(p1 / "0.003");  // killed after rank 0 wrote 0.003, before rank 1 had
  // (issue 54: it stops there, exit 1, the times before it done; -skipDamaged goes past it)
  EXPECT_EQ(c.run(RECONSTRUCTPAR_EXE, "reconstructPar"), 1) << "see " << c.path() / "log.reconstructPar";
  EXPECT_EQ(listing(c.path()), "0 0.002") << "0 and 0.002 reconstructed before the stop";
  const std::string stopped = isph::test::readText(c.path() / "log.reconstructPar");
  EXPECT_NE(stopped.find("time 0.003 cannot be read"), std::string::npos) << stopped;
  EXPECT_NE(stopped.find("-skipDamaged"), std::string::npos) << stopped;
  ASSERT_EQ(c.run(RECONSTRUCTPAR_EXE, "reconstructPar", "-skipDamaged"), 0)
      << "see " << c.path() / "log.reconstructPar";
  EXPECT_EQ(listing(c.path()), "0 0.002") << "0.003 skipped";
  EXPECT_NE(isph::test::readText(c.path() / "log.reconstructPar").find("time 0.003 is skipped"), std::string::npos);
  c.set("system/controlDict", "endTime", "0.004");
  ASSERT_EQ(c.run(MPIRUN_EXE, "isphLandslideFoam", ranks, mpiEnvironment), 0)
      << "see " << c.path() / "log.isphLandslideFoam";
  EXPECT_NE(isph::test::readText(c.path() / "log.isphLandslideFoam").find("Reading cloud 'particles' from 0.002"),
            std::string::npos)
      << "the restart starts from the latest time both processors hold";
  for (const fs::path& p : {p0, p1}) {
    EXPECT_EQ(listing(p), "0 0.002 0.003 0.004") << p << ": 0.003 written again (processor0's replaced)";
  }
}

}  // namespace
