// Reading system/particleMeshDict: a complete scene, the wall layers from the kernel, and bad
// input, each reported with the file, line and keyword to fix (nothing is generated then).
#include <gtest/gtest.h>

#include "SceneTestHelpers.hpp"
#include "particleGeneration/SceneReader.hpp"

namespace isph {
namespace {

using test::expectFatal;
using test::TempCase;

const char* materials = R"(materials
{
    sand { model rigidPlastic; rho 1379; phi 44; }
    clay { model rigidPlastic; rho 1800; phi 25; }
}
)";

const char* validDict = R"(spacing         0.01;
cloud           grains;
lattice         hexagonal;
initialPressure lithostatic;
initialVelocity (0.5 0 0);
transform { rotate -45; origin (0 0 0); translate (0 1 0); }
regions
{
    sandBox { type box; min (0 0 0); max (0.5 0.24 0); material sand; }
    clayLens
    {
        type        polygon;
        points      ((0.6 0 0) (0.9 0 0) (0.7 0.2 0));
        material    clay;
        initialVelocity (0 0 0);
    }
}
walls
{
    bed     { type polyline; points ((0 0.4 0) (0 0 0) (2.4 0 0)); frictionAngle 25; }
    barrier { type box; min (1.8 0 0); max (1.82 0.3 0); frictionAngle 20; patch obstacle; rho 2500; }
}
)";

