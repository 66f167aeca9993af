// A parallel run restarting with startFrom latestTime starts from the latest time that every
// processor directory holds (Time.hpp): one that a rank wrote before the run was killed, while
// the others had not, is passed over. Run by testParallel on 1 and 3 ranks.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/time/Time.hpp"
#include "parallel/Reduce.hpp"

namespace {

using namespace isph;
namespace fs = std::filesystem;

TEST(TimeOverRanks, LatestTimeIsTheLatestEveryProcessorHolds) {
  // (one case for all ranks: named by rank 0's process id)
  const long pid = sumOverRanks(thisRank() == 0 ? static_cast<long>(::getpid()) : 0L);
  const fs::path dir = fs::temp_directory_path() / ("isphTimeOverRanks-" + std::to_string(pid));
  if (thisRank() == 0) {
    fs::remove_all(dir);
    fs::create_directories(dir / "system");
    std::ofstream(dir / "system/controlDict")
        << "FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }\n"
        << "startFrom latestTime; endTime 1; deltaT 0.1; writeControl timeStep; writeInterval 1;\n";
  }
  sumOverRanks(0L);  // (a barrier)
  const fs::path mine = dir / ("processor" + std::to_string(thisRank()));
  for (const char* t : {"0.1", "0.2"}) fs::create_directories(mine / t);
  // Rank 0 wrote 0.3 and purged 0.1 (purgeWrite 2) before the run was killed; the others had not.
  if (thisRank() == 0) {
    fs::create_directories(mine / "0.3");
    fs::remove_all(mine / "0.1");
  }
  sumOverRanks(0L);
  {
    const Time time(dir, "processor" + std::to_string(thisRank()));
    EXPECT_EQ(time.timeName(), nRanks() == 1 ? "0.3" : "0.2");
    EXPECT_TRUE(time.decomposedStart());
    EXPECT_EQ(time.startPath(), mine / time.timeName());
  }
  sumOverRanks(0L);
  if (thisRank() == 0) fs::remove_all(dir);
}

}  // namespace
