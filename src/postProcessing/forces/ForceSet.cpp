#include "postProcessing/forces/ForceSet.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/dictionary/Dictionary.hpp"

namespace isph {

ForceSet readForceSet(const std::string& name, const Dictionary& dict) {
  ForceSet set;
  set.name = name;
  set.where = dict.location();
  set.patchNames = dict.get<std::vector<std::string>>("patches");
  set.patchesWhere = dict.entry("patches").location();
  if (set.patchNames.empty()) {
    fatalIOError(set.patchesWhere, fmt::format("keyword 'patches' of set '{}': expected at least one patch name",
                                               name));
  }
  set.CofR = dict.getOrDefault<Vec3>("CofR", Vec3::Zero());
  set.width = dict.getOptional<double>("width");
  if (set.width && !(*set.width > 0)) {
    fatalIOError(dict.entry("width").location(),
                 fmt::format("keyword 'width' of set '{}' is {}; expected a positive width in metres", name,
                             *set.width));
  }
  set.facing = dict.getOptional<Vec3>("facing");
  if (set.facing && !(set.facing->norm() > 0)) {
    fatalIOError(dict.entry("facing").location(),
                 fmt::format("keyword 'facing' of set '{}' is the zero vector; expected a direction, the outward "
                             "normal of the faces to sum, e.g. (-1 0 0) for a barrier's upstream face",
                             name));
  }
  set.reference = dict.getOptional<std::string>("reference");
  if (const auto cols = dict.getOptional<std::vector<int>>("referenceColumns")) {
    if (cols->size() != 2 || (*cols)[0] < 1 || (*cols)[1] < 1) {
      fatalIOError(dict.entry("referenceColumns").location(),
                   fmt::format("keyword 'referenceColumns' of set '{}': expected two column numbers from 1, "
                               "(time force), e.g. (1 2)",
                               name));
    }
    set.referenceColumns = {(*cols)[0], (*cols)[1]};
  }
  for (auto [key, value] : {std::pair{"filterWindow", &set.filterWindow}, {"lateForceWindow", &set.lateForceWindow}}) {
    *value = dict.getOrDefault<double>(key, *value);
    if (!(*value > 0) || !std::isfinite(*value)) {
      fatalIOError(dict.entry(key).location(),
                   fmt::format("keyword '{}' of set '{}' is {}; expected a positive duration in seconds", key, name,
                               *value));
    }
  }
  dict.checkKeywords();
  return set;
}

std::vector<ForceSet> readForceSets(const Dictionary& dict, const std::vector<std::string>& topLevel) {
  std::vector<ForceSet> sets;
  std::vector<std::string> valid = topLevel;
  for (const auto& e : dict.entries()) {
    if (e.key() == "FoamFile" || !e.isDict()) continue;
    sets.push_back(readForceSet(e.key(), e.dict()));
    valid.push_back(e.key());
  }
  if (sets.empty()) {
    fatalIOError(dict.location(),
                 fmt::format("dictionary {} names no set; expected one or more sets such as\n    barrier {{ patches "
                             "(barrier); CofR (0 0 0); width 0.3; }}",
                             dict.name()));
  }
  dict.checkKeywords(valid);
  return sets;
}

std::vector<label> patchLabels(const ForceSet& set, const CloudProperties& props) {
  std::vector<label> labels;
  for (const auto& name : set.patchNames) {
    const auto it = std::find_if(props.patches.begin(), props.patches.end(),
                                 [&](const PatchInfo& p) { return p.name == name; });
    if (it == props.patches.end()) {
      std::vector<std::string> names;
      for (const auto& p : props.patches) names.push_back(p.name);
      fatalIOError(set.patchesWhere, fmt::format("set '{}': no patch '{}' in the cloud; expected one of ({})",
                                                 set.name, name, fmt::join(names, " ")));
    }
    labels.push_back(static_cast<label>(it - props.patches.begin()));
  }
  return labels;
}

}  // namespace isph
