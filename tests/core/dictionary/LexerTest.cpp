#include "core/dictionary/Lexer.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace isph {
namespace {

std::vector<Token> lexAll(std::string_view text) {
  Lexer lexer(text, std::make_shared<const std::string>("test"));
  std::vector<Token> tokens;
  while (auto t = lexer.next()) tokens.push_back(*t);
  return tokens;
}

TEST(Lexer, WordsNumbersPunctuationAndLocations) {
  const auto t = lexAll("endTime 2.5;\n  deltaT\t1e-4 ;\nn -3;");
  ASSERT_EQ(t.size(), 9u);
  EXPECT_TRUE(t[0].isWord());
  EXPECT_EQ(t[0].text, "endTime");
  EXPECT_TRUE(t[1].isNumber());
  EXPECT_DOUBLE_EQ(t[1].number, 2.5);
  EXPECT_FALSE(t[1].isInteger);
  EXPECT_TRUE(t[2].isPunct(';'));
  EXPECT_EQ(t[3].loc.line, 2);
  EXPECT_EQ(t[3].loc.column, 3);
  EXPECT_DOUBLE_EQ(t[4].number, 1e-4);
  EXPECT_DOUBLE_EQ(t[7].number, -3);
  EXPECT_TRUE(t[7].isInteger);
}

TEST(Lexer, CommentsAreSkippedAndLinesCounted) {
  const auto t = lexAll("// line comment\n/* block\n comment */ a 1; // trailing\nb/*x*/2;");
  ASSERT_EQ(t.size(), 6u);
  EXPECT_EQ(t[0].text, "a");
  EXPECT_EQ(t[0].loc.line, 3);
  EXPECT_EQ(t[3].text, "b");
  EXPECT_EQ(t[3].loc.line, 4);
  EXPECT_DOUBLE_EQ(t[4].number, 2);
}

TEST(Lexer, StringsVariablesDirectivesAndSpecialWords) {
  const auto t = lexAll(R"(#include "a b.txt" $sub/name ${x.y} $:top.key List<scalar> "q\"uote")");
  ASSERT_EQ(t.size(), 7u);
  EXPECT_EQ(t[0].kind, TokenKind::Directive);
  EXPECT_EQ(t[0].text, "include");
  EXPECT_TRUE(t[1].isString());
  EXPECT_EQ(t[1].text, "a b.txt");
  EXPECT_EQ(t[2].kind, TokenKind::Variable);
  EXPECT_EQ(t[2].text, "sub/name");
  EXPECT_EQ(t[3].text, "x.y");
  EXPECT_EQ(t[4].text, ":top.key");
  EXPECT_TRUE(t[5].isWord());
  EXPECT_EQ(t[5].text, "List<scalar>");
  EXPECT_EQ(t[6].text, "q\"uote");
}

TEST(Lexer, SizedListsAndUniformLists) {
  const auto t = lexAll("3(1 2 3) 2{0.5}");
  ASSERT_EQ(t.size(), 10u);
  EXPECT_TRUE(t[0].isInteger);
  EXPECT_TRUE(t[1].isPunct('('));
  EXPECT_TRUE(t[7].isPunct('{'));
}

TEST(Lexer, ParseNumberAcceptsOnlyWholeNumbers) {
  double v = 0;
  bool integer = false;
  EXPECT_TRUE(parseNumber("+1.5e3", v, integer));
  EXPECT_DOUBLE_EQ(v, 1500);
  EXPECT_TRUE(parseNumber(".5", v, integer));
  EXPECT_FALSE(parseNumber("1.5abc", v, integer));
  EXPECT_FALSE(parseNumber("abc", v, integer));
  EXPECT_FALSE(parseNumber("inf", v, integer));
}

TEST(Lexer, UnterminatedCommentAndStringAreErrorsWithTheirLine) {
  try {
    lexAll("a 1;\n/* never closed");
    FAIL();
  } catch (const FatalError& e) {
    EXPECT_EQ(e.where().line, 2);
    EXPECT_NE(std::string(e.what()).find("*/"), std::string::npos);
  }
  try {
    lexAll("a \"open;\n");
    FAIL();
  } catch (const FatalError& e) {
    EXPECT_EQ(e.where().line, 1);
  }
}

}  // namespace
}  // namespace isph
