// particleMesh: the initial particles of a case, from the scene in system/particleMeshDict:
// material regions filled on a square or hexagonal lattice, wall and dummy layers along the
// walls, the initial velocity and pressure. Writes 0/lagrangian/<cloud>/ (all of it or, when
// the input is bad, nothing). The first utility of every tutorial's Allrun.
//
//   particleMesh           # 0/lagrangian/particles/{positions,origId,U,p,material,kind,...}
//   particleMesh -csv      # also postProcessing/particleMesh/<cloud>.csv, for a first look
//   particleMesh -spacing 0.0108   # the scene at another spacing (the file unchanged)
//
// Material particles outside the walls' material side (a region drawn across a wall) are
// refused, naming the region (MaterialInsideWalls.hpp).
//
// A case with later times (a run of the old particles) keeps its 0/ unless -force: the
// solver's 'startFrom latestTime' would go on with the old run.
//
// Keywords: src/particleGeneration/SceneReader.hpp; what is done: ParticleGenerator.hpp.
#include <filesystem>
#include <iostream>

#include "core/Log.hpp"
#include "core/app/Application.hpp"
#include "core/Strings.hpp"
#include "core/app/OutOfMemory.hpp"
#include "core/time/TimeName.hpp"
#include "core/io/ReadFile.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "core/dictionary/KeywordRecord.hpp"
#include "core/io/AtomicFile.hpp"
#include "particleGeneration/CsvExport.hpp"
#include "particleGeneration/GenerationReport.hpp"
#include "particleGeneration/MaterialInsideWalls.hpp"
#include "particleGeneration/ParticleEstimate.hpp"
#include "particleGeneration/ParticleGenerator.hpp"
#include "particleGeneration/SceneReader.hpp"
#include "particles/CloudIO.hpp"

