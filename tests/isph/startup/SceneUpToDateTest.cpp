// An edit of system/particleMeshDict after particleMesh made 0/ (a wall friction changed without
// particleMesh again) stops the solver, or with -force warns; a scene older than 0/, or newer
// only by what cp -r of a case makes, runs.
#include "isph/startup/SceneUpToDate.hpp"

#include <gtest/gtest.h>

#include <chrono>

#include "../postProcessing/PostProcessingTestHelpers.hpp"
#include "core/Error.hpp"

namespace {

using namespace isph;
using pptest::TempDir;
namespace fs = std::filesystem;

// A case whose particleMeshDict was written `seconds` after its 0/ (negative: before).
void makeCase(const TempDir& dir, double seconds) {
  pptest::writeText(dir / "0/lagrangian/particles/positions", "0\n()\n");
  pptest::writeText(dir / "system/particleMeshDict", "spacing 0.01;\n");
  const auto made = fs::last_write_time(dir / "0/lagrangian/particles/positions");
  fs::last_write_time(dir / "system/particleMeshDict",
                      made + std::chrono::duration_cast<fs::file_time_type::duration>(
                                 std::chrono::duration<double>(seconds)));
}

TEST(SceneUpToDate, ASceneEditedAfterParticleMeshStopsTheSolver) {
  TempDir dir;
  makeCase(dir, 60);
  try {
    checkSceneUpToDate(dir.path(), false);
    ADD_FAILURE() << "an edited scene was run";
  } catch (const FatalError& e) {
    const std::string r = e.report();
    EXPECT_NE(r.find("particleMeshDict was changed 60 s after the particles in"), std::string::npos) << r;
    EXPECT_NE(r.find("Run particleMesh again"), std::string::npos) << r;
    EXPECT_NE(r.find("-force"), std::string::npos) << r;
  }
  const int before = warningCount();
  testing::internal::CaptureStderr();
  EXPECT_NO_THROW(checkSceneUpToDate(dir.path(), true));
  (void)testing::internal::GetCapturedStderr();
  EXPECT_EQ(warningCount(), before + 1);
}

TEST(SceneUpToDate, AnOlderSceneOrACopyRuns) {
  TempDir dir;
  makeCase(dir, -60);
  EXPECT_NO_THROW(checkSceneUpToDate(dir.path(), false));
  makeCase(dir, 0.5 * copySlackSeconds);  // cp -r wrote system/ just after 0/
  EXPECT_NO_THROW(checkSceneUpToDate(dir.path(), false));
  fs::remove_all(dir / "0");  // nothing to compare (a decomposed case, a scene not meshed yet)
  EXPECT_NO_THROW(checkSceneUpToDate(dir.path(), false));
}

}  // namespace
