#pragma once
// A StageSetup from the text of system/isphSchemes and a scene of sand, water or air
// (tests of the projection step's stages, src/isph/stages/).
#include <memory>
#include <string>

#include "../MaterialTableForTest.hpp"
#include "isph/stages/StepContext.hpp"

namespace isph::test {

struct StageSetupForTest {
  StageSetupForTest(const std::string& schemesText, const std::string& material, int dimension = 2)
      : schemes(Dictionary::parse(schemesText, "isphSchemes")),
        solution("isphSolution"),
        common(IsphSchemes::read(schemes, dimension)),
        dimension(dimension),
        materials(materialTable("stages", "sand { model rigidPlastic; rho 2650; phi 30; } "
                                          "water { model newtonian; rho 1000; nu 1e-6; } air { model inviscid; rho 1; }",
                                {material})) {}

  StageSetup setup() const { return {schemes, solution, common, *materials, dimension}; }

  Dictionary schemes;
  Dictionary solution;
  IsphSchemes common;
  int dimension;
  std::unique_ptr<MaterialTable> materials;
};

}  // namespace isph::test
