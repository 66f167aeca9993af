// reconstructPar: merges the processor directories of a parallel run back into the case's
// time directories, as OpenFOAM's (doc/parallel.md): every time of processor0 (or those of
// -time, -latestTime, -noZero) becomes <time>/lagrangian/<cloud>/ with every field, the
// particles ordered material, wall, dummy and by origId, and uniform/; an existing time
// directory is replaced (atomically); a time that cannot be merged (a processor lacks it, as a
// parallel run killed while it wrote leaves) is skipped with a warning. toVTK, sampleForces and
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
#include "parallel/DecomposedCase.hpp"

namespace {

namespace fs = std::filesystem;

const isph::ApplicationSpec spec{
    .name = "reconstructPar",
    .description = "Merge processor*/<time> into <time> for the selected times (all of processor0's by default).",
    .options = {},
    .arguments = {},
    .timeOptions = true,
};

void run(const isph::ArgList& args) {
  const fs::path& caseDir = args.casePath();
  const int nProcs = isph::nProcessorDirectories(caseDir);
  if (nProcs == 0) isph::fatalError(fmt::format("{} has no processor directories to reconstruct", caseDir.string()));
  const auto all = isph::decomposedTimes(caseDir);
  const auto times = isph::selectTimes(all, isph::timeSelection(args));
  if (times.empty()) {
    isph::warning(fmt::format("no time selected in {} ({} times there)", (caseDir / "processor0").string(), all.size()));
  }
  isph::info("Reconstructing {} time(s) from {} processor directories\n", times.size(), nProcs);
  isph::SkippedTimes skipped;  // a time a processor lacks (a run killed while it wrote) is skipped with a warning
  for (const auto& time : times) {
    const auto n = skipped.read(time, [&] {
      isph::StagedDirectory staged(caseDir / time.name);
      const std::size_t particles = isph::reconstructTime(caseDir, nProcs, time.name, staged.path());
      staged.commit();
      return particles;
    });
    if (n) isph::info("Time = {}: {} particles", time.name, *n);
  }
  skipped.finish(times.size());
}

}  // namespace

int main(int argc, char* argv[]) { return isph::runApplication(spec, argc, argv, run); }
