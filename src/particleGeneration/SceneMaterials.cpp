#include "particleGeneration/SceneMaterials.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/Strings.hpp"

namespace isph {

SceneMaterials SceneMaterials::read(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) {
    fatalError(fmt::format(
        "cannot open {}: the material regions of system/particleMeshDict name materials, which "
        "this file defines:\n    materials {{ sand {{ model rigidPlastic; rho 1379; phi 44; }} }}",
        file.string()));
  }
  const Dictionary dict = Dictionary::readFile(file);
  SceneMaterials table;
  table.file_ = file.string();
  table.materials_ = dict.subDict("materials");
  for (const Entry& e : table.materials_.entries()) {
    if (!e.isDict()) {
      fatalIOError(e.location(),
                   fmt::format("entry '{}' in dictionary {}: expected a material sub-dictionary "
                               "{{ rho ...; }}",
                               e.key(), table.materials_.name()));
    }
    table.names_.push_back(e.key());
  }
  return table;
}

label SceneMaterials::index(const std::string& name, const SourceLocation& where) const {
  const auto it = std::find(names_.begin(), names_.end(), name);
  if (it == names_.end()) {
    fatalIOError(where, fmt::format("unknown material '{}': {} defines {}{}", name, file_,
                                    names_.empty() ? "no materials" : join(names_, ", "),
                                    didYouMean(name, names_)));
  }
  return static_cast<label>(it - names_.begin());
}

double SceneMaterials::density(label m) const {
  const Dictionary& d = materials_.subDict(names_.at(static_cast<std::size_t>(m)));
  const double rho = d.get<double>("rho");
  if (!(rho > 0)) {
    fatalIOError(
        d.findEntry("rho")->location(),
        fmt::format("keyword 'rho' in dictionary {}: the density must be positive, found {}",
                    d.name(), rho));
  }
  return rho;
}

}  // namespace isph
