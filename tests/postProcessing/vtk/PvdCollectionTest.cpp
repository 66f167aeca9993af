// The ParaView collection: every converted time in time order, merged with what is there.
#include "postProcessing/vtk/PvdCollection.hpp"

#include <gtest/gtest.h>

#include "../PostProcessingTestHelpers.hpp"
#include "core/Error.hpp"

namespace isph {
namespace {

std::vector<std::string> timesOf(const std::vector<PvdEntry>& entries) {
  std::vector<std::string> out;
  for (const auto& e : entries) out.push_back(e.time);
  return out;
}

TEST(PvdCollection, MergesInTimeOrderAndReplacesATimeConvertedAgain) {
  pptest::TempDir dir;
  for (const char* f : {"c_0.vtp", "c_1e-05.vtp", "c_0.1.vtp", "c_2.vtp", "c_10.vtp"}) pptest::writeText(dir / f, "x");
  const auto pvd = dir / "c.pvd";
  updatePvd(pvd, {{"2", "c_2.vtp"}, {"0.1", "c_0.1.vtp"}});
  updatePvd(pvd, {{"10", "c_10.vtp"}, {"0", "c_0.vtp"}});
  const auto entries = updatePvd(pvd, {{"1e-05", "c_1e-05.vtp"}, {"0.1", "c_0.1.vtp"}});
  EXPECT_EQ(timesOf(entries), (std::vector<std::string>{"0", "1e-05", "0.1", "2", "10"}));
  EXPECT_EQ(timesOf(readPvd(pvd)), timesOf(entries));  // what was written reads back
  EXPECT_EQ(readPvd(pvd)[2].file, "c_0.1.vtp");
}

TEST(PvdCollection, DropsEntriesWhoseFileIsGone) {
  pptest::TempDir dir;
  pptest::writeText(dir / "c_0.vtp", "x");
  pptest::writeText(dir / "c_1.vtp", "x");
  updatePvd(dir / "c.pvd", {{"0", "c_0.vtp"}, {"1", "c_1.vtp"}});
  std::filesystem::remove(dir / "c_1.vtp");
  EXPECT_EQ(timesOf(updatePvd(dir / "c.pvd", {})), std::vector<std::string>{"0"});
}

TEST(PvdCollection, TextIsAParaViewCollection) {
  const std::string text = pvdText({{"0.5", "a&b.vtp"}});
  EXPECT_NE(text.find("<VTKFile type=\"Collection\""), std::string::npos);
  EXPECT_NE(text.find("<DataSet timestep=\"0.5\" group=\"\" part=\"0\" file=\"a&amp;b.vtp\"/>"), std::string::npos)
      << text;
}

TEST(PvdCollection, ABrokenFileIsAFatalErrorNamingIt) {
  pptest::TempDir dir;
  pptest::writeText(dir / "c.pvd", "<VTKFile type=\"Collection\"><Nothing/></VTKFile>\n");
  try {
    readPvd(dir / "c.pvd");
    FAIL() << "a collection without <Collection> was accepted";
  } catch (const FatalError& e) {
    EXPECT_NE(std::string(e.what()).find("c.pvd"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace isph
