#include "isph/discretisation/FreeSurfaceDetector.hpp"

#include <cmath>
#include <cstdint>

#include "isph/parallel/GhostExchange.hpp"
#include "parallel/Reduce.hpp"

namespace isph {

namespace {
// The 26 lattice directions of latticeDirection (bit 13, the zero vector, left out).
constexpr std::uint32_t allLatticeDirections = ((1u << 27) - 1) & ~(1u << 13);
}  // namespace

FreeSurfaceDetector::FreeSurfaceDetector(double threshold, double gradientThreshold, double minNeighbourFraction,
                                         int fullNeighbourCount, double h)
    : threshold_(threshold),
      gradientThreshold_(gradientThreshold),
      h_(h),
      minNeighbours_(minNeighbourFraction * fullNeighbourCount) {}

void FreeSurfaceDetector::detect(const ParticleSystem& ps) {
  const std::size_t n = ps.size();
  flags_.assign(n, 0);
  divR_.assign(n, 0.0);
  const auto& x = ps.cloud.positions;
  const auto& nl = ps.neighbours;
  // Wall particles: 1 where no material is within the support (an inactive wall); their rows
  // hold the material only (NeighbourList.hpp). Dummies: 0.
  for (std::size_t a = ps.wallBegin(); a < ps.dummyBegin(); ++a) flags_[a] = nl.start[a + 1] == nl.start[a];
  const long active = static_cast<long>(ps.nMaterial);
  long surface = 0;
#pragma omp parallel for schedule(static) reduction(+ : surface)
  for (long a = 0; a < active; ++a) {
    const auto ua = static_cast<std::size_t>(a);
    double div = 0;
    Vec3 gradC = Vec3::Zero();
    for (long k = nl.start[ua]; k < nl.start[ua + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const auto b = static_cast<std::size_t>(nl.index[kk]);
      const Vec3 xab = x[ua] - x[b];
      div -= ps.volume[b] * nl.F[kk] * xab.squaredNorm();
      gradC += ps.volume[b] * nl.F[kk] * xab;
    }
    divR_[ua] = div;
    const double count = double(nl.start[ua + 1] - nl.start[ua]);
    bool isSurface = div < threshold_ || count < minNeighbours_;
    if (!isSurface && ps.dimension == 2) {
      // Sector scan: an empty 45° sector of the support (no particle of any kind) is an
      // opening to the outside.
      unsigned occupied = 0;
      for (long k = nl.start[ua]; k < nl.start[ua + 1]; ++k) {
        const Vec3 xba = x[static_cast<std::size_t>(nl.index[static_cast<std::size_t>(k)])] - x[ua];
        // sectors centred on the lattice directions, so that no lattice neighbour sits on an edge
        occupied |= 1u << static_cast<unsigned>(supportSector(xba.x(), xba.y()));
      }
      isSurface = occupied != 0xffu;
    } else if (!isSurface) {
      // 3D: one of the 26 lattice directions of the support holds no particle of any kind (the
      // 2D scan's counterpart: the waterline against a wall), or the colour gradient confirmed
      // by a probe region empty of particles of any kind (Marrone et al. 2010, with the walls
      // filling the support: material half a spacing from a wall has its gradient into it).
      // Seen from material, a wall or dummy particle fills its direction only where that
      // direction's axis points into its wall: a side wall standing above the water lies in
      // the surface particles' upward cone (two rows up, 14° off the axis) but does not close
      // it (doc/notes/threeD.md: a slab one spacing wide found no surface at all).
      std::uint32_t occupied = 0;
      for (long k = nl.start[ua]; k < nl.start[ua + 1]; ++k) {
        const auto b = static_cast<std::size_t>(nl.index[static_cast<std::size_t>(k)]);
        const int direction = latticeDirection(x[b] - x[ua]);
        if (!ps.isMaterial(b)) {
          const Vec3& n = ps.isWall(b) ? ps.cloud.normal[b] : ps.cloud.normal[static_cast<std::size_t>(ps.parentWall[b])];
          const Vec3 axis(direction % 3 - 1, direction / 3 % 3 - 1, direction / 9 - 1);
          if (axis.dot(n) > -1e-9) continue;
        }
        occupied |= 1u << direction;
      }
      isSurface = occupied != allLatticeDirections;
      if (!isSurface && gradC.norm() * h_ > gradientThreshold_) {
        const Vec3 probe = x[ua] - h_ * gradC.normalized();
        isSurface = true;
        for (long k = nl.start[ua]; k < nl.start[ua + 1] && isSurface; ++k) {
          const auto b = static_cast<std::size_t>(nl.index[static_cast<std::size_t>(k)]);
          isSurface = (x[b] - probe).squaredNorm() >= h_ * h_;
        }
      }
    }
    flags_[ua] = isSurface;
    surface += isSurface && ua < ps.ownMaterial();  // (parallel: the own particles)
  }
  nSurface_ = sumOverRanks(static_cast<std::size_t>(surface));
  exchangeGhosts(ps, flags_);  // parallel: a ghost's flag from its whole neighbourhood, on its rank
}

int latticeDirection(const Vec3& v) {
  // Each component −1, 0 or +1 by whether it exceeds tan(π/8) times the largest: cones about the
  // face (6), edge (12) and corner (8) directions of a cubic lattice, numbered 0-26 (13 is none).
  const double limit = std::tan(M_PI / 8) * v.cwiseAbs().maxCoeff();
  auto sign = [&](double c) { return c > limit ? 2 : c < -limit ? 0 : 1; };
  return 9 * sign(v.z()) + 3 * sign(v.y()) + sign(v.x());
}

int supportSector(double x, double y) {
  // w = −(x, y) turned by π/8: sector k is the octant [kπ/4, (k+1)π/4) of w's angle.
  static const double c = std::cos(M_PI / 8), s = std::sin(M_PI / 8);
  const double wx = -(c * x - s * y), wy = -(s * x + c * y);
  if (wy >= 0) return wx > 0 ? (wy < wx ? 0 : 1) : (wy > -wx ? 2 : 3);
  return wx < 0 ? (-wy < -wx ? 4 : 5) : (-wy > wx ? 6 : 7);
}

int fullLatticeNeighbourCount(const Kernel& kernel, double dx, const std::string& lattice, int dimension) {
  const double R = kernel.supportRadius();
  const int n = static_cast<int>(std::ceil(R / dx)) + 1;
  int count = 0;
  if (dimension == 3) {
    for (int i = -n; i <= n; ++i)
      for (int j = -n; j <= n; ++j)
        for (int k = -n; k <= n; ++k) count += dx * std::sqrt(double(i * i + j * j + k * k)) < R;
  } else if (lattice == "hexagonal") {
    const double dy = dx * std::sqrt(3.0) / 2.0;
    for (int j = -n - 1; j <= n + 1; ++j)
      for (int i = -n - 1; i <= n + 1; ++i) count += std::hypot(dx * (i + 0.5 * (j & 1)), dy * j) < R;
  } else {
    for (int i = -n; i <= n; ++i)
      for (int j = -n; j <= n; ++j) count += dx * std::hypot(double(i), double(j)) < R;
  }
  return count - 1;
}

}  // namespace isph
