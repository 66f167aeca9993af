// sampleForces: the force the material exerts on wall patches, for the selected times, set by
// set as system/sampleForcesDict names them; writes postProcessing/sampleForces/<firstTime>/
// <set>.dat (and <set>.png with -plot). The same routine as the solver's forces function object.
// Beside each <set>.dat, <set>Filtered.dat and <set>Figures.txt: the history filtered by the set's
// centred moving average (filterWindow) and its filtered peak, late force and raw maximum
// (FilteredForces.hpp). On written times a 10 ms window is narrower than their spacing: then the
// filtered history is the raw one, and the log says so (the function object filters every step).
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/app/Application.hpp"
#include "core/app/SkippedTimes.hpp"
#include "core/app/TimeOptions.hpp"
#include "parallel/DecomposedCase.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "core/io/AtomicFile.hpp"
#include "particles/CloudIO.hpp"
#include "postProcessing/forces/FilteredForces.hpp"
#include "postProcessing/forces/ForcePlot.hpp"
#include "postProcessing/forces/SetForces.hpp"
#include "postProcessing/forces/WallStress.hpp"

namespace {

namespace fs = std::filesystem;

const isph::ApplicationSpec spec{
    .name = "sampleForces",
    .description = "Forces of the material on the wall patches of each set in system/sampleForcesDict.",
    .options = {{"plot", "", "also draw <set>.png with gnuplot (force against time)"},
                {"cloud", "name", "the cloud (default: `cloud` in the dictionary, else particles)"},
                isph::SkippedTimes::option()},
    .arguments = {},
    .timeOptions = true,
    .parallel = true,
};

// What the forces of one time are computed from.
struct TimeState {
  isph::ParticleCloud cloud;
  std::optional<std::vector<isph::Vec3>> friction;
  std::optional<std::vector<isph::SymmTensor>> tau;
};

// The kernel that carries τ to the walls: the solver's (system/isphSchemes) when the case has one.
std::unique_ptr<isph::Kernel> kernelFor(const fs::path& casePath, const isph::CloudProperties& props) {
  return isph::caseKernel(casePath, props.spacing, props.dimension);
}

void run(const isph::ArgList& args) {
  const isph::Dictionary dict = isph::Dictionary::readFile(args.casePath() / "system" / "sampleForcesDict");
  const std::string cloudName = args.option("cloud").value_or(dict.getOrDefault("cloud", "particles"));
  const auto sets = isph::readForceSets(dict, {"cloud"});
  const auto times = isph::selectedTimes(args);

  std::vector<isph::ForceTable> tables;
  std::vector<std::string> text(sets.size());
  std::vector<std::string> headers(sets.size());
  std::unique_ptr<isph::Kernel> kernel;
  isph::SkippedTimes skipped(args);  // a time that cannot be read: an error, or skipped (-skipDamaged)
  for (const auto& time : times) {
    isph::info("Time = {}", time.name);
    // A material that slides on the walls (the solver wrote its wall friction) exchanges no τ
    // with them (PatchForces.hpp): τ is read only for one that does not.
    const auto state = skipped.read(time, [&] {
      const isph::DecomposedTime decomposed(args.casePath(), time.name, args.found("parallel"));
      const fs::path& timeDir = decomposed.path();
      TimeState s{isph::readCloud(timeDir, cloudName), std::nullopt, std::nullopt};
      s.friction = isph::readWallFriction(timeDir, cloudName, s.cloud.size());
      if (!s.friction) s.tau = isph::readDeviatoricStress(timeDir, cloudName, s.cloud.size());
      return s;
    });
    if (!state) continue;
    const auto& [cloud, friction, tau] = *state;
    if (tau && !kernel) kernel = kernelFor(args.casePath(), cloud.properties);
    const auto forces = isph::setForces({.cloud = cloud,
                                         .sets = sets,
                                         .tau = tau ? &*tau : nullptr,
                                         .kernel = kernel.get(),
                                         .neighbours = nullptr,
                                         .wallFriction = friction ? &*friction : nullptr});
    for (std::size_t s = 0; s < sets.size(); ++s) {
      if (tables.size() == s) {
        tables.emplace_back(sets[s], cloud.properties.dimension);
        headers[s] = tables[s].header(forces[s]);
        text[s] = headers[s];
      }
      text[s] += tables[s].row(time.value, forces[s]);
      const auto& f = forces[s];
      isph::info("    {}: Fn {:.6g} (pressure {:.6g}, deviatoric {:.6g}), Ft {:.6g} (friction {:.6g}) [{}] on {} wall "
                 "particles",
                 sets[s].name, f.normal(f.total), f.normal(f.pressure), f.normal(f.deviatoric), f.tangential(f.total),
                 f.tangential(f.friction), tables[s].columns()[1].unit, f.nWall);
    }
  }

  skipped.finish(times.size());
  const fs::path outDir = args.casePath() / "postProcessing" / "sampleForces" / times.front().name;
  fs::create_directories(outDir);
  for (std::size_t s = 0; s < sets.size(); ++s) {
    isph::writeFileAtomic(outDir / (sets[s].name + ".dat"), text[s]);
    isph::info("\nWritten {}", (outDir / (sets[s].name + ".dat")).string());
    const isph::ForceRows rows = isph::readForceRows(text[s]);
    if (rows.empty()) continue;
    double spacing = 0;  // the widest gap between samples
    for (std::size_t k = 1; k < rows.size(); ++k) spacing = std::max(spacing, rows[k][0] - rows[k - 1][0]);
    const fs::path filtered = outDir / (sets[s].name + "Filtered.dat");
    const fs::path figures = outDir / (sets[s].name + "Figures.txt");
    const isph::ForceFigures f = isph::writeFilteredForces(sets[s], tables[s], headers[s], rows, filtered, figures);
    const std::string unit = tables[s].columns()[1].unit;
    isph::info("Written {} and {}: filtered ({:g} s) peak Fn {:.6g} {} at {:.6g} s, late force {:.6g} {} (last {:g} s), "
               "raw maximum {:.6g} {}",
               filtered.string(), figures.string(), sets[s].filterWindow, f.filteredPeak, unit, f.filteredPeakTime,
               f.lateForce, unit, sets[s].lateForceWindow, f.rawMax, unit);
    if (spacing > sets[s].filterWindow) {
      isph::warning(fmt::format("set '{}': the filter window {:g} s (filterWindow) is narrower than the spacing of "
                                "the times sampled, up to {:g} s: the filtered history is nearly the raw one (the "
                                "solver's patchForces function object, every step, filters it)",
                                sets[s].name, sets[s].filterWindow, spacing));
    }
  }
  if (!args.found("plot")) return;
  for (std::size_t s = 0; s < sets.size(); ++s) {  // after every .dat is written: gnuplot may be missing
    const fs::path reference = sets[s].reference ? args.casePath() / *sets[s].reference : fs::path();
    const fs::path png = outDir / (sets[s].name + ".png");
    const fs::path dat = outDir / (sets[s].name + ".dat");
    isph::plotForces(sets[s], tables[s], {.dat = dat, .png = png, .reference = reference});
    isph::info("Written {}", png.string());
  }
}

}  // namespace

int main(int argc, char* argv[]) { return isph::runApplication(spec, argc, argv, run); }