// 1-based line of the first line of `text` that contains `what`.
int lineOf(const std::string& text, const std::string& what) {
  const std::size_t at = text.find(what);
  EXPECT_NE(at, std::string::npos) << what;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

// The case with `dict` as particleMeshDict; expects readScene (and generation) to fail and
// returns the error.
FatalError sceneError(const TempCase& c, const std::string& dict) {
  c.write("system/particleMeshDict", dict);
  return expectFatal([&] { generateParticles(readScene(c.path())); });
}

void expectAt(const FatalError& e, const std::string& fileEnd, int line) {
  ASSERT_TRUE(e.where().file) << e.what();
  const std::string& file = *e.where().file;
  EXPECT_EQ(file.substr(file.size() - std::min(file.size(), fileEnd.size())), fileEnd) << file;
  EXPECT_EQ(e.where().line, line) << e.what();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

class SceneReader : public ::testing::Test {
 protected:
  void SetUp() override {
    c.write("constant/materialProperties", materials);
    c.write("constant/g", "dimensions [0 1 -2 0 0 0 0];\nvalue (0 -9.81 0);\n");
  }
  TempCase c;
};

TEST_F(SceneReader, ReadsACompleteScene) {
  c.write("system/particleMeshDict", validDict);
  const Scene s = readScene(c.path());
  EXPECT_DOUBLE_EQ(s.spacing, 0.01);
  EXPECT_EQ(s.cloudName, "grains");
  EXPECT_EQ(s.lattice, LatticeType::hexagonal);
  EXPECT_EQ(s.wallLayers, 3);  // no system/isphSchemes: Wendland C2, h = 1.3 dx
  EXPECT_EQ(s.initialPressure, InitialPressure::lithostatic);
  EXPECT_EQ(s.gravity, Vec3(0, -9.81, 0));
  EXPECT_DOUBLE_EQ(s.transform.angleDegrees(), -45);
  EXPECT_EQ(s.materials, (std::vector<std::string>{"sand", "clay"}));
  ASSERT_EQ(s.regions.size(), 2u);
  EXPECT_EQ(s.regions[1].material, 1);
  EXPECT_DOUBLE_EQ(s.regions[1].density, 1800);
  EXPECT_EQ(s.regions[0].initialVelocity, Vec3(0.5, 0, 0));
  EXPECT_EQ(s.regions[1].initialVelocity, Vec3::Zero());
  ASSERT_EQ(s.patches.size(), 2u);
  EXPECT_EQ(s.patches[1].name, "obstacle");
  EXPECT_DOUBLE_EQ(s.patches[1].frictionAngle, 20);
  EXPECT_DOUBLE_EQ(s.walls[0].density, 1379);  // default: the first region's material
  EXPECT_DOUBLE_EQ(s.walls[1].density, 2500);
  EXPECT_EQ(s.walls[0].side, MaterialSide::automatic);
  const GenerationResult r = generateParticles(s);
  EXPECT_EQ(r.cloud.name, "grains");
  EXPECT_EQ(r.cloud.properties.lattice, "hexagonal");
  EXPECT_GT(r.cloud.size(), 1000u);
}

TEST_F(SceneReader, WallLayersFollowTheKernel) {
  c.write("system/particleMeshDict", validDict);
  c.write("system/isphSchemes", "kernel WendlandC2;\nhOverDx 2.0;\n");
  EXPECT_EQ(readScene(c.path()).wallLayers, 4);
  c.write("system/particleMeshDict", std::string(validDict) + "wallLayers 5;\n");
  EXPECT_EQ(readScene(c.path()).wallLayers, 5);
}

TEST_F(SceneReader, MissingSpacing) {
  const FatalError e = sceneError(c, replaced(validDict, "spacing         0.01;\n", ""));
  EXPECT_NE(std::string(e.what()).find("spacing"), std::string::npos) << e.what();
  ASSERT_TRUE(e.where().file);
  EXPECT_NE(e.where().file->find("particleMeshDict"), std::string::npos);
}

TEST_F(SceneReader, NonPositiveSpacing) {
  const std::string dict = replaced(validDict, "0.01;", "-0.01;");
  const FatalError e = sceneError(c, dict);
  EXPECT_NE(std::string(e.what()).find("'spacing'"), std::string::npos) << e.what();
  expectAt(e, "particleMeshDict", lineOf(dict, "spacing"));
}

TEST_F(SceneReader, UnknownRegionTypeSuggestsTheNearestName) {
  const std::string dict = replaced(validDict, "type box; min (0 0 0)", "type boxx; min (0 0 0)");
  const FatalError e = sceneError(c, dict);
  EXPECT_NE(std::string(e.what()).find("unknown region type 'boxx'"), std::string::npos)
      << e.what();
  EXPECT_NE(std::string(e.what()).find("did you mean box"), std::string::npos) << e.what();
  expectAt(e, "particleMeshDict", lineOf(dict, "boxx"));
}

TEST_F(SceneReader, UnknownWallType) {
  const std::string dict = replaced(validDict, "type polyline;", "type polyLine;");
  const FatalError e = sceneError(c, dict);
  EXPECT_NE(std::string(e.what()).find("did you mean polyline"), std::string::npos) << e.what();
  expectAt(e, "particleMeshDict", lineOf(dict, "polyLine"));
}

TEST_F(SceneReader, MaterialNotInMaterialProperties) {
  const std::string dict = replaced(validDict, "material sand;", "material sandd;");
  const FatalError e = sceneError(c, dict);
  EXPECT_NE(std::string(e.what()).find("unknown material 'sandd'"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("did you mean sand"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("sand, clay"), std::string::npos) << e.what();
  expectAt(e, "particleMeshDict", lineOf(dict, "sandd"));
}

TEST_F(SceneReader, MissingMaterialProperties) {
  std::filesystem::remove(c.path() / "constant/materialProperties");
  const FatalError e = sceneError(c, validDict);
  EXPECT_NE(std::string(e.what()).find("materialProperties"), std::string::npos) << e.what();
}

TEST_F(SceneReader, PolygonWithTooFewPoints) {
  const std::string dict =
      replaced(validDict, "((0.6 0 0) (0.9 0 0) (0.7 0.2 0))", "((0.6 0 0) (0.9 0 0))");
  const FatalError e = sceneError(c, dict);
  EXPECT_NE(std::string(e.what()).find("at least 3"), std::string::npos) << e.what();
  expectAt(e, "particleMeshDict", lineOf(dict, "points      ("));
}

TEST_F(SceneReader, SelfIntersectingPolygon) {
  const std::string dict = replaced(validDict, "((0.6 0 0) (0.9 0 0) (0.7 0.2 0))",
                                    "((0.6 0 0) (0.9 0.2 0) (0.9 0 0) (0.6 0.2 0))");
  const FatalError e = sceneError(c, dict);
  EXPECT_NE(std::string(e.what()).find("crosses itself"), std::string::npos) << e.what();
  expectAt(e, "particleMeshDict", lineOf(dict, "points      ("));
}

TEST_F(SceneReader, ZeroAreaBox) {
  const std::string dict = replaced(validDict, "max (0.5 0.24 0)", "max (0.5 0 0)");
  const FatalError e = sceneError(c, dict);
  EXPECT_NE(std::string(e.what()).find("zero area"), std::string::npos) << e.what();
  expectAt(e, "particleMeshDict", lineOf(dict, "max (0.5 0 0)"));
}

TEST_F(SceneReader, RegionWithoutSitesAtThisSpacing) {
  const std::string dict = replaced(validDict, "min (0 0 0); max (0.5 0.24 0)",
                                    "min (0.001 0.001 0); max (0.004 0.004 0)");
  const FatalError e = sceneError(c, dict);
  EXPECT_NE(std::string(e.what()).find("holds no lattice site"), std::string::npos) << e.what();
  expectAt(e, "particleMeshDict", lineOf(dict, "sandBox"));
}

TEST_F(SceneReader, WallWithoutFrictionAngle) {
  const std::string dict = replaced(validDict, " frictionAngle 25;", "");
  const FatalError e = sceneError(c, dict);
  EXPECT_NE(std::string(e.what()).find("frictionAngle"), std::string::npos) << e.what();
}

TEST_F(SceneReader, MaterialSideIsForPolylines) {
  const std::string dict =
      replaced(validDict, "patch obstacle;", "patch obstacle; materialSide left;");
  const FatalError e = sceneError(c, dict);
  EXPECT_NE(std::string(e.what()).find("materialSide"), std::string::npos) << e.what();
  expectAt(e, "particleMeshDict", lineOf(dict, "materialSide"));
}

TEST_F(SceneReader, LithostaticNeedsGravity) {
  std::filesystem::remove(c.path() / "constant/g");
  const FatalError e = sceneError(c, validDict);
  EXPECT_NE(std::string(e.what()).find("constant/g"), std::string::npos) << e.what();
  expectAt(e, "particleMeshDict", lineOf(validDict, "initialPressure"));
}

// A misspelt keyword (the region would start at rest) is an error at its line; an unknown one
// far from every keyword a warning.
TEST_F(SceneReader, MisspeltKeywordIsAnErrorUnknownOneAWarning) {
  const std::string dict = replaced(validDict, "material    clay;", "material    clay; initalVelocity (1 0 0);");
  const FatalError e = sceneError(c, dict);
  EXPECT_NE(std::string(e.what()).find("did you mean initialVelocity?"), std::string::npos) << e.what();
  expectAt(e, "particleMeshDict", lineOf(dict, "initalVelocity"));
  c.write("system/particleMeshDict", replaced(validDict, "material    clay;", "material    clay; remark lens;"));
  const int before = warningCount();
  readScene(c.path());
  EXPECT_EQ(warningCount(), before + 1);
}

TEST_F(SceneReader, PointsMustLieInThePlane) {
  const std::string dict = replaced(validDict, "(0.7 0.2 0))", "(0.7 0.2 1))");
  const FatalError e = sceneError(c, dict);
  EXPECT_NE(std::string(e.what()).find("z must be 0"), std::string::npos) << e.what();
  expectAt(e, "particleMeshDict", lineOf(dict, "points      ("));
}

// A 3D scene: the extent in z, square lattice, side walls; each misuse names its keyword.
TEST_F(SceneReader, ThreeDimensionalScene) {
  const std::string square = replaced(validDict, "lattice         hexagonal;", "lattice         square;");
  c.write("system/particleMeshDict",
          square + "dimension 3;\nwidth 0.2;\nsideWalls { frictionAngle 10; patch sides; rho 2000; }\n");
  const Scene s = readScene(c.path());
  EXPECT_EQ(s.dimension, 3);
  EXPECT_DOUBLE_EQ(s.width, 0.2);
  ASSERT_TRUE(s.sideWalls);
  EXPECT_EQ(s.sideWalls->patch[0], s.sideWalls->patch[1]);
  EXPECT_EQ(s.patches.at(static_cast<std::size_t>(s.sideWalls->patch[0])).name, "sides");
  EXPECT_DOUBLE_EQ(s.patches.at(static_cast<std::size_t>(s.sideWalls->patch[0])).frictionAngle, 10);
  EXPECT_DOUBLE_EQ(s.sideWalls->density, 2000);

  c.write("system/particleMeshDict",
          square + "dimension 3;\nwidth 0.2;\nsideWalls { frictionAngle 10; patches (front back); }\n");
  const Scene two = readScene(c.path());
  EXPECT_EQ(two.patches.at(static_cast<std::size_t>(two.sideWalls->patch[0])).name, "front");
  EXPECT_EQ(two.patches.at(static_cast<std::size_t>(two.sideWalls->patch[1])).name, "back");

  const auto errorAt = [&](const std::string& dict, const std::string& keyword, const std::string& says) {
    const FatalError e = sceneError(c, dict);
    EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    expectAt(e, "particleMeshDict", lineOf(dict, keyword));
  };
  errorAt(square + "dimension 4;\n", "dimension 4", "expected 2 (plane strain in x-y) or 3");
  errorAt(square + "dimension 3;\n", "dimension 3", "width");  // no width: at the dictionary
  errorAt(square + "dimension 3;\nwidth 0.001;\n", "width 0.001", "at least one spacing");
  errorAt(square + "width 0.2;\n", "width 0.2", "needs dimension 3");
  errorAt(square + "sideWalls { frictionAngle 10; }\n", "sideWalls", "needs dimension 3");
  errorAt(std::string(validDict) + "dimension 3;\nwidth 0.2;\n", "lattice         hexagonal", "lattice square");
  errorAt(square + "dimension 3;\nwidth 0.2;\nsideWalls { frictionAngel 10; }\n", "sideWalls", "frictionAngle");
  errorAt(square + "dimension 3;\nwidth 0.2;\nsideWalls { frictionAngle 10; patches (front); }\n", "sideWalls",
          "expected two names");
  c.write("system/particleMeshDict", square + "dimension 3;\nwidth 0.2;\nsideWalls { frictionAngle 10; max (3 0.6 0); }\n");
  const Scene clipped = readScene(c.path());
  EXPECT_DOUBLE_EQ(clipped.sideWalls->max.y(), 0.6);
  EXPECT_LT(clipped.sideWalls->min.x(), -1e299);  // min not given: no clip below
  errorAt(square + "dimension 3;\nwidth 0.2;\nsideWalls { frictionAngle 10; min (0 1 0); max (3 0.6 0); }\n",
          "sideWalls", "must exceed min");
  errorAt(square + "dimension 3;\nwidth 0.2;\nsideWalls { frictionAngle 10; max (3 0.6 0.1); }\n", "sideWalls",
          "z must be 0");
}

TEST_F(SceneReader, ARegionOfPartOfTheWidth) {
  const std::string square = replaced(validDict, "lattice         hexagonal;", "lattice         square;");
  const std::string threeD = square + "dimension 3;\nwidth 0.2;\n";
  const std::string half = replaced(threeD, "material sand; }", "material sand; zRange (0 0.1); }");
  c.write("system/particleMeshDict", half);
  const Scene s = readScene(c.path());
  ASSERT_TRUE(s.regions[0].zRange);
  EXPECT_DOUBLE_EQ(s.regions[0].zRange->lo, 0);
  EXPECT_DOUBLE_EQ(s.regions[0].zRange->hi, 0.1);
  EXPECT_FALSE(s.regions[1].zRange);

  const auto errorAt = [&](const std::string& dict, const std::string& keyword, const std::string& says) {
    const FatalError e = sceneError(c, dict);
    EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    expectAt(e, "particleMeshDict", lineOf(dict, keyword));
  };
  const auto withRange = [&](const std::string& base, const std::string& range) {
    return replaced(base, "material sand; }", "material sand; zRange " + range + "; }");
  };
  errorAt(withRange(square, "(0 0.1)"), "zRange", "needs dimension 3");
  errorAt(withRange(threeD, "(0.1 0.05)"), "zRange", "0 <= z0 < z1 <= 0.2");
  errorAt(withRange(threeD, "(0 0.3)"), "zRange", "0 <= z0 < z1 <= 0.2");
  errorAt(withRange(threeD, "(-0.01 0.1)"), "zRange", "0 <= z0 < z1 <= 0.2");
  errorAt(withRange(threeD, "(0 0.1 0.2)"), "zRange", "expected two values");
  errorAt(withRange(threeD, "(0.1001 0.1049)"), "zRange", "holds no layer");  // layers at 0.095, 0.105
  // A wall of part of the width is not available (its end faces: doc/notes/threeD.md).
  errorAt(replaced(threeD, "patch obstacle;", "patch obstacle; zRange (0 0.1);"), "barrier", "not available");
}

TEST_F(SceneReader, ACylinderIsA3DRegion) {
  const std::string square = replaced(validDict, "lattice         hexagonal;", "lattice         square;");
  const std::string cylinder =
      "type cylinder; base (0.3 0 0.1); radius 0.1; height 0.2; material sand; }";
  const std::string threeD = replaced(square + "dimension 3;\nwidth 0.2;\n",
                                      "type box; min (0 0 0); max (0.5 0.24 0); material sand; }", cylinder);
  c.write("system/particleMeshDict", threeD);
  const Scene s = readScene(c.path());
  EXPECT_EQ(s.regions[0].shape->type(), "cylinder");
  EXPECT_EQ(s.regions[0].shape->dimension(), 3);
  EXPECT_NEAR(s.regions[0].shape->measure(), M_PI * 0.01 * 0.2, 1e-15);

  const auto errorAt = [&](const std::string& dict, const std::string& keyword, const std::string& says) {
    const FatalError e = sceneError(c, dict);
    EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    expectAt(e, "particleMeshDict", lineOf(dict, keyword));
  };
  errorAt(replaced(square, "type box; min (0 0 0); max (0.5 0.24 0); material sand; }", cylinder), "type cylinder",
          "needs dimension 3");
  errorAt(replaced(threeD, "height 0.2;", "height 0.2; zRange (0 0.1);"), "zRange", "bounded in z already");
  errorAt(replaced(threeD, "radius 0.1;", "radius 0;"), "radius 0", "must be positive");
  errorAt(replaced(threeD, "height 0.2;", "height -1;"), "height -1", "must be positive");
}

const std::string profileDict = R"(spacing 0.1;
regions
{
    slide
    {
        type      profile;
        upperFile "constant/ground.csv";
        lower     ((0 0 0) (10 5 0));
        material  sand;
    }
}
)";

TEST_F(SceneReader, ProfileFromACsvFile) {
  c.write("system/particleMeshDict", profileDict);
  c.write("constant/ground.csv", "# ground surface\nx,y,note\n0,0,toe\n2,3,\n10,5,crest\n");
  const Scene s = readScene(c.path());
  EXPECT_NEAR(s.regions[0].shape->measure(), 10.0, 1e-12);  // the triangle (0 0) (2 3) (10 5)
}

TEST_F(SceneReader, MissingCsvFileNamesItAndTheKeyword) {
  const FatalError e = sceneError(c, profileDict);
  EXPECT_NE(std::string(e.what()).find("ground.csv"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("no such file"), std::string::npos) << e.what();
  expectAt(e, "particleMeshDict", lineOf(profileDict, "upperFile"));
}

TEST_F(SceneReader, BadCsvLineNamesTheCsvFileAndLine) {
  c.write("constant/ground.csv", "x,y\n0,0\n2,3\n4;4\n10,5\n");
  FatalError e = sceneError(c, profileDict);
  expectAt(e, "ground.csv", 4);
  c.write("constant/ground.csv", "x,y\n0,0\n2,abc\n10,5\n");
  e = sceneError(c, profileDict);
  EXPECT_NE(std::string(e.what()).find("abc"), std::string::npos) << e.what();
  expectAt(e, "ground.csv", 3);
  // A point out of order: the error names the CSV line of that point.
  c.write("constant/ground.csv", "x,y\n0,0\n2,3\n1,4\n10,5\n");
  e = sceneError(c, profileDict);
  EXPECT_NE(std::string(e.what()).find("strictly"), std::string::npos) << e.what();
  expectAt(e, "ground.csv", 4);
}

TEST_F(SceneReader, CrossingProfiles) {
  c.write("constant/ground.csv", "x,y\n0,1\n10,-1\n");
  const FatalError e = sceneError(c, profileDict);
  EXPECT_NE(std::string(e.what()).find("profiles cross"), std::string::npos) << e.what();
  expectAt(e, "particleMeshDict", lineOf(profileDict, "upperFile"));
}

}  // namespace
}  // namespace isph
