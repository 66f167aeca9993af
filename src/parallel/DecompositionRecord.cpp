#include "parallel/DecompositionRecord.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "core/io/AtomicFile.hpp"
#include "parallel/DecomposedCase.hpp"
#include "parallel/DecompositionDict.hpp"

namespace isph {

namespace fs = std::filesystem;

void writeDecompositionRecord(const fs::path& processorDir, int numberOfSubdomains, long particles) {
  fs::create_directories(processorDir);
  writeFileAtomic(processorDir / "decomposition",
                  fmt::format("FoamFile {{ version 2.0; format ascii; class dictionary; object decomposition; }}\n"
                              "// written by the decomposition (decomposePar, or a parallel run from an undecomposed "
                              "time); reconstructPar checks the processor folders against it\n"
                              "numberOfSubdomains {};\nparticles {};\n",
                              numberOfSubdomains, particles));
}

DecompositionRecord wholeDecomposition(const fs::path& caseDir, bool force) {
  const int found = nProcessorDirectories(caseDir);
  if (found == 0) fatalError(fmt::format("{} has no processor directories", caseDir.string()));
  DecompositionRecord record;
  for (int p = 0; p < found && record.numberOfSubdomains == 0; ++p) {
    const fs::path file = caseDir / processorName(p) / "decomposition";
    if (!fs::is_regular_file(file)) continue;
    const Dictionary dict = Dictionary::readFile(file);
    record = {.numberOfSubdomains = dict.get<int>("numberOfSubdomains"), .particles = dict.get<long>("particles"),
              .source = file.string()};
  }
  if (record.numberOfSubdomains == 0) {
    record = {.numberOfSubdomains = DecompositionSettings::read(caseDir).numberOfSubdomains, .particles = 0,
              .source = (caseDir / "system/decomposeParDict").string()};
  }
  if (found == record.numberOfSubdomains) return record;
  const int missing = record.numberOfSubdomains - found;
  const std::string what = missing == 1  ? fmt::format("{} is missing", processorName(found))
                           : missing > 1 ? fmt::format("{} to {} are missing", processorName(found),
                                                       processorName(record.numberOfSubdomains - 1))
                                         : fmt::format("{} folder(s) too many", -missing);
  const std::string message = fmt::format(
      "{} holds {} processor directories, but the decomposition has numberOfSubdomains {} ({}): {}",
      caseDir.string(), found, record.numberOfSubdomains, record.source, what);
  if (!force) {
    fatalError(message + ". Put the missing processor folders back (or decompose again); -force reads what is "
                         "there, less than the whole case");
  }
  warning(message + "; -force: reading the " + std::to_string(found) + " there, less than the whole case");
  record.numberOfSubdomains = found;
  record.particles = 0;
  return record;
}

void checkWholeTime(const DecompositionRecord& record, const std::string& timeName, std::size_t particles) {
  if (record.particles <= 0 || static_cast<long>(particles) == record.particles) return;
  fatalError(fmt::format("time {}: the {} processor directories hold {} particles, the decomposition has {} ({}): "
                         "a processor lost particles or the time is damaged",
                         timeName, record.numberOfSubdomains, particles, record.particles, record.source));
}

}  // namespace isph
