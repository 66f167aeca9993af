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

}  // namespace
}  // namespace isph
