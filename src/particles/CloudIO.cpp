#include "particles/CloudIO.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "core/io/AtomicFile.hpp"
#include "core/io/FoamFileHeader.hpp"

namespace isph {

namespace {

constexpr const char* propertiesFile = "cloudProperties";

std::string propertiesText(const CloudProperties& props, const std::string& location) {
  Dictionary d("cloudProperties");
  d.set("dimension", props.dimension);
  d.set("spacing", props.spacing);
  d.set("lattice", props.lattice);
  d.set("materials", props.materials);
  Dictionary& patches = d.subDictOrAdd("patches");
  for (std::size_t i = 0; i < props.patches.size(); ++i) {
    Dictionary& p = patches.subDictOrAdd(props.patches[i].name);
    p.set("index", static_cast<int>(i));
    p.set("frictionAngle", props.patches[i].frictionAngle);
  }
  return foamFileHeader("dictionary", propertiesFile, location, false) + "\n" + d.write() + "\n" +
         foamFileFooter();
}

CloudProperties readProperties(const std::filesystem::path& file) {
  const Dictionary d = Dictionary::readFile(file);
  CloudProperties props;
  props.dimension = d.get<int>("dimension");
  props.spacing = d.get<double>("spacing");
  props.lattice = d.getChoice("lattice", {"square", "hexagonal"});
  props.materials = d.get<std::vector<std::string>>("materials");
  const Dictionary& patches = d.subDict("patches");
  props.patches.resize(patches.size());
  for (const auto& e : patches.entries()) {
    if (!e.isDict()) fatalIOError(e.location(), fmt::format("patch '{}' must be a sub-dictionary", e.key()));
    const int index = e.dict().get<int>("index");
    if (index < 0 || static_cast<std::size_t>(index) >= props.patches.size()) {
      fatalIOError(e.location(), fmt::format("patch '{}': index {} is out of range 0..{}", e.key(), index,
                                             props.patches.size() - 1));
    }
    props.patches[static_cast<std::size_t>(index)] = {e.key(), e.dict().get<double>("frictionAngle")};
  }
  return props;
}

}  // namespace

void writeCloud(const std::filesystem::path& timeDir, const std::string& timeName, const ParticleCloud& cloud,
                const FieldWriteOptions& options) {
  cloud.checkSizes("writeCloud");
  const std::filesystem::path dir = timeDir / "lagrangian" / cloud.name;
  std::filesystem::create_directories(dir);
  FieldWriteOptions o = options;
  o.location = fmt::format("{}/lagrangian/{}", timeName, cloud.name);
  writeField(dir / "positions", cloud.positions, o);
  writeField(dir / "origId", cloud.origId, o);
  writeField(dir / "U", cloud.U, o);
  writeField(dir / "p", cloud.p, o);
  writeField(dir / "material", cloud.material, o);
  writeField(dir / "kind", cloud.kind, o);
  writeField(dir / "patch", cloud.patch, o);
  writeField(dir / "normal", cloud.normal, o);
  writeField(dir / "mass", cloud.mass, o);
  writeFileAtomic(dir / propertiesFile, propertiesText(cloud.properties, o.location));
}

CloudProperties readCloudProperties(const std::filesystem::path& timeDir, const std::string& name) {
  return readProperties(timeDir / "lagrangian" / name / propertiesFile);
}

ParticleCloud readCloud(const std::filesystem::path& timeDir, const std::string& name) {
  const std::filesystem::path dir = timeDir / "lagrangian" / name;
  if (!std::filesystem::is_directory(dir)) {
    fatalError(fmt::format("cloud '{}' not found: no folder {}\n    (run particleMesh first, or check `cloud` "
                           "in system/particleMeshDict)",
                           name, dir.string()));
  }
  ParticleCloud cloud;
  cloud.name = name;
  cloud.properties = readProperties(dir / propertiesFile);
  cloud.positions = readField<Vec3>(dir / "positions");
  const std::size_t n = cloud.positions.size();
  cloud.origId = readField<label>(dir / "origId", n);
  cloud.U = readField<Vec3>(dir / "U", n);
  cloud.p = readField<scalar>(dir / "p", n);
  cloud.material = readField<label>(dir / "material", n);
  cloud.kind = readField<label>(dir / "kind", n);
  cloud.patch = readField<label>(dir / "patch", n);
  cloud.normal = readField<Vec3>(dir / "normal", n);
  cloud.mass = readField<scalar>(dir / "mass", n);
  const auto nMaterials = static_cast<label>(cloud.properties.materials.size());
  const auto nPatches = static_cast<label>(cloud.properties.patches.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (cloud.kind[i] < 0 || cloud.kind[i] > 2 || cloud.material[i] >= nMaterials || cloud.patch[i] >= nPatches ||
        (cloud.kind[i] == static_cast<label>(ParticleKind::material) && cloud.material[i] < 0)) {
      fatalError(fmt::format("{}: particle {} has kind {}, material {}, patch {}; expected kind 0..2, a material "
                             "below {} (material particles) and a patch below {}",
                             dir.string(), i, cloud.kind[i], cloud.material[i], cloud.patch[i], nMaterials,
                             nPatches));
    }
  }
  return cloud;
}

}  // namespace isph
