#pragma once
// The materials of constant/materialProperties, as the particle generator needs them:
//   materials { sand { model rigidPlastic; rho 1379; phi 44; } }
// Names in file order (the `material` labels of the cloud index them) and the density `rho`
// of those the scene uses. Model keywords belong to the solver and are not checked here.
#include <filesystem>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "core/Types.hpp"
#include "core/dictionary/Dictionary.hpp"

namespace isph {

class SceneMaterials {
 public:
  SceneMaterials() = default;
  // FatalError when the file is missing or has no `materials` dictionary.
  static SceneMaterials read(const std::filesystem::path& file);

  const std::vector<std::string>& names() const { return names_; }
  // The label of `name`; a FatalIOError at `where` (the keyword naming it) when unknown.
  label index(const std::string& name, const SourceLocation& where) const;
  // `rho` of material `m` [kg/m³]; FatalIOError when missing or not positive.
  double density(label m) const;

 private:
  Dictionary materials_;
  std::string file_;
  std::vector<std::string> names_;
};

}  // namespace isph
