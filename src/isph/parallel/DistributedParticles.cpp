#include "isph/parallel/DistributedParticles.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <numeric>
#include <unordered_map>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "parallel/DecomposedCase.hpp"
#include "parallel/DecompositionRecord.hpp"
#include "parallel/GlobalNumbering.hpp"
#include "parallel/Migration.hpp"
#include "parallel/ParticleFields.hpp"
#include "parallel/ParticlePartition.hpp"
#include "parallel/Reduce.hpp"
#include "particles/CloudIO.hpp"
#include "sph/neighbours/NearestPoints.hpp"
#include "sph/neighbours/NeighbourList.hpp"

namespace isph {

namespace {

constexpr auto materialKind = static_cast<label>(ParticleKind::material);
constexpr auto wallKind = static_cast<label>(ParticleKind::wall);
constexpr auto dummyKind = static_cast<label>(ParticleKind::dummy);

// The index of each dummy particle's wall particle in `cloud` (the nearest within `radius`,
// ties by origId, as initialiseParticleSystem finds it), -1 for the others and for a dummy
// without one (initialiseParticleSystem then stops with the message the serial run gives).
std::vector<int> wallOfDummies(const ParticleCloud& cloud, double radius) {
  std::vector<std::size_t> walls, dummies;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.kind[i] == wallKind) walls.push_back(i);
    if (cloud.kind[i] == dummyKind) dummies.push_back(i);
  }
  std::vector<Vec3> wallX, dummyX;
  std::vector<label> wallIds;
  for (const std::size_t w : walls) {
    wallX.push_back(cloud.positions[w]);
    wallIds.push_back(cloud.origId[w]);
  }
  for (const std::size_t d : dummies) dummyX.push_back(cloud.positions[d]);
  const std::vector<int> nearest = nearestPoints(wallX, wallIds, dummyX, radius, cloud.properties.dimension);
  std::vector<int> parent(cloud.size(), -1);
  for (std::size_t k = 0; k < dummies.size(); ++k) {
    parent[dummies[k]] = nearest[k] < 0 ? -1 : static_cast<int>(walls[static_cast<std::size_t>(nearest[k])]);
  }
  return parent;
}

// The order material, wall, dummy (each in its current order), and the material by cell.
std::vector<std::size_t> kindAndCellOrder(const ParticleCloud& cloud, double cellSize) {
  std::vector<std::size_t> order;
  std::vector<Vec3> material;
  std::vector<std::size_t> materialIndex;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.kind[i] == materialKind) {
      material.push_back(cloud.positions[i]);
      materialIndex.push_back(i);
    }
  }
  for (const int m : cellOrder(material, cellSize, cloud.properties.dimension)) {
    order.push_back(materialIndex[static_cast<std::size_t>(m)]);
  }
  for (const label kind : {wallKind, dummyKind}) {
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      if (cloud.kind[i] == kind) order.push_back(i);
    }
  }
  return order;
}

}  // namespace

DistributedParticles::DistributedParticles(const Time& time) : settings_(DecompositionSettings::read(time.path())) {
  if (settings_.numberOfSubdomains != nRanks()) {
    fatalError(fmt::format("system/decomposeParDict has numberOfSubdomains {}, but the run has {} MPI ranks: run "
                           "mpirun -np {} (or change numberOfSubdomains, and run decomposePar -force)",
                           settings_.numberOfSubdomains, nRanks(), settings_.numberOfSubdomains));
  }
  const int processors = nProcessorDirectories(time.path());
  if (!allRanks(time.decomposedStart() == (processors > 0))) {
    fatalError(fmt::format("{} holds {} processor directories, not all with the start time {}: run decomposePar "
                           "-force, or remove processor* to start from the undecomposed {}",
                           time.path().string(), processors, time.timeName(), time.timeName()));
  }
  if (processors > 0 && processors != nRanks()) {
    fatalError(fmt::format("{} is decomposed into {} processor directories, but the run has {} MPI ranks",
                           time.path().string(), processors, nRanks()));
  }
  if (!allRanks(minOverRanks(time.value()) == maxOverRanks(time.value()))) {
    fatalError("the processor directories start at different times: their latest times differ");
  }
  processorDir_ = time.timePath().parent_path();
  std::filesystem::create_directories(processorDir_);  // processor<rank>, for the writes
}

