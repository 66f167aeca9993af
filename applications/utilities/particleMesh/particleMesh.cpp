// particleMesh: the initial particles of a case, from the scene in system/particleMeshDict:
// material regions filled on a square or hexagonal lattice, wall and dummy layers along the
// walls, the initial velocity and pressure. Writes 0/lagrangian/<cloud>/ (all of it or, when
// the input is bad, nothing). The first utility of every tutorial's Allrun.
//
//   particleMesh           # 0/lagrangian/particles/{positions,origId,U,p,material,kind,...}
//   particleMesh -csv      # also postProcessing/particleMesh/<cloud>.csv, for a first look
//
// Keywords: src/particleGeneration/SceneReader.hpp; what is done: ParticleGenerator.hpp.
#include <filesystem>
#include <iostream>

#include "core/Log.hpp"
#include "core/app/Application.hpp"
#include "core/app/OutOfMemory.hpp"
#include "core/io/ReadFile.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "core/io/AtomicFile.hpp"
#include "particleGeneration/CsvExport.hpp"
#include "particleGeneration/GenerationReport.hpp"
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
                 "(x,y,z,kind,material,patch,nx,ny,mass,p)"}},
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

void run(const isph::ArgList& args) {
  const std::filesystem::path& caseDir = args.casePath();
  const isph::Scene scene = isph::readScene(caseDir);
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
