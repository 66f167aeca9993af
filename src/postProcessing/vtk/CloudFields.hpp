#pragma once
// Every particle field of a cloud in a time directory, whatever its name and type: the
// cloud's own fields (CloudIO) plus any other field file the solver wrote beside them
// (freeSurface, tau, ...), recognised by its FoamFile class.
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/Types.hpp"
#include "particles/ParticleCloud.hpp"

namespace isph {

using FieldValues = std::variant<std::vector<scalar>, std::vector<label>, std::vector<Vec3>, std::vector<SymmTensor>>;

struct NamedField {
  std::string name;
  FieldValues values;
};

struct CloudFields {
  ParticleCloud cloud;            // positions, the standard fields and cloudProperties
  std::vector<NamedField> fields;  // the selected fields, in file-name order (positions aside)
  std::vector<std::string> available;  // every field name found (positions aside)

  const NamedField* find(const std::string& name) const;
};

// Reads cloud `cloudName` of `timeDir`. With `only`, keeps just the fields named there
// (a name the cloud does not hold is a warning naming the fields it does hold).
CloudFields readCloudFields(const std::filesystem::path& timeDir, const std::string& cloudName,
                            const std::optional<std::vector<std::string>>& only = {});

}  // namespace isph
