#pragma once
// Every particle's neighbours within the kernel support, found through a CellGrid and
// stored once per step as compressed rows with the kernel value and gradient factor of
// each pair, so that every pass of the step (density, gradients, PPE, forces) reuses
// them. No O(N²) search anywhere.
//
// For particle a, pairs k in [start[a], start[a+1]): b = index[k],
//   W_ab = W[k],  ∇_a W_ab = F[k] * (x_a − x_b)   (F = W'(r)/r ≤ 0).
// The particle itself is not in its own list; its self-contribution W(0) is kernel().W(0).
//
// Given `nMaterial` (particles [0, nMaterial) are material, the rest wall and dummy particles,
// ParticleSystem.hpp), the rows of the others hold their material neighbours only, in the
// order of a whole row: a wall or dummy particle takes from the material (its pressure, the
// friction, the wall stress) and nothing from another wall, and the method reads no other
// pair (doc/notes/stepCost.md). In a 3D slab that is 71 % of the particles and most of the
// pairs.
#include <cstddef>
#include <limits>
#include <vector>

#include "core/Types.hpp"
#include "sph/kernels/Kernel.hpp"

namespace isph {

class NeighbourList {
 public:
  // Pairs closer than the kernel support. Parallel over particles (OpenMP), deterministic.
  // Rows of particles from `nMaterial` on: their material neighbours only (every row whole by
  // default). With `withRow`, a particle whose entry is 0 gets an empty row (a parallel run's
  // ghosts: every value a ghost's row would give is exchanged from its owner or not read,
  // doc/notes/stepCost.md); it stays a neighbour in the other rows.
  void build(const std::vector<Vec3>& positions, const Kernel& kernel,
             std::size_t nMaterial = std::numeric_limits<std::size_t>::max(),
             const std::vector<char>* withRow = nullptr);

  std::size_t nParticles() const { return start.empty() ? 0 : start.size() - 1; }
  std::size_t nPairs() const { return index.size(); }
  double meanNeighbours() const { return nParticles() ? double(nPairs()) / double(nParticles()) : 0.0; }

  std::vector<long> start;
  std::vector<int> index;
  std::vector<double> W;
  std::vector<double> F;
};

// A permutation that orders particles cell by cell (cells x fastest) so that neighbours
// sit close in memory; order[newIndex] = oldIndex.
std::vector<int> cellOrder(const std::vector<Vec3>& positions, double cellSize, int dimension);

}  // namespace isph
