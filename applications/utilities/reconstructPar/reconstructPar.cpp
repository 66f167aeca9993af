// reconstructPar: merges the processor directories of a parallel run back into the case's
// time directories, as OpenFOAM's (doc/parallel.md): every time of processor0 (or those of
// -time, -latestTime, -noZero) becomes <time>/lagrangian/<cloud>/ with every field, the
// particles ordered material, wall, dummy and by origId, and uniform/; an existing time
// directory is replaced (atomically). Only by the whole: the processor folders must be the
// decomposition's (processor<i>/decomposition, DecompositionRecord.hpp), each time must hold its
// particle count, and a root time (0/ above all) is never replaced by one with another particle
// count; -force reconstructs what is there all the same. A time that cannot be merged (a
// processor lacks it, as a parallel run killed while it wrote leaves) stops it with an error,
// or is skipped with a warning with -skipDamaged (SkippedTimes.hpp). toVTK, sampleForces and
// the other utilities then run on the case as on a serial run's (or on processor*/ directly,
// with -parallel).
#include <fmt/format.h>

#include <filesystem>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/app/Application.hpp"
#include "core/app/SkippedTimes.hpp"
#include "core/app/TimeOptions.hpp"
#include "core/io/AtomicFile.hpp"
#include "core/fields/FieldIO.hpp"
#include "parallel/DecomposedCase.hpp"
#include "parallel/DecompositionRecord.hpp"

namespace {

namespace fs = std::filesystem;

const isph::ApplicationSpec spec{
    .name = "reconstructPar",
    .description = "Merge processor*/<time> into <time> for the selected times (all of processor0's by default).",
    .options = {{"force", "", "reconstruct from processor folders that are less than the decomposition, and replace "
                              "root times that hold another number of particles"},
                isph::SkippedTimes::option()},
    .arguments = {},
    .timeOptions = true,
    .recovery = isph::CaseRecovery::allHosts,  // it writes time directories: it holds the case lock
};

// The particles of the root time `timeDir` (0 when it has none): those of its one cloud's origId.
std::size_t rootParticles(const fs::path& timeDir) {
  const std::vector<std::string> clouds = isph::cloudNames(timeDir);
  std::size_t n = 0;
  for (const std::string& cloud : clouds) n += isph::readFieldInfo(timeDir / "lagrangian" / cloud / "origId").size;
  return n;
}

// FatalError unless -force when the root time `timeDir` exists with another particle count than
// the `particles` that would replace it.
void checkReplace(const fs::path& timeDir, std::size_t particles, bool force) {
  if (force || !fs::is_directory(timeDir)) return;
  const std::size_t existing = rootParticles(timeDir);
  if (existing == particles) return;
  isph::fatalError(fmt::format("{} holds {} particles, the processor directories {}: not replaced (they are not the "
                               "decomposition of this case's particles; reconstructPar -force replaces it)",
                               timeDir.string(), existing, particles));
}

void run(const isph::ArgList& args) {
  const fs::path& caseDir = args.casePath();
  const bool force = args.found("force");
  const isph::DecompositionRecord decomposition = isph::wholeDecomposition(caseDir, force);
  const int nProcs = decomposition.numberOfSubdomains;
  const auto all = isph::decomposedTimes(caseDir);
  const auto times = isph::selectTimes(all, isph::timeSelection(args));
  if (times.empty()) {
    isph::fatalError(fmt::format("no time selected in {} ({} times there): nothing to do",
                                 (caseDir / "processor0").string(), all.size()));
  }
  isph::info("Reconstructing {} time(s) from {} processor directories\n", times.size(), nProcs);
  isph::SkippedTimes skipped(args);  // a time a processor lacks: an error, or skipped (-skipDamaged)
  for (const auto& time : times) {
    const auto n = skipped.read(time, [&] {
      isph::StagedDirectory staged(caseDir / time.name);
      const std::size_t particles = isph::reconstructTime(caseDir, nProcs, time.name, staged.path());
      if (!force) isph::checkWholeTime(decomposition, time.name, particles);
      checkReplace(caseDir / time.name, particles, force);
      staged.commit();
      return particles;
    });
    if (n) isph::info("Time = {}: {} particles", time.name, *n);
  }
  skipped.finish(times.size());
}

}  // namespace

int main(int argc, char* argv[]) { return isph::runApplication(spec, argc, argv, run); }
