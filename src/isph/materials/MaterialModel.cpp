#include "isph/materials/MaterialModel.hpp"

#include <fmt/format.h>

#include "core/Plausibility.hpp"

namespace isph {

MaterialModel::MaterialModel(std::string name, const Dictionary& dict)
    : name_(std::move(name)), rho_(dict.get<double>("rho")) {
  if (!(rho_ > 0)) {
    fatalIOError(dict.findEntry("rho")->location(),
                 fmt::format("material '{}': rho must be positive (kg/m^3), got {}", name_, rho_));
  }
  warnIfImplausibleDensity(rho_, fmt::format("material '{}': rho", name_), dict.findEntry("rho")->location());
}

std::unique_ptr<MaterialModel> makeMaterialModel(const std::string& name, const Dictionary& dict) {
  const std::string model = dict.get<std::string>("model");
  return MaterialRegistry::create(model, "material model", dict.findEntry("model")->location(), name, dict);
}

}  // namespace isph
