// Replays the inputs the fuzzers found (tests/fuzz/regressions/<target>/, one file each, named
// for what went wrong) through the fuzz targets' bodies in this build (g++, and with
// ./Allwmake -sanitize under the sanitizers): each must end in a FatalError or be read, not
// crash or hang. The fuzzers replay them too before they run (runFuzzer.sh).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "FuzzTargets.hpp"

namespace {

namespace fs = std::filesystem;

std::string bytesOf(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(FuzzRegressions, EveryKeptInputIsReadOrRefused) {
  const std::map<std::string, std::function<void(std::string_view)>> targets{
      {"dictionary", isph::fuzz::dictionary},
      {"fieldAscii", isph::fuzz::fieldFile},
      {"fieldBinary", isph::fuzz::binaryFieldData},
      {"csvPoints", isph::fuzz::csvPoints}};
  int replayed = 0;
  for (const auto& dir : fs::directory_iterator(ISPH_FUZZ_REGRESSIONS)) {
    const auto target = targets.find(dir.path().filename().string());
    ASSERT_NE(target, targets.end()) << "no fuzz target " << dir.path().filename();
    for (const auto& input : fs::directory_iterator(dir.path())) {
      SCOPED_TRACE(input.path().string());
      target->second(bytesOf(input.path()));  // a crash or another exception fails the test
      ++replayed;
    }
  }
  EXPECT_GT(replayed, 0);
}

}  // namespace
