#include "parallel/DecompositionDict.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/dictionary/Dictionary.hpp"

namespace isph {

DecompositionSettings DecompositionSettings::read(const Dictionary& dict) {
  DecompositionSettings s;
  s.numberOfSubdomains = dict.get<int>("numberOfSubdomains");
  if (s.numberOfSubdomains < 1) {
    fatalIOError(dict.entry("numberOfSubdomains").location(),
                 fmt::format("numberOfSubdomains {} must be at least 1", s.numberOfSubdomains));
  }
  dict.getChoice("method", {"zoltan"});
  const Dictionary coeffs = dict.subDictOrEmpty("zoltanCoeffs");
  s.algorithm = coeffs.getChoiceOrDefault("algorithm", {"RCB", "HSFC"}, s.algorithm);
  coeffs.checkKeywords();
  s.repartitionFactor = dict.getOrDefault("repartitionFactor", s.repartitionFactor);
  if (!(s.repartitionFactor >= 1.0)) {
    fatalIOError(dict.entry("repartitionFactor").location(),
                 fmt::format("repartitionFactor {} must be at least 1 (the largest load over the mean load)",
                             s.repartitionFactor));
  }
  dict.checkKeywords();
  return s;
}

DecompositionSettings DecompositionSettings::read(const std::filesystem::path& caseDir) {
  const auto file = caseDir / "system" / "decomposeParDict";
  if (!std::filesystem::is_regular_file(file)) {
    fatalError(fmt::format("{} not found: it sets numberOfSubdomains and the method (zoltan) of the "
                           "decomposition\n    (see doc/parallel.md)",
                           file.string()));
  }
  return read(Dictionary::readFile(file));
}

}  // namespace isph