DistributedParticles::~DistributedParticles() = default;

ParticleCloud DistributedParticles::read(const Time& time, const std::string& name) const {
  if (time.decomposedStart() || thisRank() == 0) return readCloud(time.startPath(), name);
  ParticleCloud cloud;  // an undecomposed start: rank 0 reads, the others start empty
  cloud.name = name;
  cloud.properties = readCloudProperties(time.startPath(), name);
  return cloud;
}

void DistributedParticles::distribute(ParticleCloud& cloud, double wallRadius) {
  const int dimension = cloud.properties.dimension;
  zoltan_ = std::make_unique<ZoltanPartitioner>(settings_.algorithm, dimension, nRanks());
  const PartitionInput in = partitionInput(cloud, wallOfDummies(cloud, wallRadius));
  const std::vector<int> part = zoltan_->partition(in.points, in.weights, cloud.origId);
  ParticleFields fields(cloud);
  migrateParticles(fields, part);

  std::vector<double> loads;
  lastImbalance_ = worstImbalance_ = imbalanceOf(partitionLoad(cloud), &loads);
  long material = 0;
  for (const label k : cloud.kind) material += k == materialKind;
  const std::vector<long> all = gatherOverRanks(static_cast<long>(cloud.size()));
  const std::vector<long> materials = gatherOverRanks(material);
  info("\nDecomposition: {} MPI ranks, zoltan {} (system/decomposeParDict); repartition above {} x the mean load",
       nRanks(), settings_.algorithm, settings_.repartitionFactor);
  info("    particles per rank:          {}", fmt::join(all, " "));
  info("    material particles per rank: {}", fmt::join(materials, " "));
  info("    balance: largest load / mean load = {:.3f} (material 1, wall {}, dummy {})", lastImbalance_,
       wallWeight, dummyWeight);
  warnIfOverDecomposed(materials);
  // (what reconstructPar checks the processor folders against: each rank its own)
  const long particles = std::accumulate(all.begin(), all.end(), 0L);
  writeDecompositionRecord(processorDir_, nRanks(), particles);
}

double DistributedParticles::imbalanceOf(double load, std::vector<double>* loads) const {
  const std::vector<double> all = gatherOverRanks(load);
  if (loads) *loads = all;
  return imbalance(all);
}

void DistributedParticles::beginStep(ParticleSystem& ps, const MaterialTable& materials, double supportRadius,
                                     bool redistribute, const Time& time) {
  if (!adopted_) {  // the particles as initialiseParticleSystem left them: own, each dummy's wall found
    parentId_.assign(ps.size(), -1);
    for (std::size_t d = ps.dummyBegin(); d < ps.size(); ++d) {
      parentId_[d] = ps.cloud.origId[static_cast<std::size_t>(ps.parentWall[d])];
    }
    firstRow_ = GlobalNumbering::of(static_cast<long>(ps.nMaterial)).first;
    adopted_ = true;
  } else {
    dropGhosts(ps);
    if (redistribute) this->redistribute(ps, supportRadius, time);
  }
  buildGhosts(ps, materials, supportRadius);
}

void DistributedParticles::dropGhosts(ParticleSystem& ps) {
  // The ghosts of each kind are a block after the own ones: remove the blocks from the back.
  ParticleFields fields(ps.cloud);
  fields.add(parentId_);  // (as the cloud: one per particle, own and ghost)
  fields.erase(ps.dummyBegin() + ps.nOwnedDummy, ps.nDummy - ps.nOwnedDummy);
  fields.erase(ps.wallBegin() + ps.nOwnedWall, ps.nWall - ps.nOwnedWall);
  fields.erase(ps.nOwnedMaterial, ps.nMaterial - ps.nOwnedMaterial);
  ps.nMaterial = ps.nOwnedMaterial;
  ps.nWall = ps.nOwnedWall;
  ps.nDummy = ps.nOwnedDummy;
  ps.halo = nullptr;
  halo_.reset();
  ps.ghostRow.clear();
}

