// The projection chosen by name from `incrementalPressure` and the scene (stages/Projection.hpp):
// plain by default and where the incremental projection does not act (`granular` in a scene
// without a granular material, or with the explicit deviatoric term), incremental where it
// does; each reads its own entries (pressureGradient, laggedPressure) and says what it is in
// its log lines. Settings that would be ignored are an error at the line of the entry,
// saying what it needs; the settings that go together are accepted.
#include "isph/stages/Projection.hpp"

#include <gtest/gtest.h>

#include "StageSetupForTest.hpp"
#include "core/Error.hpp"

namespace isph {
namespace {

using test::StageSetupForTest;

std::unique_ptr<Projection> projectionFor(const std::string& text, const std::string& material) {
  const StageSetupForTest s(text, material);
  const auto deviatoric = DeviatoricTerm::New(s.setup());
  return Projection::New(s.setup(), *deviatoric);
}

bool says(const Projection& p, const std::string& what) { return p.describe().find(what) != std::string::npos; }

TEST(Projection, PlainWithTheRenormalisedGradientByDefault) {
  const auto p = projectionFor("", "sand");
  EXPECT_TRUE(says(*p, "projection: plain")) << p->describe();
  EXPECT_TRUE(says(*p, "renormalised")) << p->describe();
  EXPECT_TRUE(p->lagged().empty());
  EXPECT_TRUE(says(*projectionFor("pressureGradient symmetric;\n", "sand"), "as the paper"));
}

TEST(Projection, IncrementalWhereItActsWithThePairFormByDefault) {
  const auto sand = projectionFor("incrementalPressure granular;\n", "sand");
  EXPECT_TRUE(says(*sand, "projection: incremental")) << sand->describe();
  EXPECT_TRUE(says(*sand, "symmetric pair form")) << sand->describe();
  EXPECT_TRUE(says(*projectionFor("incrementalPressure granular;\n", "water"), "projection: plain"))
      << "granular: not in a scene without a granular material";
  EXPECT_TRUE(says(*projectionFor("incrementalPressure all;\n", "water"), "projection: incremental"));
  EXPECT_TRUE(says(*projectionFor("incrementalPressure all;\n", "air"), "projection: plain"))
      << "no deviatoric term to solve implicitly";
  const auto gradient = projectionFor("incrementalPressure granular;\nlaggedPressure { form gradient; smoothing 3; }\n",
                                      "sand");
  EXPECT_TRUE(says(*gradient, "renormalised gradient of Eq. 11 of p^n after 3 Shepard passes")) << gradient->describe();
}

// An error at the line of the entry that would be ignored, saying what it needs.
void expectConflict(const std::string& text, const std::string& material, const std::string& key, int line,
                    const std::string& needs) {
  try {
    projectionFor(text, material);
    FAIL() << "expected a FatalError for\n" << text;
  } catch (const FatalError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("keyword '" + key + "'"), std::string::npos) << m;
    EXPECT_NE(m.find(needs), std::string::npos) << m;
    EXPECT_EQ(e.where().line, line) << m;
  }
}

TEST(Projection, SettingsThatWouldBeIgnoredAreAnErrorAtTheirLine) {
  expectConflict("viscousTerm explicit;\nincrementalPressure granular;\n", "sand", "incrementalPressure", 2,
                 "viscousTerm implicit");
  expectConflict("kernel WendlandC2;\nlaggedPressure { form gradient; }\n", "sand", "laggedPressure", 2,
                 "incrementalPressure granular or all");
  expectConflict("incrementalPressure all;\n\npressureGradient symmetric;\n", "sand", "pressureGradient", 3,
                 "renormalised gradient of the increment");
  expectConflict("incrementalPressure granular;\nwallFriction\n{\n    normalForce hydrostatic;\n}\n", "sand",
                 "normalForce", 4, "laggedPressure { form gradient; }");
  expectConflict("incrementalPressure granular;\nlaggedPressure\n{\n    smoothing 2;\n}\n", "sand", "smoothing", 4,
                 "form gradient");
  expectConflict("incrementalPressure granular;\nlaggedPressure { form gradient; smoothing 11; }\n", "sand",
                 "smoothing", 2, "[0, 10]");
  EXPECT_THROW(projectionFor("incrementalPressure granular;\nlaggedPressure { form divergence; }\n", "sand"),
               FatalError);
}

TEST(Projection, SettingsThatGoTogetherAreAccepted) {
  EXPECT_TRUE(says(*projectionFor("incrementalPressure granular;\npressureGradient symmetric;\n", "water"),
                   "as the paper"))
      << "the incremental projection does not act on water: the symmetric form is used";
  EXPECT_NO_THROW(projectionFor("incrementalPressure granular;\nlaggedPressure { form gradient; }\n"
                                "wallFriction { normalForce hydrostatic; }\n",
                                "sand"));
  EXPECT_NO_THROW(projectionFor("viscousTerm explicit;\npressureGradient symmetric;\n", "sand"));
}

}  // namespace
}  // namespace isph
