// The material table's traits of a scene: "granular" is a trait of the soil models
// (rigidPlastic, elasticPlastic), not of the fluids (newtonian, inviscid), whatever their wall
// contact; the schemes for granular materials (`compressed granular`) act on a scene with at
// least one.
#include "isph/materials/MaterialTable.hpp"

#include <gtest/gtest.h>

#include "../MaterialTableForTest.hpp"

namespace {

using isph::test::materialTable;

const std::string materials = "water { model newtonian; rho 1000; nu 1e-6; } air { model inviscid; rho 1; } "
                              "sand { model rigidPlastic; rho 2650; phi 19.8; } "
                              "rods { model elasticPlastic; rho 2650; phi 19.8; cohesion 0; E 0.84e6; nu 0.3; }";

TEST(MaterialTable, TheSoilModelsAreGranularTheFluidsNot) {
  const auto table = materialTable("granularTrait", materials, {"water", "air", "sand", "rods"});
  EXPECT_FALSE((*table)[0].granular());
  EXPECT_FALSE((*table)[1].granular());
  EXPECT_TRUE((*table)[2].granular());
  EXPECT_TRUE((*table)[3].granular());
}

TEST(MaterialTable, AScenesGranularTraitIsThatOfAnyOfItsMaterials) {
  EXPECT_FALSE(materialTable("fluids", materials, {"water", "air"})->anyGranular());
  EXPECT_TRUE(materialTable("fluidAndSand", materials, {"water", "sand"})->anyGranular());
  EXPECT_TRUE(materialTable("rods", materials, {"rods"})->anyGranular());
}

}  // namespace
