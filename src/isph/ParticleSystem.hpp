#pragma once
// The particles as the solver sees them: the cloud (ordered material | wall | dummy), the
// per-particle density and volume that the SPH sums use, the dummy-to-wall association,
// and the neighbour list of the current step.
#include <vector>

#include "core/Types.hpp"
#include "isph/materials/MaterialTable.hpp"
#include "parallel/Halo.hpp"
#include "particles/ParticleCloud.hpp"
#include "sph/kernels/Kernel.hpp"
#include "sph/neighbours/NeighbourList.hpp"

namespace isph {

struct ParticleSystem {
  ParticleCloud cloud;
  int dimension = 2;
  double dx = 0;
  std::size_t nMaterial = 0;  // particles [0, nMaterial) are material
  std::size_t nWall = 0;      // [nMaterial, nMaterial + nWall) are wall particles
  std::size_t nDummy = 0;     // the rest are dummy particles

  std::vector<double> rho;     // material: its density; wall and dummy: the wall reference density
  std::vector<double> volume;  // m/ρ (material), the area of a wall site (walls)
  std::vector<int> parentWall; // dummy particle -> the wall particle it extends (-1 for others)
  double wallRho = 0;          // the wall reference density: the materials' bulk density, Σm / Σ(m/ρ)
  std::vector<double> wallPullLimit;  // the most suction a wall may exert (WallBoundaryPressure)
  std::vector<Vec3> wallTangentialGradient;  // ∇p along a friction wall as seen from a (WallBoundaryPressure)
  std::vector<char> frictionWall;  // boundary particle of a patch with a friction angle
  double latticeSum = 1;       // Σ_b V_b W_ab of a full lattice (self included): θ = 1 at rest

  NeighbourList neighbours;

  // A parallel run (doc/parallel.md, src/isph/parallel): each kind's particles are this
  // rank's own first, then its ghosts, copies of other ranks' particles within the kernel
  // support: material [0, nOwnedMaterial) own and [nOwnedMaterial, nMaterial) ghosts, walls
  // [wallBegin(), wallBegin() + nOwnedWall) own, dummies likewise. A loop over the material
  // computes the ghosts' entries too (from their empty neighbour rows, NeighbourList.hpp:
  // wrong), and exchangeGhosts (isph/parallel/GhostExchange.hpp) then gives them their owners' values before
  // a pair loop reads them. The linear systems hold the own material particles' rows, numbered
  // from firstRow over all ranks (globalRow). In a serial run everything is owned, firstRow 0.
  std::size_t nOwnedMaterial = 0, nOwnedWall = 0, nOwnedDummy = 0;  // (set with halo)
  long firstRow = 0;
  std::vector<long> ghostRow;    // the global row of each ghost material particle
  const Halo* halo = nullptr;    // null in a serial run
  // The own particles of each kind (all of them in a serial run).
  std::size_t ownMaterial() const { return halo ? nOwnedMaterial : nMaterial; }
  std::size_t ownWall() const { return halo ? nOwnedWall : nWall; }
  std::size_t ownDummy() const { return halo ? nOwnedDummy : nDummy; }
  long globalRow(std::size_t a) const {
    return a < ownMaterial() ? firstRow + static_cast<long>(a) : ghostRow[a - nOwnedMaterial];
  }
  bool isOwned(std::size_t a) const {
    return !halo || a < nOwnedMaterial || (a >= wallBegin() && a < wallBegin() + nOwnedWall) ||
           (a >= dummyBegin() && a < dummyBegin() + nOwnedDummy);
  }

  std::size_t size() const { return cloud.size(); }
  bool isMaterial(std::size_t a) const { return a < nMaterial; }
  bool isWall(std::size_t a) const { return a >= nMaterial && a < nMaterial + nWall; }
  bool isDummy(std::size_t a) const { return a >= nMaterial + nWall; }
  std::size_t wallBegin() const { return nMaterial; }
  std::size_t dummyBegin() const { return nMaterial + nWall; }
};

// Orders the cloud material | wall | dummy, sets densities, volumes, the lattice sum and the
// dummy-to-wall association. FatalError if the cloud has no material particles.
void initialiseParticleSystem(ParticleSystem& ps, const MaterialTable& materials, const Kernel& kernel);

// Marks the wall and dummy particles of patches with a friction angle (ps.frictionWall; a
// dummy particle by its wall particle's patch).
void markFrictionWalls(ParticleSystem& ps);

// Reorders the material particles by cell so that neighbours sit close in memory. Returns
// the permutation of the material particles, order[new] = old, for the callers' own arrays.
std::vector<int> reorderMaterialParticles(ParticleSystem& ps, double cellSize);

}  // namespace isph