void DistributedParticles::redistribute(ParticleSystem& ps, double supportRadius, const Time& time) {
  ParticleCloud& cloud = ps.cloud;
  std::unordered_map<label, std::size_t> wallIndex;
  for (std::size_t w = ps.wallBegin(); w < ps.dummyBegin(); ++w) wallIndex[cloud.origId[w]] = w;
  std::vector<int> parent(cloud.size(), -1);
  for (std::size_t d = ps.dummyBegin(); d < cloud.size(); ++d) parent[d] = static_cast<int>(wallIndex.at(parentId_[d]));
  const PartitionInput in = partitionInput(cloud, parent);

  // Where each particle belongs by the kept cuts; the loads that gives.
  std::vector<int> destination(cloud.size());
  std::vector<double> loads(static_cast<std::size_t>(nRanks()), 0.0);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    destination[i] = zoltan_->partOf(in.points[i]);
    loads[static_cast<std::size_t>(destination[i])] += in.weights[i];
  }
  sumOverRanks(std::span<double>(loads));
  double balance = imbalance(loads);
  // The worst balance is the one the run reached with the kept cuts, before a repartition.
  worstImbalance_ = std::max(worstImbalance_, balance);
  if (balance > settings_.repartitionFactor) {
    destination = zoltan_->partition(in.points, in.weights, cloud.origId);
    std::fill(loads.begin(), loads.end(), 0.0);
    for (std::size_t i = 0; i < cloud.size(); ++i) loads[static_cast<std::size_t>(destination[i])] += in.weights[i];
    sumOverRanks(std::span<double>(loads));
    info("    Repartitioned at time {}: largest load / mean load {:.3f} > {} -> {:.3f}", time.timeName(), balance,
         settings_.repartitionFactor, imbalance(loads));
    balance = imbalance(loads);
    ++repartitions_;
  }
  ParticleFields fields(cloud);
  fields.add(parentId_);
  migrateParticles(fields, destination);

  // Material (by cell), wall, dummy; and the rows of the own material, numbered anew.
  const std::vector<std::size_t> order = kindAndCellOrder(cloud, supportRadius);
  fields.keep(order);
  ps.nOwnedMaterial = ps.nMaterial = static_cast<std::size_t>(std::count(cloud.kind.begin(), cloud.kind.end(), materialKind));
  ps.nOwnedWall = ps.nWall = static_cast<std::size_t>(std::count(cloud.kind.begin(), cloud.kind.end(), wallKind));
  ps.nOwnedDummy = ps.nDummy = cloud.size() - ps.nMaterial - ps.nWall;
  firstRow_ = GlobalNumbering::of(static_cast<long>(ps.nMaterial)).first;
  ++checks_;
  lastImbalance_ = balance;
  imbalanceSum_ += balance;
}

