// CSV point files: comments, a header naming x and y among other columns, plain two-column
// files; errors name the CSV file and its line, or the keyword when the file is missing.
#include <gtest/gtest.h>

#include "SceneTestHelpers.hpp"
#include "particleGeneration/CsvPoints.hpp"

namespace isph {
namespace {

TEST(CsvPoints, HeaderPicksColumnsByName) {
  test::TempCase c;
  const auto file = c.write("ground.csv", "# surveyed\n\nid,y,x\n1,0.5,2\n2, 1.5 ,3\r\n");
  const CsvPoints p = readCsvPoints(file, {});
  ASSERT_EQ(p.points.size(), 2u);
  EXPECT_EQ(p.points[0], Vec2(2, 0.5));
  EXPECT_EQ(p.points[1], Vec2(3, 1.5));
  EXPECT_EQ(p.lines, (std::vector<int>{4, 5}));
}

TEST(CsvPoints, WithoutHeaderTheFirstTwoColumns) {
  test::TempCase c;
  const auto file = c.write("slip.csv", "0,0\n1e1,-2.5,ignored\n");
  const CsvPoints p = readCsvPoints(file, {});
  ASSERT_EQ(p.points.size(), 2u);
  EXPECT_EQ(p.points[1], Vec2(10, -2.5));
}

TEST(CsvPoints, Errors) {
  test::TempCase c;
  auto file = c.write("bad.csv", "x,y\n0,0\n1\n");
  FatalError e = test::expectFatal([&] { readCsvPoints(file, {}); });
  ASSERT_TRUE(e.where().file);
  EXPECT_EQ(*e.where().file, file.string());
  EXPECT_EQ(e.where().line, 3);
  file = c.write("header.csv", "east,north\n0,0\n");
  e = test::expectFatal([&] { readCsvPoints(file, {}); });
  EXPECT_EQ(e.where().line, 1);
  EXPECT_NE(std::string(e.what()).find("x and y"), std::string::npos);
  file = c.write("empty.csv", "# nothing\n");
  e = test::expectFatal([&] { readCsvPoints(file, {}); });
  EXPECT_NE(std::string(e.what()).find("no points"), std::string::npos);
  const SourceLocation keyword{std::make_shared<const std::string>("system/particleMeshDict"), 12,
                               5};
  e = test::expectFatal([&] { readCsvPoints(c.path() / "missing.csv", keyword); });
  EXPECT_EQ(e.where().line, 12);
  EXPECT_NE(std::string(e.what()).find("missing.csv"), std::string::npos);
}

// nan and inf were read as coordinates (issue 34); a device was read until memory ran out.
TEST(CsvPoints, NonFiniteValuesAndHostileFilesAreRefused) {
  test::TempCase c;
  for (const std::string bad : {"nan", "inf", "-Infinity", "1e400"}) {
    const auto file = c.write("ground.csv", "x,y\n0,0\n1," + bad + "\n");
    const FatalError e = test::expectFatal([&] { readCsvPoints(file, {}); });
    EXPECT_EQ(e.where().line, 3) << e.report();
    EXPECT_NE(e.report().find("y = '" + bad + "' is not a finite number"), std::string::npos) << e.report();
  }
  // Without a header a first line of nan is data, not a header without x and y.
  auto file = c.write("slip.csv", "nan,0\n1,1\n");
  FatalError e = test::expectFatal([&] { readCsvPoints(file, {}); });
  EXPECT_EQ(e.where().line, 1);
  EXPECT_NE(e.report().find("x = 'nan' is not a finite number"), std::string::npos) << e.report();

  const SourceLocation keyword{std::make_shared<const std::string>("system/particleMeshDict"), 7, 5};
  e = test::expectFatal([&] { readCsvPoints("/dev/zero", keyword); });
  EXPECT_EQ(e.where().line, 7);
  EXPECT_NE(e.report().find("not a regular file"), std::string::npos) << e.report();

  file = c.write("long.csv", "x,y\n" + std::string(2 << 20, '1') + "\n");
  e = test::expectFatal([&] { readCsvPoints(file, {}); });
  EXPECT_EQ(e.where().line, 2);
  EXPECT_NE(e.report().find("longer than 1024 KiB"), std::string::npos) << e.report();
  file = c.write("wide.csv", "x,y\n" + std::string(5000, ',') + "\n");
  e = test::expectFatal([&] { readCsvPoints(file, {}); });
  EXPECT_NE(e.report().find("more than 1024 columns"), std::string::npos) << e.report();
}

}  // namespace
}  // namespace isph
