#include "particleGeneration/LithostaticPressure.hpp"

#include <algorithm>

namespace isph {

namespace {

// Density at p: that of the first region holding it, 0 outside all.
double densityAt(const Vec3& p, const std::vector<const Region*>& regions,
                 const std::vector<double>& densities) {
  for (std::size_t r = 0; r < regions.size(); ++r) {
    if (regions[r]->contains(p)) return densities[r];
  }
  return 0.0;
}

double columnWeight(const Vec2& x, const std::vector<const Region*>& regions,
                    const std::vector<double>& densities, const Vec3& up, std::vector<double>& t) {
  const Vec3 o = toVec3(x);
  t.assign(1, 0.0);
  for (const Region* r : regions) r->rayCrossings(o, up, t);
  std::sort(t.begin(), t.end());
  double weight = 0;  // ∫ ρ ds
  for (std::size_t k = 0; k + 1 < t.size(); ++k) {
    const double length = t[k + 1] - t[k];
    if (length <= 0) continue;
    weight += length * densityAt(o + 0.5 * (t[k] + t[k + 1]) * up, regions, densities);
  }
  return weight;
}

}  // namespace

std::vector<double> lithostaticPressure(const std::vector<Vec2>& points,
                                        const std::vector<const Region*>& regions,
                                        const std::vector<double>& densities, const Vec2& up,
                                        double g) {
  std::vector<double> p(points.size(), 0.0);
  const Vec3 direction = toVec3(up.normalized());
  const long n = static_cast<long>(points.size());
#pragma omp parallel
  {
    std::vector<double> t;
#pragma omp for schedule(static)
    for (long i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      p[k] = g * columnWeight(points[k], regions, densities, direction, t);
    }
  }
  return p;
}

}  // namespace isph
