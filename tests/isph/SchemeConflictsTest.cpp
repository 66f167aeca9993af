// The settings of system/isphSchemes that exclude each other (SchemeConflicts.hpp), read
// through IsphSchemes::read: each conflict is an error at the line of the entry that would be
// ignored, saying what it needs; the pairs that go together are accepted; method wcsph leaves
// the projection's entries unread with a warning each. (The scene-dependent check, the
// symmetric gradient where the incremental projection acts, is tested on a case:
// solvers/ParticleSolverTest.cpp.)
#include "isph/SchemeConflicts.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/Error.hpp"
#include "core/dictionary/Dictionary.hpp"

namespace isph {
namespace {

IsphSchemes schemesFrom(const std::string& text) {
  return IsphSchemes::read(Dictionary::parse(text, "isphSchemes"), 2);
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

TEST(SchemeConflicts, TheWeaklyCompressibleMethodLeavesTheProjectionsEntriesUnread) {
  const int warnings = warningCount();
  const IsphSchemes s = schemesFrom("method wcsph;\nsource { type divergence; alpha 7; }\nlaplacian { eta 9; }\n");
  EXPECT_EQ(warningCount() - warnings, 2) << "one warning for each of the projection's entries, no range error";
  EXPECT_EQ(s.ppe.source, PpeSource::densityInvariant);
  EXPECT_EQ(s.describe().find("PPE"), std::string::npos) << s.describe();
}

}  // namespace
}  // namespace isph
