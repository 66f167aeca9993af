#pragma once
// Finds the free-surface particles, where the PPE holds p = 0 (the paper: "finding the
// free surface particles and then equating all stresses to zero"). A particle is on the
// surface when
//  - the divergence of position, ∇·r_a = −Σ_b V_b x_ab·∇_a W_ab (≈ d inside), is below the
//    threshold (Lee et al. 2008; 1.5 in 2D), or
//  - it has fewer neighbours than a set share of a full lattice neighbourhood (splash), or
//  - 2D: one of the eight 45° sectors of its support holds no particle of any kind. This
//    catches the waterline against a wall, where the wall particles above the surface fill
//    part of the missing support and lift ∇·r over 1.5, without flagging material crowded
//    against a wall (particleMesh leaves it half a spacing from the wall particles), which
//    a colour-gradient test |∇C| h > threshold takes for a surface and so pins p = 0 inside.
//  - 3D: one of the 26 lattice directions of its support holds no particle (the 2D scan's
//    counterpart; a wall or dummy particle fills a direction of a material particle only
//    where the direction's axis points into its wall, so that a side wall beside the
//    water's surface does not close the way up), or |∇C| h is above its
//    threshold, confirmed by a probe at
//    x_a + h n, n = −∇C/|∇C|, with no particle of any kind within h (a simplified scan of
//    Marrone et al. 2010; walls fill the support as in the 2D scan, or material against a
//    wall would be taken for a surface).
// Wall and dummy particles count as neighbours.
#include <vector>

#include "isph/ParticleSystem.hpp"

namespace isph {

class FreeSurfaceDetector {
 public:
  FreeSurfaceDetector(double threshold, double gradientThreshold, double minNeighbourFraction,
                      int fullNeighbourCount, double h);

  // Flags for all particles: material 1 = free surface, 0 = interior; wall particles 1 where no
  // material is within their support (inactive); dummies 0.
  void detect(const ParticleSystem& ps);

  const std::vector<char>& flags() const { return flags_; }  // (parallel: the owners' flags at ghosts)
  const std::vector<double>& divergence() const { return divR_; }
  std::size_t nSurfaceMaterial() const { return nSurface_; }  // over all ranks

 private:
  double threshold_;
  double gradientThreshold_;
  double h_;
  double minNeighbours_;
  std::vector<char> flags_;
  std::vector<double> divR_;
  std::size_t nSurface_ = 0;
};

// The 2D sector scan's sector (0-7) of the direction (x, y): 45° sectors centred on the
// lattice directions, sector k spanning the angles θ with θ + π + π/8 in [kπ/4, (k+1)π/4),
// θ = atan2(y, x). By the signs and magnitudes of the direction turned by π/8, without atan2
// (which cost 2.4 % of a barrier run); a direction on an edge between two sectors may fall in
// either.
int supportSector(double x, double y);

// The 3D scan's direction (0-26) of v: each component −1, 0 or +1 by whether it exceeds
// tan(π/8) times the largest (cones about the cubic lattice's face, edge and corner
// directions), as 9 (z + 1) + 3 (y + 1) + x + 1; 13 only for the zero vector.
int latticeDirection(const Vec3& v);

// Neighbours of a particle inside a full lattice (self excluded), for the safety net.
int fullLatticeNeighbourCount(const Kernel& kernel, double dx, const std::string& lattice, int dimension);

}  // namespace isph
