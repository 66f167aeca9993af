// system/isphSchemes as the solver reads it: the bed-drag passes of wallFriction (default,
// given, out of range with the keyword's line).
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

TEST(IsphSchemes, WallFrictionPassesDefaultToFour) {
  EXPECT_EQ(schemesFrom("").frictionPasses, 4);
  EXPECT_NE(schemesFrom("").describe().find("repeated up to 4 times"), std::string::npos);
}

TEST(IsphSchemes, WallFrictionPassesAreRead) {
  const IsphSchemes s = schemesFrom("wallFriction { passes 2; }\n");
  EXPECT_EQ(s.frictionPasses, 2);
  EXPECT_NE(s.describe().find("repeated up to 2 times"), std::string::npos) << s.describe();
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

}  // namespace
}  // namespace isph
