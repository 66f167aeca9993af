#include "isph/materials/MaterialTable.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/Strings.hpp"

namespace isph {

MaterialTable::MaterialTable(const std::filesystem::path& file, const std::vector<std::string>& names) {
  const Dictionary dict = Dictionary::readFile(file);
  const Dictionary& materials = dict.subDict("materials");
  for (const auto& name : names) {
    if (!materials.isDict(name)) {
      fatalIOError(materials.location(),
                   fmt::format("material '{}' used by the particles is not defined in {}{}", name,
                               materials.name(), didYouMean(name, materials.keys())));
    }
    models_.push_back(makeMaterialModel(name, materials.subDict(name)));
  }
}

bool MaterialTable::anyDeviatoricStress() const {
  return std::any_of(models_.begin(), models_.end(), [](const auto& m) { return m->hasDeviatoricStress(); });
}

bool MaterialTable::anyGranular() const {
  return std::any_of(models_.begin(), models_.end(), [](const auto& m) { return m->granular(); });
}

double MaterialTable::maxViscosity() const {
  double v = 0;
  for (const auto& m : models_) v = std::max(v, m->maxViscosity());
  return v;
}

double MaterialTable::maxRho() const {
  double v = 0;
  for (const auto& m : models_) v = std::max(v, m->rho());
  return v;
}

}  // namespace isph