void DistributedParticles::buildGhosts(ParticleSystem& ps, const MaterialTable& materials, double supportRadius) {
  ParticleCloud& cloud = ps.cloud;
  const std::size_t nOwned = cloud.size();
  // Own particles: material [0, nM), walls [nM, nM + nW), dummies after (ps as dropGhosts left it).
  const std::size_t nM = ps.nMaterial, nW = ps.nWall;
  std::unordered_map<label, std::size_t> ownWall;
  for (std::size_t w = nM; w < nM + nW; ++w) ownWall[cloud.origId[w]] = w;
  std::vector<int> companion(nOwned, -1);
  std::vector<long> row(nOwned, -1);
  for (std::size_t i = 0; i < nOwned; ++i) {
    if (i < nM) row[i] = firstRow_ + static_cast<long>(i);
    if (cloud.kind[i] == dummyKind) companion[i] = static_cast<int>(ownWall.at(parentId_[i]));
  }
  halo_ = std::make_unique<Halo>(cloud.positions, supportRadius, cloud.properties.dimension, companion);

  // The ghosts, received in a cloud of their own, then inserted as a block after the own
  // particles of their kind (the layout of ParticleSystem.hpp): only the blocks after move.
  ParticleFields fields(cloud);
  fields.add(parentId_);
  fields.add(row);
  ParticleCloud ghosts;
  std::vector<label> ghostParent;
  std::vector<long> ghostRowOf;
  ParticleFields ghostFields(ghosts);
  ghostFields.add(ghostParent);
  ghostFields.add(ghostRowOf);
  halo_->sendParticles(fields, ghostFields);
  std::vector<std::size_t> counts;  // own and ghost, per kind
  std::vector<std::size_t> ghostLocal(ghosts.size());
  std::size_t at = 0;
  for (const label kind : {materialKind, wallKind, dummyKind}) {
    const std::size_t own = static_cast<std::size_t>(kind == materialKind ? nM : kind == wallKind ? nW : nOwned - nM - nW);
    std::vector<std::size_t> ofKind;
    for (std::size_t g = 0; g < ghosts.size(); ++g) {
      if (ghosts.kind[g] == kind) ofKind.push_back(g);
    }
    at += own;
    const std::vector<std::byte> packed = ghostFields.pack(ofKind);
    fields.insert(at, packed.data(), ofKind.size());
    for (std::size_t k = 0; k < ofKind.size(); ++k) ghostLocal[ofKind[k]] = at + k;
    at += ofKind.size();
    counts.push_back(own);
    counts.push_back(ofKind.size());
  }
  const std::size_t nLocal = cloud.size();
  // An own particle moved up by the ghosts inserted before it.
  std::vector<std::size_t> sendLocal;
  for (const std::size_t i : halo_->sent()) {
    sendLocal.push_back(i < nM ? i : i < nM + nW ? i + counts[1] : i + counts[1] + counts[3]);
  }

  ps.nOwnedMaterial = counts[0];
  ps.nMaterial = counts[0] + counts[1];
  ps.nOwnedWall = counts[2];
  ps.nWall = counts[2] + counts[3];
  ps.nOwnedDummy = counts[4];
  ps.nDummy = counts[4] + counts[5];
  halo_->setLayout(std::move(sendLocal), std::move(ghostLocal), nLocal, ps.nMaterial);
  ps.halo = halo_.get();
  ps.firstRow = firstRow_;
  ps.ghostRow.assign(row.begin() + static_cast<long>(ps.nOwnedMaterial), row.begin() + static_cast<long>(ps.nMaterial));

  // What initialiseParticleSystem set for every particle: density, volume, dummy-to-wall.
  const double wallArea = ps.dimension == 3 ? ps.dx * ps.dx * ps.dx : ps.dx * ps.dx;
  ps.rho.assign(nLocal, ps.wallRho);
  ps.volume.assign(nLocal, wallArea);
  for (std::size_t a = 0; a < ps.nMaterial; ++a) {
    ps.rho[a] = materials[static_cast<std::size_t>(cloud.material[a])].rho();
    ps.volume[a] = cloud.mass[a] / ps.rho[a];
  }
  std::unordered_map<label, std::size_t> wallAt;
  for (std::size_t w = ps.wallBegin(); w < ps.dummyBegin(); ++w) wallAt[cloud.origId[w]] = w;
  ps.parentWall.assign(nLocal, -1);
  for (std::size_t d = ps.dummyBegin(); d < nLocal; ++d) {
    const auto it = wallAt.find(parentId_[d]);
    if (it == wallAt.end()) {
      fatalError(fmt::format("rank {}: dummy particle {} arrived without its wall particle {}", thisRank(),
                             cloud.origId[d], parentId_[d]));
    }
    ps.parentWall[d] = static_cast<int>(it->second);
  }
  markFrictionWalls(ps);
  ghostSum_ += static_cast<long>(halo_->nGhosts());
  ++steps_;
}

std::string DistributedParticles::balanceSummary() const {
  const long ghosts = sumOverRanks(ghostSum_);
  return fmt::format(
      "Partition balance (largest load / mean load): {:.3f} now, {:.3f} at worst (before a repartition), {:.3f} on "
      "average after {} checks; "
      "{} repartition(s); {:.0f} ghost particles per step over all ranks",
      lastImbalance_, worstImbalance_, checks_ > 0 ? imbalanceSum_ / checks_ : lastImbalance_, checks_, repartitions_,
      steps_ > 0 ? static_cast<double>(ghosts) / static_cast<double>(steps_) : 0.0);
}

}  // namespace isph
