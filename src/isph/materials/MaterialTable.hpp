#pragma once
// The materials of a cloud, in the order of its `material` labels, built from
// constant/materialProperties (`materials { sand { model ...; rho ...; } }`).
#include <filesystem>
#include <memory>
#include <vector>

#include "isph/materials/MaterialModel.hpp"

namespace isph {

class MaterialTable {
 public:
  // `names` are the cloud's material names (cloudProperties); each must be defined.
  MaterialTable(const std::filesystem::path& materialProperties, const std::vector<std::string>& names);

  std::size_t size() const { return models_.size(); }
  const MaterialModel& operator[](std::size_t i) const { return *models_[i]; }
  MaterialModel& operator[](std::size_t i) { return *models_[i]; }
  bool anyDeviatoricStress() const;
  bool anyGranular() const;  // MaterialModel::granular
  double maxViscosity() const;
  double maxRho() const;

 private:
  std::vector<std::unique_ptr<MaterialModel>> models_;
};

}  // namespace isph
