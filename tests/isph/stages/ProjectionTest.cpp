// The projection (stages/Projection.hpp): the plain projection in every scene, Eq. 11 in its
// renormalised difference form; the keywords of the variants removed with issue 48
// (incrementalPressure, laggedPressure, pressureGradient) are an error at their line, naming
// the keyword and saying that it was removed, so that an old case does not run something
// other than what it says.
#include "isph/stages/Projection.hpp"

#include <gtest/gtest.h>

#include "StageSetupForTest.hpp"
#include "core/Error.hpp"

namespace isph {
namespace {

using test::StageSetupForTest;

std::unique_ptr<Projection> projectionFor(const std::string& text, const std::string& material) {
  const StageSetupForTest s(text, material);
  return Projection::New(s.setup());
}

bool says(const Projection& p, const std::string& what) { return p.describe().find(what) != std::string::npos; }

TEST(Projection, PlainWithTheRenormalisedGradientInEveryScene) {
  for (const char* material : {"sand", "water", "air"}) {
    const auto p = projectionFor("", material);
    EXPECT_TRUE(says(*p, "projection: plain")) << material << ": " << p->describe();
    EXPECT_TRUE(says(*p, "renormalised")) << material << ": " << p->describe();
  }
  EXPECT_TRUE(says(*projectionFor("viscousTerm explicit;\n", "sand"), "projection: plain"));
}

TEST(Projection, TheRemovedVariantsAreAnErrorAtTheirLine) {
  const struct {
    std::string text, key;
    int line;
  } cases[] = {{"kernel WendlandC2;\nincrementalPressure granular;\n", "incrementalPressure", 2},
               {"laggedPressure\n{\n    form gradient;\n}\n", "laggedPressure", 1},
               {"kernel WendlandC2;\n\npressureGradient symmetric;\n", "pressureGradient", 3},
               {"pressureGradient renormalised;\n", "pressureGradient", 1}};
  for (const auto& c : cases) {
    try {
      projectionFor(c.text, "sand");
      FAIL() << "expected a FatalError for\n" << c.text;
    } catch (const FatalError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("keyword '" + c.key + "'"), std::string::npos) << m;
      EXPECT_NE(m.find("was removed"), std::string::npos) << m;
      EXPECT_NE(m.find("remove the line"), std::string::npos) << m;
      EXPECT_EQ(e.where().line, c.line) << m;
    }
  }
}

}  // namespace
}  // namespace isph
