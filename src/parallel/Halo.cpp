#include "parallel/Halo.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <limits>

#include "core/Error.hpp"
#include "parallel/Reduce.hpp"

namespace isph {

namespace {

struct Box {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::infinity());
  bool holds(const Vec3& x, int dimension) const {
    for (int d = 0; d < dimension; ++d) {
      if (x[d] < lo[d] || x[d] > hi[d]) return false;
    }
    return true;
  }
};

// Every rank's bounding box of its particles, grown by `radius` (empty for a rank without any).
std::vector<Box> grownBoxes(const std::vector<Vec3>& x, double radius) {
  Box mine;
  for (const Vec3& p : x) {
    mine.lo = mine.lo.cwiseMin(p);
    mine.hi = mine.hi.cwiseMax(p);
  }
  if (!x.empty()) {
    mine.lo.array() -= radius;
    mine.hi.array() += radius;
  }
  std::vector<Box> all(static_cast<std::size_t>(nRanks()));
  if (distributedRun()) {
    MPI_Allgather(&mine, 6, MPI_DOUBLE, all.data(), 6, MPI_DOUBLE, MPI_COMM_WORLD);
  } else {
    all[0] = mine;
  }
  return all;
}

}  // namespace

Halo::Halo(const std::vector<Vec3>& positions, double radius, int dimension, const std::vector<int>& companion) {
  static_assert(sizeof(Box) == 6 * sizeof(double));
  if (!companion.empty() && companion.size() != positions.size()) {
    fatalError("Halo: the companions and the positions differ in length");
  }
  const std::vector<Box> boxes = grownBoxes(positions, radius);
  const int me = thisRank();
  std::vector<int> destination;
  std::vector<char> marked(positions.size());
  for (int r = 0; r < static_cast<int>(boxes.size()); ++r) {
    if (r == me) continue;
    std::fill(marked.begin(), marked.end(), 0);
    bool any = false;
    for (std::size_t i = 0; i < positions.size(); ++i) {
      if (boxes[static_cast<std::size_t>(r)].holds(positions[i], dimension)) marked[i] = any = true;
    }
    if (!any) continue;
    if (!companion.empty()) {
      for (std::size_t i = 0; i < positions.size(); ++i) {
        if (marked[i] == 1 && companion[i] >= 0) {
          const auto c = static_cast<std::size_t>(companion[i]);
          if (!marked[c]) marked[c] = 2;  // (a companion does not bring its own)
        }
      }
    }
    for (std::size_t i = 0; i < positions.size(); ++i) {
      if (marked[i]) {
        sent_.push_back(i);
        destination.push_back(r);
      }
    }
  }
  plan_ = std::make_unique<CommPlan>(destination);
  destination_ = std::move(destination);
}

void Halo::sendParticles(const ParticleFields& owned, ParticleFields& ghosts) const {
  const std::vector<std::byte> out = owned.pack(sent_);
  std::vector<std::byte> in(plan_->nReceived() * owned.bytesPerParticle());
  plan_->exchange(out.data(), owned.bytesPerParticle(), in.data());
  if (ghosts.bytesPerParticle() != owned.bytesPerParticle()) fatalError("Halo::sendParticles: the field sets differ");
  ghosts.append(in.data(), plan_->nReceived());
}

void Halo::setLayout(std::vector<std::size_t> sendLocal, std::vector<std::size_t> ghostLocal, std::size_t nLocal,
                     std::size_t nMaterial) {
  if (sendLocal.size() != nSent() || ghostLocal.size() != nGhosts()) {
    fatalError(fmt::format("Halo::setLayout: {} sent and {} ghost places for {} sent and {} ghosts", sendLocal.size(),
                           ghostLocal.size(), nSent(), nGhosts()));
  }
  nLocal_ = nLocal;
  nMaterial_ = nMaterial;
  // The material items keep their order in both lists (a plan orders by source rank, then by
  // send order), so the material plan's k-th ghost is the k-th material ghost of the whole.
  std::vector<int> destination;
  material_.from.clear();
  material_.to.clear();
  for (std::size_t k = 0; k < sendLocal.size(); ++k) {
    if (sendLocal[k] < nMaterial) {
      material_.from.push_back(sendLocal[k]);
      destination.push_back(destination_[k]);
    }
  }
  for (const std::size_t g : ghostLocal) {
    if (g < nMaterial) material_.to.push_back(g);
  }
  materialPlan_ = std::make_unique<CommPlan>(destination);
  if (materialPlan_->nReceived() != material_.to.size()) {
    fatalError(fmt::format("Halo::setLayout: {} material ghosts placed, {} received", material_.to.size(),
                           materialPlan_->nReceived()));
  }
  material_.plan = materialPlan_.get();
  all_.plan = plan_.get();
  all_.from = std::move(sendLocal);
  all_.to = std::move(ghostLocal);
  laidOut_ = true;
}

const Halo::Exchange& Halo::exchangeFor(std::size_t length) const {
  if (!laidOut_) fatalError("Halo::exchange before setLayout");
  if (length == nLocal_) return all_;
  if (length == nMaterial_) return material_;
  fatalError(fmt::format("Halo::exchange: a field of {} values, expected {} (all particles) or {} (material)", length,
                         nLocal_, nMaterial_));
}

}  // namespace isph
