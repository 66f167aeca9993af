#include "isph/walls/WallBoundaryPressure.hpp"

namespace isph {

void updateWallPressure(ParticleSystem& ps, const std::vector<Vec3>& ustar, const Vec3& g, double dt) {
  auto& c = ps.cloud;
  const auto& nl = ps.neighbours;
  const long first = static_cast<long>(ps.wallBegin());
  const long last = static_cast<long>(ps.size());
#pragma omp parallel for schedule(static)
  for (long bl = first; bl < last; ++bl) {
    const auto b = static_cast<std::size_t>(bl);
    double sum = 0, weight = 0;
    for (long k = nl.start[b]; k < nl.start[b + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const auto a = static_cast<std::size_t>(nl.index[kk]);
      if (!ps.isMaterial(a) || !facesMaterial(ps, b, a)) continue;
      const double w = ps.volume[a] * nl.W[kk];
      sum += w * (c.p[a] + wallPressureIncrement(ps, ustar, g, a, b, dt));
      weight += w;
    }
    c.p[b] = weight > 0 ? sum / weight : 0.0;
  }
}

}  // namespace isph
