// system/isphSchemes as the solver reads it: the bed-drag passes of wallFriction (default,
// given, out of range with the keyword's line); the method (isph, or the weakly-compressible
// baseline with its sub-dictionary and its explicit viscous term).
#include <gtest/gtest.h>

#include <string>

#include "core/Error.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "isph/IsphSchemes.hpp"

namespace isph {
namespace {

IsphSchemes schemesFrom(const std::string& text) {
  return IsphSchemes::read(Dictionary::parse(text, "isphSchemes"), 2);
}

TEST(IsphSchemes, WallFrictionPassesDefaultToTen) { EXPECT_EQ(schemesFrom("").frictionPasses, 10); }

TEST(IsphSchemes, WallFrictionPassesAreRead) {
  const IsphSchemes s = schemesFrom("wallFriction { passes 2; }\n");
  EXPECT_EQ(s.frictionPasses, 2);
}

TEST(IsphSchemes, ZeroWallFrictionPassesAreAnErrorAtTheirLine) {
  try {
    schemesFrom("kernel WendlandC2;\nwallFriction\n{\n    passes 0;\n}\n");
    FAIL() << "expected a FatalError";
  } catch (const FatalError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("keyword 'passes'"), std::string::npos) << m;
    EXPECT_NE(m.find("[1, 20]"), std::string::npos) << m;
    EXPECT_EQ(e.where().line, 4) << "the line of the keyword";
  }
}

TEST(IsphSchemes, MethodDefaultsToTheProjection) {
  const IsphSchemes s = schemesFrom("");
  EXPECT_EQ(s.method, Method::isph);
  EXPECT_NE(s.describe().find("incompressible SPH, projection"), std::string::npos) << s.describe();
}

TEST(IsphSchemes, WeaklyCompressibleMethodIsExplicitWithItsDefaults) {
  const IsphSchemes s = schemesFrom("method wcsph;\n");
  EXPECT_EQ(s.method, Method::wcsph);
  EXPECT_NE(s.describe().find("deviatoric term (where a material has one): explicit"), std::string::npos)
      << s.describe();
  EXPECT_EQ(s.wcsph.soundSpeed, 0.0) << "0: from the scene";
  EXPECT_EQ(s.wcsph.densityDiffusion, 0.1);
  EXPECT_EQ(s.wcsph.artificialViscosity, 0.1);
  EXPECT_NE(s.describe().find("weakly-compressible SPH"), std::string::npos) << s.describe();
}

TEST(IsphSchemes, WeaklyCompressibleEntriesAreRead) {
  const IsphSchemes s =
      schemesFrom("method wcsph;\nwcsph { soundSpeed 25; densityDiffusion 0; artificialViscosity 0.02; }\n");
  EXPECT_EQ(s.wcsph.soundSpeed, 25.0);
  EXPECT_EQ(s.wcsph.densityDiffusion, 0.0);
  EXPECT_EQ(s.wcsph.artificialViscosity, 0.02);
  EXPECT_NE(s.describe().find("sound speed 25 m/s"), std::string::npos) << s.describe();
  EXPECT_NE(s.describe().find("density diffusion off"), std::string::npos) << s.describe();
}

TEST(IsphSchemes, ImplicitViscousTermWithWeaklyCompressibleIsAnErrorAtItsLine) {
  try {
    schemesFrom("method wcsph;\n\nviscousTerm implicit;\n");
    FAIL() << "expected a FatalError";
  } catch (const FatalError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("'viscousTerm'"), std::string::npos) << m;
    EXPECT_NE(m.find("method isph"), std::string::npos) << m;
    EXPECT_EQ(e.where().line, 3);
  }
}

TEST(IsphSchemes, NegativeSoundSpeedIsAnError) {
  EXPECT_THROW(schemesFrom("method wcsph;\nwcsph { soundSpeed -1; }\n"), FatalError);
}

TEST(IsphSchemes, UnknownMethodIsAnError) {
  EXPECT_THROW(schemesFrom("method sph;\n"), FatalError);
}

TEST(IsphSchemes, ShiftingNearTheSurfaceIsOffUnlessPairsAreAskedFor) {
  EXPECT_FALSE(schemesFrom("").shifting.pairsNearSurface);
  EXPECT_NE(schemesFrom("").describe().find("none next to it"), std::string::npos) << schemesFrom("").describe();
  const IsphSchemes s = schemesFrom("shifting { nearSurface pairs; }\n");
  EXPECT_TRUE(s.shifting.pairsNearSurface);
  EXPECT_NE(s.describe().find("the pair term alone next to it"), std::string::npos) << s.describe();
}

TEST(IsphSchemes, UnknownNearSurfaceShiftingIsAnErrorAtItsLine) {
  try {
    schemesFrom("shifting\n{\n    nearSurface all;\n}\n");
    FAIL() << "expected a FatalError";
  } catch (const FatalError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("nearSurface"), std::string::npos) << m;
    EXPECT_NE(m.find("pairs"), std::string::npos) << "lists the valid choices\n" << m;
    EXPECT_EQ(e.where().line, 3);
  }
}

TEST(IsphSchemes, TheWeaklyCompressibleMethodLeavesTheProjectionsEntriesUnread) {
  const int warnings = warningCount();
  const IsphSchemes s = schemesFrom("method wcsph;\nsource { type divergence; alpha 7; }\nlaplacian { eta 9; }\n");
  EXPECT_EQ(warningCount() - warnings, 2) << "one warning for each of the projection's entries, no range error";
  EXPECT_EQ(s.ppe.source, PpeSource::densityInvariant);
  EXPECT_EQ(s.describe().find("PPE"), std::string::npos) << s.describe();
}

}  // namespace
}  // namespace isph
