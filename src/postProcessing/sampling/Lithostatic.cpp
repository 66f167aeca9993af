#include "postProcessing/sampling/Lithostatic.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <fmt/format.h>

#include "core/Error.hpp"

namespace isph {

LithostaticError lithostaticError(const ParticleCloud& cloud, const LithostaticSpec& spec) {
  if (!(spec.rho > 0)) fatalError(fmt::format("lithostatic error: rho must be positive (got {})", spec.rho));
  if (!(spec.height > 0)) fatalError(fmt::format("lithostatic error: height must be positive (got {})", spec.height));
  if (!(spec.normal.norm() > 0)) fatalError("lithostatic error: the bed normal is the zero vector");
  const Vec3 n = spec.normal.normalized();
  const double gNormal = -spec.g.dot(n);  // |g| cos(beta)
  if (!(gNormal > 0)) fatalError("lithostatic error: gravity does not point into the bed (g . normal >= 0)");
  const auto material = label(ParticleKind::material);

  LithostaticError e;
  bool any = false;
  e.surface = -1e300;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.kind[i] != material) continue;
    e.surface = std::max(e.surface, cloud.positions[i].dot(n));
    any = true;
  }
  if (!any) fatalError("lithostatic error: the cloud has no material particle");

  const double scale = spec.rho * spec.g.norm() * spec.height;
  double sumError2 = 0, sumExact2 = 0, minDev = 1e300, maxDev = -1e300;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.kind[i] != material) continue;
    const double depth = e.surface - cloud.positions[i].dot(n);
    const double exact = spec.rho * gNormal * depth;
    sumError2 += (cloud.p[i] - exact) * (cloud.p[i] - exact);
    sumExact2 += exact * exact;
    const double x = cloud.positions[i].x();
    if (x > spec.xMin && x < spec.xMax && depth > spec.minDepth) {
      minDev = std::min(minDev, (cloud.p[i] - exact) / scale);
      maxDev = std::max(maxDev, (cloud.p[i] - exact) / scale);
      ++e.interior;
    }
  }
  if (e.interior == 0) {
    fatalError(fmt::format("lithostatic error: no material particle in the interior (x in ({}, {}), depth > {})",
                           spec.xMin, spec.xMax, spec.minDepth));
  }
  e.l2 = sumExact2 > 0 ? std::sqrt(sumError2 / sumExact2) : std::sqrt(sumError2);
  e.spread = maxDev - minDev;
  return e;
}

double largestDisplacement(const ParticleCloud& start, const ParticleCloud& end) {
  const auto material = label(ParticleKind::material);
  std::unordered_map<label, Vec3> initial;
  for (std::size_t i = 0; i < start.size(); ++i) {
    if (start.kind[i] == material) initial[start.origId[i]] = start.positions[i];
  }
  double largest = 0;
  for (std::size_t i = 0; i < end.size(); ++i) {
    if (end.kind[i] != material) continue;
    const auto it = initial.find(end.origId[i]);
    if (it == initial.end()) {
      fatalError(fmt::format("displacement: material particle {} is not in the reference cloud", end.origId[i]));
    }
    largest = std::max(largest, (end.positions[i] - it->second).norm());
  }
  return largest;
}

}  // namespace isph
