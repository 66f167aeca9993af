// The settings of system/isphSchemes that exclude each other (SchemeConflicts.hpp), checked
// as the solver checks them after IsphSchemes::read: each conflict is an error at the line of
// the entry that would be ignored, saying what it needs; the pairs that go together are
// accepted. (The scene-dependent check, the symmetric gradient where the incremental
// projection acts, is tested on a case: solvers/ParticleSolverTest.cpp.)
#include "isph/SchemeConflicts.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/Error.hpp"
#include "core/dictionary/Dictionary.hpp"

namespace isph {
namespace {

// The schemes of `text`, read and checked as the solver does.
IsphSchemes schemesFrom(const std::string& text) {
  const Dictionary dict = Dictionary::parse(text, "isphSchemes");
  const IsphSchemes schemes = IsphSchemes::read(dict, 2);
  checkSchemeConflicts(dict, schemes);
  return schemes;
}

// Settings that exclude each other: an error at the line of the entry that would be ignored,
// saying what it needs.
void expectConflict(const std::string& text, const std::string& key, int line, const std::string& needs) {
  try {
    schemesFrom(text);
    FAIL() << "expected a FatalError for\n" << text;
  } catch (const FatalError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("keyword '" + key + "'"), std::string::npos) << m;
    EXPECT_NE(m.find(needs), std::string::npos) << m;
    EXPECT_EQ(e.where().line, line) << m;
  }
}

TEST(SchemeConflicts, SettingsThatWouldBeIgnoredAreAnErrorAtTheirLine) {
  expectConflict("viscousTerm explicit;\nincrementalPressure granular;\n", "incrementalPressure", 2,
                 "viscousTerm implicit");
  expectConflict("kernel WendlandC2;\nlaggedPressure { form gradient; }\n", "laggedPressure", 2,
                 "incrementalPressure granular or all");
  expectConflict("incrementalPressure all;\n\npressureGradient symmetric;\n", "pressureGradient", 3,
                 "renormalised gradient of the increment");
  expectConflict("incrementalPressure granular;\nwallFriction\n{\n    normalForce hydrostatic;\n}\n", "normalForce", 4,
                 "laggedPressure { form gradient; }");
}

TEST(SchemeConflicts, SettingsThatGoTogetherAreAccepted) {
  EXPECT_NO_THROW(schemesFrom("incrementalPressure granular;\npressureGradient symmetric;\n"))
      << "granular: the solver decides with the scene's materials";
  EXPECT_NO_THROW(schemesFrom("incrementalPressure granular;\nlaggedPressure { form gradient; }\n"
                              "wallFriction { normalForce hydrostatic; }\n"));
  EXPECT_NO_THROW(schemesFrom("viscousTerm explicit;\npressureGradient symmetric;\n"));
}

}  // namespace
}  // namespace isph
