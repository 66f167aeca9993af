#include "parallel/DecomposedCase.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <numeric>
#include <type_traits>

#include "core/Error.hpp"
#include "core/Types.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "core/fields/FieldIO.hpp"
#include "core/io/AtomicFile.hpp"
#include "core/io/StagingNames.hpp"
#include "core/io/ReadFile.hpp"
#include "parallel/DecompositionRecord.hpp"

namespace isph {

namespace fs = std::filesystem;

namespace {

// The options that write a field as it was read: its format, ascii to 17 digits (exact).
FieldWriteOptions optionsLike(const FieldFileInfo& info, const std::string& location) {
  return {.format = info.format, .precision = 17, .location = location};
}

bool isFieldClass(const std::string& className) {
  return className == "scalarField" || className == "labelField" || className == "vectorField" ||
         className == "symmTensorField";
}

// Calls f.template operator()<T>() with the particle field type of an OpenFOAM class name;
// false for a file that is not a particle field (cloudProperties, a dictionary).
template <class F>
bool withFieldType(const std::string& className, F&& f) {
  if (className == "scalarField") return f.template operator()<scalar>(), true;
  if (className == "labelField") return f.template operator()<label>(), true;
  if (className == "vectorField") return f.template operator()<Vec3>(), true;
  if (className == "symmTensorField") return f.template operator()<SymmTensor>(), true;
  return false;
}

// The class of a file's FoamFile header ("vectorField", "dictionary", ...), from its first bytes.
std::string headerClass(const fs::path& file) {
  std::size_t end = 0;
  const Dictionary header = Dictionary::parseHeader(readFileBytes(file, 4096), file.string(), end);
  const Dictionary* foamFile = header.findDict("FoamFile");
  return foamFile ? foamFile->getOrDefault<std::string>("class", "") : std::string();
}

void copyUniform(const fs::path& fromTime, const fs::path& toTime) {
  const fs::path uniform = fromTime / "uniform";
  if (!fs::is_directory(uniform)) return;
  fs::create_directories(toTime / "uniform");
  for (const auto& e : fs::directory_iterator(uniform)) {
    if (e.is_regular_file()) writeFileAtomic(toTime / "uniform" / e.path().filename(), readFileBytes(e.path()));
  }
}

fs::path cloudDir(const fs::path& timeDir, const std::string& cloud) { return timeDir / "lagrangian" / cloud; }

template <class T>
T zeroValue() {
  if constexpr (std::is_arithmetic_v<T>) {
    return T{0};
  } else {
    return T::Zero();
  }
}

// The field files of uniform/ (the solver's arrays by origId, StepState.hpp) of the
// processors' <timeName>, merged into <target>/uniform: entry id from the processor that holds
// particle origId id (`owner`), zero for one that none holds. A processor without the file (one
// that had no entries) gives none. The other files of uniform/ are processor0's (copyUniform).
void mergeUniformFields(const fs::path& caseDir, int nProcs, const std::string& timeName, const std::vector<int>& owner,
                        const fs::path& target) {
  std::vector<std::string> names;
  for (int p = 0; p < nProcs; ++p) {
    for (const std::string& name : listFields(caseDir / processorName(p) / timeName / "uniform")) {
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
  }
  for (const std::string& name : names) {
    std::vector<fs::path> files;
    for (int p = 0; p < nProcs; ++p) files.push_back(caseDir / processorName(p) / timeName / "uniform" / name);
    const auto present = std::find_if(files.begin(), files.end(), [](const fs::path& f) { return fs::is_regular_file(f); });
    if (!isFieldClass(headerClass(*present))) continue;
    const FieldFileInfo info = readFieldInfo(*present);
    withFieldType(info.className, [&]<class T>() {
      std::vector<std::vector<T>> parts(files.size());
      std::size_t size = 0;
      for (std::size_t p = 0; p < files.size(); ++p) {
        if (fs::is_regular_file(files[p])) parts[p] = readField<T>(files[p]);
        size = std::max(size, parts[p].size());
      }
      std::vector<T> merged(size, zeroValue<T>());
      for (std::size_t id = 0; id < size && id < owner.size(); ++id) {
        if (owner[id] < 0) continue;
        const auto& part = parts[static_cast<std::size_t>(owner[id])];
        if (id < part.size()) merged[id] = part[id];
      }
      writeField(target / "uniform" / name, merged, optionsLike(info, "uniform"));
    });
  }
}

}  // namespace

std::string processorName(int i) { return fmt::format("processor{}", i); }

int nProcessorDirectories(const fs::path& caseDir) {
  int n = 0;
  while (fs::is_directory(caseDir / processorName(n))) ++n;
  std::error_code ec;
  for (fs::directory_iterator it(caseDir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind("processor", 0) != 0 || !it->is_directory()) continue;
    const std::string number = name.substr(9);
    if (!number.empty() && std::all_of(number.begin(), number.end(), [](unsigned char c) { return std::isdigit(c) != 0; }) && std::stoi(number) >= n) {
      fatalError(fmt::format("{}: {} exists but {} does not: the processor directories must run from processor0 "
                             "without a gap (decomposePar -force writes them anew)",
                             caseDir.string(), name, processorName(n)));
    }
  }
  return n;
}

std::vector<std::string> cloudNames(const fs::path& timeDir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(timeDir / "lagrangian", ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (it->is_directory() && !name.empty() && name[0] != '.') names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

void decomposeTime(const fs::path& caseDir, const std::string& timeName, const std::string& cloudName,
                   const std::vector<int>& part, int nParts) {
  const fs::path source = caseDir / timeName;
  const std::vector<std::string> clouds = cloudNames(source);
  if (clouds.size() != 1 || clouds[0] != cloudName) {
    fatalError(fmt::format("decomposing {}: expected the one cloud '{}' in {}, found {}", timeName, cloudName,
                           (source / "lagrangian").string(), clouds.size()));
  }
  std::vector<std::vector<std::size_t>> members(static_cast<std::size_t>(nParts));
  for (std::size_t i = 0; i < part.size(); ++i) {
    if (part[i] < 0 || part[i] >= nParts) fatalError(fmt::format("decomposeTime: particle {} in part {}", i, part[i]));
    members[static_cast<std::size_t>(part[i])].push_back(i);
  }
  const fs::path from = cloudDir(source, cloudName);
  const std::string location = fmt::format("{}/lagrangian/{}", timeName, cloudName);
  for (int p = 0; p < nParts; ++p) {
    fs::create_directories(caseDir / processorName(p));
    StagedDirectory staged(caseDir / processorName(p) / timeName);
    const fs::path to = cloudDir(staged.path(), cloudName);
    fs::create_directories(to);
    for (const std::string& field : listFields(from)) {
      const FieldFileInfo info = isFieldClass(headerClass(from / field)) ? readFieldInfo(from / field) : FieldFileInfo{};
      const bool isField = withFieldType(info.className, [&]<class T>() {
        const std::vector<T> all = readField<T>(from / field, part.size());
        std::vector<T> mine;
        mine.reserve(members[static_cast<std::size_t>(p)].size());
        for (const std::size_t i : members[static_cast<std::size_t>(p)]) mine.push_back(all[i]);
        writeField(to / field, mine, optionsLike(info, location));
      });
      if (!isField) writeFileAtomic(to / field, readFileBytes(from / field));  // cloudProperties
    }
    copyUniform(source, staged.path());
    staged.commit();
  }
}

std::size_t reconstructTime(const fs::path& caseDir, int nProcs, const std::string& timeName, const fs::path& target) {
  if (nProcs < 1) fatalError(fmt::format("{}: no processor directories to reconstruct", caseDir.string()));
  const fs::path first = caseDir / processorName(0) / timeName;
  if (!fs::is_directory(first)) fatalError(fmt::format("{} does not exist", first.string()));
  std::size_t total = 0;
  std::vector<int> owner;  // by origId: the processor that holds the particle
  for (const std::string& cloud : cloudNames(first)) {
    // Every processor's particles of this cloud: their kinds and origIds give the order.
    std::vector<label> kind, origId;
    std::vector<std::size_t> counts;
    for (int p = 0; p < nProcs; ++p) {
      const fs::path dir = cloudDir(caseDir / processorName(p) / timeName, cloud);
      if (!fs::is_directory(dir)) {
        fatalError(fmt::format("{} does not exist: {} lacks time {} or its cloud '{}'", dir.string(), processorName(p),
                               timeName, cloud));
      }
      const std::vector<label> k = readField<label>(dir / "kind"), id = readField<label>(dir / "origId", k.size());
      kind.insert(kind.end(), k.begin(), k.end());
      origId.insert(origId.end(), id.begin(), id.end());
      counts.push_back(k.size());
    }
    for (int p = 0, i = 0; p < nProcs; ++p) {
      for (std::size_t k = 0; k < counts[static_cast<std::size_t>(p)]; ++k, ++i) {
        const label id = origId[static_cast<std::size_t>(i)];
        if (id < 0) continue;
        if (static_cast<std::size_t>(id) >= owner.size()) owner.resize(static_cast<std::size_t>(id) + 1, -1);
        owner[static_cast<std::size_t>(id)] = p;
      }
    }
    std::vector<std::size_t> order(kind.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return kind[a] != kind[b] ? kind[a] < kind[b] : origId[a] < origId[b];
    });
    for (std::size_t k = 1; k < order.size(); ++k) {
      if (origId[order[k]] == origId[order[k - 1]] && kind[order[k]] == kind[order[k - 1]]) {
        fatalError(fmt::format("reconstructing {} of {}: particle origId {} is on two processors", timeName,
                               caseDir.string(), origId[order[k]]));
      }
    }
    const fs::path to = cloudDir(target, cloud);
    fs::create_directories(to);
    const fs::path from0 = cloudDir(first, cloud);
    const std::string location = fmt::format("{}/lagrangian/{}", timeName, cloud);
    for (const std::string& field : listFields(from0)) {
      const FieldFileInfo info = isFieldClass(headerClass(from0 / field)) ? readFieldInfo(from0 / field) : FieldFileInfo{};
      const bool isField = withFieldType(info.className, [&]<class T>() {
        std::vector<T> all;
        all.reserve(kind.size());
        for (int p = 0; p < nProcs; ++p) {
          const fs::path file = cloudDir(caseDir / processorName(p) / timeName, cloud) / field;
          if (!fs::is_regular_file(file)) {
            fatalError(fmt::format("{} does not exist (processor0 has field {})", file.string(), field));
          }
          const std::vector<T> part = readField<T>(file, counts[static_cast<std::size_t>(p)]);
          all.insert(all.end(), part.begin(), part.end());
        }
        std::vector<T> sorted;
        sorted.reserve(all.size());
        for (const std::size_t i : order) sorted.push_back(all[i]);
        writeField(to / field, sorted, optionsLike(info, location));
      });
      if (!isField) writeFileAtomic(to / field, readFileBytes(from0 / field));
    }
    total += kind.size();
  }
  copyUniform(first, target);
  mergeUniformFields(caseDir, nProcs, timeName, owner, target);
  return total;
}

std::vector<Instant> decomposedTimes(const fs::path& caseDir) { return listTimes(caseDir / processorName(0)); }

DecomposedTime::DecomposedTime(const fs::path& caseDir, const std::string& timeName, bool decomposed)
    : path_(caseDir / timeName) {
  if (!decomposed) return;
  path_ = stagingName(caseDir / timeName, "tmp");
  temporary_ = true;
  fs::remove_all(path_);
  fs::create_directories(path_);
  try {
    const DecompositionRecord decomposition = wholeDecomposition(caseDir);
    checkWholeTime(decomposition, timeName,
                   reconstructTime(caseDir, decomposition.numberOfSubdomains, timeName, path_));
  } catch (...) {  // (a time a processor lacks: the caller skips it; the folder must not stay)
    std::error_code ec;
    fs::remove_all(path_, ec);
    throw;
  }
}

DecomposedTime::~DecomposedTime() {
  std::error_code ec;
  if (temporary_) fs::remove_all(path_, ec);
}

}  // namespace isph
