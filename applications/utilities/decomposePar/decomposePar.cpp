// decomposePar: splits the particles of a case among the processor directories of a parallel
// run, as OpenFOAM's (doc/parallel.md): system/decomposeParDict gives numberOfSubdomains and
// Zoltan's algorithm (RCB or HSFC); every selected time directory (all by default; -time,
// -latestTime) becomes processor<i>/<time>/lagrangian/<cloud>/ with every field, and
// uniform/. The partition balances the particles' work (ParticlePartition.hpp) and keeps each
// dummy particle with its wall particle. Existing processor directories are an error unless
// -force, which removes them first.
//
//   decomposePar                 # then: mpirun -np N isphLandslideFoam -parallel
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/app/Application.hpp"
#include "core/app/TimeOptions.hpp"
#include "core/io/AtomicFile.hpp"
#include "linearSolvers/ParallelEnvironment.hpp"
#include "parallel/DecomposedCase.hpp"
#include "parallel/DecompositionDict.hpp"
#include "parallel/DecompositionRecord.hpp"
#include "parallel/ParticlePartition.hpp"
#include "parallel/ZoltanPartitioner.hpp"
#include "particles/CloudIO.hpp"
#include "sph/neighbours/NearestPoints.hpp"

namespace {

namespace fs = std::filesystem;

const isph::ApplicationSpec spec{
    .name = "decomposePar",
    .description = "Split the particles of the selected times into processor<i>/<time> for a parallel run "
                   "(system/decomposeParDict).",
    .options = {{"force", "", "remove existing processor directories first"}},
    .arguments = {},
    .timeOptions = true,
    .recovery = isph::CaseRecovery::allHosts,  // it writes time directories: it holds the case lock
};

// For each dummy particle the index of its wall particle (the nearest, ties by origId, as
// the solver finds it), -1 for the others. The search widens until every dummy has one.
std::vector<int> dummyParents(const isph::ParticleCloud& cloud) {
  std::vector<std::size_t> walls, dummies;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.kind[i] == static_cast<isph::label>(isph::ParticleKind::wall)) walls.push_back(i);
    if (cloud.kind[i] == static_cast<isph::label>(isph::ParticleKind::dummy)) dummies.push_back(i);
  }
  std::vector<int> parent(cloud.size(), -1);
  if (dummies.empty()) return parent;
  std::vector<isph::Vec3> wallX, dummyX;
  std::vector<isph::label> wallIds;
  for (const std::size_t w : walls) {
    wallX.push_back(cloud.positions[w]);
    wallIds.push_back(cloud.origId[w]);
  }
  for (const std::size_t d : dummies) dummyX.push_back(cloud.positions[d]);
  for (double radius = 8 * cloud.properties.spacing;; radius *= 2) {
    const std::vector<int> nearest = isph::nearestPoints(wallX, wallIds, dummyX, radius, cloud.properties.dimension);
    if (std::find(nearest.begin(), nearest.end(), -1) == nearest.end()) {
      for (std::size_t k = 0; k < dummies.size(); ++k) parent[dummies[k]] = static_cast<int>(walls[nearest[k]]);
      return parent;
    }
    if (radius > 1e3 * cloud.properties.spacing) {
      isph::fatalError(fmt::format("cloud '{}': a dummy particle has no wall particle within {:.3g} m", cloud.name,
                                   radius));
    }
  }
}

void run(const isph::ArgList& args) {
  const fs::path& caseDir = args.casePath();
  const isph::DecompositionSettings settings = isph::DecompositionSettings::read(caseDir);
  if (const int existing = isph::nProcessorDirectories(caseDir); existing > 0) {
    if (!args.found("force")) {
      isph::fatalError(fmt::format("{} holds {} processor directories: remove them, or run decomposePar -force",
                                   caseDir.string(), existing));
    }
    // (from the last: a kill meanwhile leaves processor0.. without a gap, each out of view
    // before it is deleted, AtomicFile.hpp)
    for (int i = existing - 1; i >= 0; --i) isph::removeDirectoryAtomically(caseDir / isph::processorName(i));
    isph::info("Removed {} processor directories", existing);
  }
  const auto times = isph::selectedTimes(args);
  const int nParts = settings.numberOfSubdomains;
  isph::info("Decomposing into {} subdomains with zoltan {}\n", nParts, settings.algorithm);
  long particles = 0;  // (every time holds the same particles: the solver creates and deletes none)
  for (const auto& time : times) {
    const std::vector<std::string> clouds = isph::cloudNames(caseDir / time.name);
    if (clouds.size() != 1) {
      isph::fatalError(fmt::format("time {}: expected one particle cloud in {}, found {}", time.name,
                                   (caseDir / time.name / "lagrangian").string(), clouds.size()));
    }
    const isph::ParticleCloud cloud = isph::readCloud(caseDir / time.name, clouds[0]);
    const isph::PartitionInput in = isph::partitionInput(cloud, dummyParents(cloud));
    isph::ZoltanPartitioner zoltan(settings.algorithm, cloud.properties.dimension, nParts);
    const std::vector<int> part = zoltan.partition(in.points, in.weights, cloud.origId);
    isph::decomposeTime(caseDir, time.name, clouds[0], part, nParts);
    particles = static_cast<long>(cloud.size());

    std::vector<double> load(static_cast<std::size_t>(nParts), 0.0);
    std::vector<long> material(static_cast<std::size_t>(nParts), 0), all(load.size(), 0);
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const auto p = static_cast<std::size_t>(part[i]);
      load[p] += in.weights[i];
      ++all[p];
      material[p] += cloud.kind[i] == static_cast<isph::label>(isph::ParticleKind::material);
    }
    isph::info("Time = {}: {} particles of cloud '{}'", time.name, cloud.size(), clouds[0]);
    for (int p = 0; p < nParts; ++p) {
      isph::info("    processor{}: {} particles, {} material", p, all[static_cast<std::size_t>(p)],
                 material[static_cast<std::size_t>(p)]);
    }
    isph::info("    balance: largest load / mean load = {:.3f}", isph::imbalance(load));
    isph::warnIfOverDecomposed(material);
  }
  for (int p = 0; p < nParts; ++p) {
    isph::writeDecompositionRecord(caseDir / isph::processorName(p), nParts, particles);
  }
  isph::info("\nWrote {} processor directories", nParts);
}

}  // namespace

int main(int argc, char* argv[]) {
  isph::ParallelEnvironment parallel(argc, argv);  // Zoltan runs on MPI (one rank here)
  return isph::runApplication(spec, argc, argv, run);
}
