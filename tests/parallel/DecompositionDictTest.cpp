// system/decomposeParDict: the entries, their defaults and the errors a user meets.
#include <gtest/gtest.h>

#include "core/Error.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "parallel/DecompositionDict.hpp"

namespace {

using namespace isph;

DecompositionSettings parse(const std::string& text) {
  return DecompositionSettings::read(Dictionary::parse(text, "system/decomposeParDict"));
}

TEST(DecompositionDict, ReadsTheSubdomainsAndZoltansAlgorithm) {
  const auto s = parse("numberOfSubdomains 3; method zoltan; zoltanCoeffs { algorithm HSFC; }");
  EXPECT_EQ(s.numberOfSubdomains, 3);
  EXPECT_EQ(s.algorithm, "HSFC");
  EXPECT_DOUBLE_EQ(s.repartitionFactor, 1.1);
}

TEST(DecompositionDict, DefaultsToRcbAndReadsTheRepartitionFactor) {
  const auto s = parse("numberOfSubdomains 2; method zoltan; repartitionFactor 1.25;");
  EXPECT_EQ(s.algorithm, "RCB");
  EXPECT_DOUBLE_EQ(s.repartitionFactor, 1.25);
}

TEST(DecompositionDict, BadEntriesAreErrorsAtTheirLine) {
  auto message = [](const std::string& text) {
    try {
      parse(text);
    } catch (const FatalError& e) {
      return e.report();
    }
    return std::string("no error");
  };
  EXPECT_NE(message("numberOfSubdomains 2;\nmethod scotch;").find("line 2"), std::string::npos);
  EXPECT_NE(message("numberOfSubdomains 2;\nmethod scotch;").find("zoltan"), std::string::npos);
  EXPECT_NE(message("numberOfSubdomains 0; method zoltan;").find("at least 1"), std::string::npos);
  EXPECT_NE(message("numberOfSubdomains 2; method zoltan;\nzoltanCoeffs { algorithm PHG; }").find("RCB"),
            std::string::npos);
  EXPECT_NE(message("numberOfSubdomains 2; method zoltan; repartitionFactor 0.9;").find("at least 1"),
            std::string::npos);
  EXPECT_NE(message("method zoltan;").find("numberOfSubdomains"), std::string::npos);
}

}  // namespace
