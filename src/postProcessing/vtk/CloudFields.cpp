#include "postProcessing/vtk/CloudFields.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "core/Error.hpp"
#include "core/fields/FieldHeader.hpp"
#include "core/fields/FieldIO.hpp"
#include "core/io/ReadFile.hpp"
#include "particles/CloudIO.hpp"

namespace isph {

namespace {

bool wanted(const std::optional<std::vector<std::string>>& only, const std::string& name) {
  return !only || std::find(only->begin(), only->end(), name) != only->end();
}

// The FoamFile class of a file (from its first block).
std::string fileClass(const std::filesystem::path& file) {
  return parseFieldHeader(readFileBytes(file, 64 * 1024), file.string()).className;
}

bool isFieldClass(const std::string& className) {
  return className == fieldClassName<scalar>() || className == fieldClassName<label>() ||
         className == fieldClassName<Vec3>() || className == fieldClassName<SymmTensor>();
}

// A field file that is not one of the cloud's own fields, read by its class.
FieldValues readOther(const std::filesystem::path& file, const std::string& className, std::size_t n) {
  if (className == fieldClassName<scalar>()) return readField<scalar>(file, n);
  if (className == fieldClassName<label>()) return readField<label>(file, n);
  if (className == fieldClassName<Vec3>()) return readField<Vec3>(file, n);
  return readField<SymmTensor>(file, n);
}

}  // namespace

const NamedField* CloudFields::find(const std::string& name) const {
  for (const auto& f : fields) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

CloudFields readCloudFields(const std::filesystem::path& timeDir, const std::string& cloudName,
                            const std::optional<std::vector<std::string>>& only) {
  CloudFields out;
  out.cloud = readCloud(timeDir, cloudName);
  const ParticleCloud& c = out.cloud;
  const std::size_t n = c.size();
  const std::filesystem::path dir = timeDir / "lagrangian" / cloudName;
  for (const std::string& name : listFields(dir)) {
    if (name == "positions") continue;
    FieldValues values;
    if (name == "origId") values = c.origId;
    else if (name == "U") values = c.U;
    else if (name == "p") values = c.p;
    else if (name == "material") values = c.material;
    else if (name == "kind") values = c.kind;
    else if (name == "patch") values = c.patch;
    else if (name == "normal") values = c.normal;
    else if (name == "mass") values = c.mass;
    else {
      const std::string className = fileClass(dir / name);
      if (!isFieldClass(className)) continue;  // cloudProperties, or another dictionary
      if (!wanted(only, name)) {
        out.available.push_back(name);
        continue;
      }
      values = readOther(dir / name, className, n);
    }
    out.available.push_back(name);
    if (wanted(only, name)) out.fields.push_back({name, std::move(values)});
  }
  if (only) {
    for (const auto& name : *only) {
      if (name != "positions" && std::find(out.available.begin(), out.available.end(), name) == out.available.end()) {
        warning(fmt::format("field '{}' (option -fields) is not in {}; the cloud holds ({})", name, dir.string(),
                            fmt::join(out.available, " ")));
      }
    }
  }
  return out;
}

}  // namespace isph