namespace {

const isph::ApplicationSpec spec{
    .name = "particleMesh",
    .description =
        "Generate the initial particles of a case from system/particleMeshDict into "
        "0/lagrangian/<cloud>.",
    .options = {{"csv", "",
                 "also write postProcessing/particleMesh/<cloud>.csv "
                 "(x,y,z,kind,material,patch,nx,ny,mass,p)"},
                {"spacing", "m", "the particle spacing in place of the one in system/particleMeshDict"},
                {"force", "", "replace 0/ although the case holds later times (a run of the old particles)"},
                {"listKeywords", "", "print every entry it reads from the case's dictionaries (its default, choices or range) and stop"}},
    .arguments = {},
    .timeOptions = false,
    .banner = true,
    .recovery = isph::CaseRecovery::allHosts,
};

// writeFormat and writePrecision of system/controlDict when the case has one (the only
// controls particleMesh needs), else ascii with 6 digits.
isph::FieldWriteOptions writeOptions(const std::filesystem::path& caseDir) {
  isph::FieldWriteOptions options;
  const std::filesystem::path file = caseDir / "system" / "controlDict";
  if (!std::filesystem::exists(file)) return options;
  const isph::Dictionary controlDict = isph::Dictionary::readFile(file);
  options.format =
      controlDict.getChoiceOrDefault("writeFormat", {"ascii", "binary"}, "ascii") == "binary"
          ? isph::WriteFormat::binary
          : isph::WriteFormat::ascii;
  options.precision = controlDict.getOrDefault("writePrecision", 6);
  if (options.precision < 1 || options.precision > 17) {
    isph::fatalIOError(
        controlDict.findEntry("writePrecision")->location(),
        fmt::format("keyword 'writePrecision' in {}: must be between 1 and 17, found {}",
                    controlDict.name(), options.precision));
  }
  return options;
}

// The value of option -spacing, if given.
std::optional<double> spacingOption(const isph::ArgList& args) {
  const auto text = args.option("spacing");
  if (!text) return std::nullopt;
  double value = 0;
  if (!isph::parseTimeName(*text, value) || !(value > 0)) {
    isph::fatalError(fmt::format("option -spacing expects a positive number in metres, found '{}'", *text));
  }
  return value;
}

// The times after 0 in the case and in its processor directories: a run of the particles in 0/.
std::vector<std::string> laterTimes(const std::filesystem::path& caseDir) {
  std::vector<std::string> later;
  std::vector<std::filesystem::path> dirs{caseDir};
  for (const auto& e : std::filesystem::directory_iterator(caseDir)) {
    if (e.is_directory() && e.path().filename().string().starts_with("processor")) dirs.push_back(e.path());
  }
  for (const auto& dir : dirs) {
    for (const auto& t : isph::listTimes(dir)) {
      if (t.value > 0) later.push_back((dir == caseDir ? "" : dir.filename().string() + "/") + t.name);
    }
  }
  return later;
}

void refuseToReplaceARun(const isph::ArgList& args) {
  const auto later = laterTimes(args.casePath());
  if (later.empty() || args.found("force")) return;
  isph::fatalError(fmt::format(
      "the case holds later times ({}{}): a run of the particles in 0/. New particles would not "
      "match them, and the solver's 'startFrom latestTime' would go on with the old run.\n"
      "    Remove them first (./Allclean, or clone the case: isphCloneCase <case> <copy>), or replace 0/ "
      "all the same with particleMesh -force",
      isph::join(std::vector<std::string>(later.begin(), later.begin() + std::min<std::size_t>(later.size(), 3)),
                 ", "),
      later.size() > 3 ? fmt::format(", ... {} in all", later.size()) : std::string()));
}

void run(const isph::ArgList& args) {
  const std::filesystem::path& caseDir = args.casePath();
  if (args.found("listKeywords")) {  // the keyword reference (doc/keywords.md): read, print, stop
    isph::enableKeywordRecord();
    (void)isph::readScene(caseDir, spacingOption(args));
    (void)writeOptions(caseDir);
    std::cout << isph::keywordReference();
    return;
  }
  refuseToReplaceARun(args);
  const isph::Scene scene = isph::readScene(caseDir, spacingOption(args));
  const isph::FieldWriteOptions options = writeOptions(caseDir);
  isph::logScene(scene);

  const isph::ParticleEstimate estimate = isph::estimateParticles(scene);
  isph::info("    estimate: {:.3g} particles (maxParticles {:.3g}); memory about {} here, {} to {} in the solver",
             estimate.particles(), scene.maxParticles, isph::bytesText(estimate.generationBytes()),
             isph::bytesText(estimate.particles() * isph::ParticleEstimate::solverBytesPerParticle[0]),
             isph::bytesText(estimate.particles() * isph::ParticleEstimate::solverBytesPerParticle[1]));
  std::cout.flush();  // the log holds the scene if the generation runs out of memory

  const isph::GenerationResult result = isph::generateParticles(scene);
  isph::logGeneration(scene, result);
  isph::checkMaterialInsideWalls(scene, result);  // nothing written with material behind a wall

  const std::filesystem::path zero = caseDir / "0";
  if (std::filesystem::exists(zero)) isph::info("\nReplacing {}", zero.string());
  const isph::Building building(fmt::format("the fields of {} particles in {}", result.cloud.size(), zero.string()));
  isph::StagedDirectory staged(zero);
  isph::writeCloud(staged.path(), "0", result.cloud, options);
  staged.commit();
  isph::info("\nWrote {} particles to {} ({}, {} digits)", result.cloud.size(),
             (zero / "lagrangian" / result.cloud.name).string(),
             options.format == isph::WriteFormat::binary ? "binary" : "ascii", options.precision);

  if (args.found("csv")) {
    const std::filesystem::path csv =
        caseDir / "postProcessing" / "particleMesh" / (result.cloud.name + ".csv");
    isph::writeCloudCsv(csv, result.cloud);
    isph::info("Wrote {}", csv.string());
  }
}

}  // namespace

int main(int argc, char* argv[]) { return isph::runApplication(spec, argc, argv, run); }
