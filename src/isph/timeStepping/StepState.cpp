#include "isph/timeStepping/StepState.hpp"

#include <fmt/format.h>

#include "core/dictionary/Dictionary.hpp"
#include "core/io/AtomicFile.hpp"
#include "core/io/FoamFileHeader.hpp"

namespace isph {

namespace fs = std::filesystem;

namespace {

const char* const stateFile = "isphState";

template <class T>
void writeArray(const fs::path& uniform, const char* name, const std::vector<T>& values,
                WriteFormat format) {
  if (values.empty()) return;
  writeField(uniform / name, values, {format, 17, "uniform"});
}

template <class T>
std::vector<T> readArray(const fs::path& uniform, const char* name) {
  const fs::path file = uniform / name;
  return fs::exists(file) ? readField<T>(file) : std::vector<T>{};
}

}  // namespace

void writeStepState(const fs::path& timeDir, const StepState& s, WriteFormat format) {
  const fs::path uniform = timeDir / "uniform";
  std::error_code ec;
  fs::create_directories(uniform, ec);
  if (ec) fatalError(fmt::format("cannot create {}: {}", uniform.string(), ec.message()));
  Dictionary d(stateFile);
  d.set("stepsTaken", s.stepsTaken);
  d.set("stepsSinceReorder", s.stepsSinceReorder);
  d.set("freshStart", s.freshStart);
  d.set("viscosityKnown", s.viscosityKnown);
  d.set("maxNu", s.maxNu);
  d.set("maxViscousAcceleration", s.maxViscousAcceleration);
  d.set("maxAcceleration", s.maxAcceleration);
  d.set("soundSpeed", s.soundSpeed);
  d.set("domainMin", s.domainMin);
  d.set("domainMax", s.domainMax);
  d.set("materialHeights", s.materialHeights);
  d.set("viscousIncrementDt", s.viscousIncrementDt);
  writeFileAtomic(uniform / stateFile, foamFileHeader("dictionary", stateFile, "uniform", false) +
                                           d.write() + foamFileFooter());
  writeArray(uniform, "frictionStates", s.frictionStates, format);
  writeArray(uniform, "slipDirections", s.slipDirections, format);
  writeArray(uniform, "viscousIncrements", s.viscousIncrements, format);
}

std::optional<StepState> readStepState(const fs::path& timeDir) {
  const fs::path uniform = timeDir / "uniform";
  if (!fs::exists(uniform / stateFile)) return std::nullopt;
  const Dictionary d = Dictionary::readFile(uniform / stateFile);
  StepState s;
  s.stepsTaken = d.get<long>("stepsTaken");
  s.stepsSinceReorder = d.get<long>("stepsSinceReorder");
  s.freshStart = d.get<bool>("freshStart");
  s.viscosityKnown = d.get<bool>("viscosityKnown");
  s.maxNu = d.get<double>("maxNu");
  s.maxViscousAcceleration = d.get<double>("maxViscousAcceleration");
  s.maxAcceleration = d.get<double>("maxAcceleration");
  s.soundSpeed = d.get<double>("soundSpeed");
  s.domainMin = d.get<Vec3>("domainMin");
  s.domainMax = d.get<Vec3>("domainMax");
  s.materialHeights = d.get<std::vector<double>>("materialHeights");
  s.viscousIncrementDt = d.get<double>("viscousIncrementDt");
  d.checkKeywords();
  s.frictionStates = readArray<label>(uniform, "frictionStates");
  s.slipDirections = readArray<Vec3>(uniform, "slipDirections");
  s.viscousIncrements = readArray<Vec3>(uniform, "viscousIncrements");
  if (s.slipDirections.size() != s.frictionStates.size()) {
    fatalError(fmt::format("{}: {} slip directions for {} friction states", uniform.string(),
                           s.slipDirections.size(), s.frictionStates.size()));
  }
  return s;
}

}  // namespace isph
