// The predictor's deviatoric term chosen by name (stages/DeviatoricTerm.hpp): `viscousTerm`
// implicit (the default) or explicit where a material has a deviatoric stress, the explicit sum
// (gravity alone) where none has; each says what it is in its log line; an unknown name is an
// error at its line with the choices.
#include "isph/stages/DeviatoricTerm.hpp"

#include <gtest/gtest.h>

#include "StageSetupForTest.hpp"
#include "core/Error.hpp"

namespace isph {
namespace {

using test::StageSetupForTest;

TEST(DeviatoricTerm, SemiImplicitByDefaultWithItsFrictionPasses) {
  const StageSetupForTest s("wallFriction { passes 3; }\n", "sand");
  const auto term = DeviatoricTerm::New(s.setup());
  EXPECT_TRUE(term->isImplicit());
  EXPECT_NE(term->describe().find("semi-implicit"), std::string::npos) << term->describe();
  EXPECT_NE(term->describe().find("repeated up to 3 times"), std::string::npos) << term->describe();
}

TEST(DeviatoricTerm, ExplicitWhenAskedForWithTheViscousLimit) {
  const StageSetupForTest s("viscousTerm explicit;\n", "sand");
  const auto term = DeviatoricTerm::New(s.setup());
  EXPECT_FALSE(term->isImplicit());
  EXPECT_NE(term->describe().find("viscous time-step limit"), std::string::npos) << term->describe();
}

TEST(DeviatoricTerm, GravityAloneWhereNoMaterialHasADeviatoricStress) {
  const StageSetupForTest s("viscousTerm implicit;\n", "air");
  const auto term = DeviatoricTerm::New(s.setup());
  EXPECT_FALSE(term->isImplicit()) << "nothing to solve for";
  EXPECT_NE(term->describe().find("gravity alone"), std::string::npos) << term->describe();
  EXPECT_TRUE(DeviatoricTerm::New(StageSetupForTest("", "water").setup())->isImplicit()) << "water has a viscosity";
}

TEST(DeviatoricTerm, AnUnknownTermIsAnErrorAtItsLineWithTheChoices) {
  try {
    DeviatoricTerm::New(StageSetupForTest("kernel WendlandC2;\nviscousTerm implict;\n", "sand").setup());
    FAIL() << "expected a FatalError";
  } catch (const FatalError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("viscousTerm"), std::string::npos) << m;
    EXPECT_NE(m.find("implicit"), std::string::npos) << "lists the choices\n" << m;
    EXPECT_EQ(e.where().line, 2);
  }
}

}  // namespace
}  // namespace isph
