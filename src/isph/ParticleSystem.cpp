#include "isph/ParticleSystem.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/Error.hpp"
#include "parallel/Reduce.hpp"
#include "sph/neighbours/NearestPoints.hpp"

namespace isph {

namespace {

// Σ_b V W(|x_b|) over an ideal lattice around the origin (self included).
double idealLatticeSum(const Kernel& kernel, double dx, const std::string& lattice, int dimension) {
  const int n = static_cast<int>(std::ceil(kernel.supportRadius() / dx)) + 1;
  double sum = 0;
  if (dimension == 3) {
    for (int i = -n; i <= n; ++i)
      for (int j = -n; j <= n; ++j)
        for (int k = -n; k <= n; ++k) sum += dx * dx * dx * kernel.W(dx * std::sqrt(double(i * i + j * j + k * k)));
    return sum;
  }
  if (lattice == "hexagonal") {
    const double dy = dx * std::sqrt(3.0) / 2.0;
    for (int j = -n - 1; j <= n + 1; ++j)
      for (int i = -n - 1; i <= n + 1; ++i) {
        const double x = dx * (i + 0.5 * (j & 1)), y = dy * j;
        sum += dx * dy * kernel.W(std::hypot(x, y));
      }
    return sum;
  }
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j) sum += dx * dx * kernel.W(dx * std::hypot(double(i), double(j)));
  return sum;
}

}  // namespace

void initialiseParticleSystem(ParticleSystem& ps, const MaterialTable& materials, const Kernel& kernel) {
  ParticleCloud& c = ps.cloud;
  ps.dimension = c.properties.dimension;
  ps.dx = c.properties.spacing;
  if (!(ps.dx > 0)) fatalError(fmt::format("cloud '{}': the spacing in cloudProperties must be positive", c.name));

  // material | wall | dummy, each group in its input order.
  std::vector<int> order(c.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return c.kind[static_cast<std::size_t>(a)] < c.kind[static_cast<std::size_t>(b)];
  });
  c.permute(order);
  ps.nMaterial = static_cast<std::size_t>(std::count(c.kind.begin(), c.kind.end(), label(ParticleKind::material)));
  ps.nWall = static_cast<std::size_t>(std::count(c.kind.begin(), c.kind.end(), label(ParticleKind::wall)));
  ps.nDummy = c.size() - ps.nMaterial - ps.nWall;
  if (sumOverRanks(ps.nMaterial) == 0) {  // (a rank of a parallel run may hold none)
    fatalError(fmt::format("cloud '{}' has no material particles: nothing to simulate", c.name));
  }

  // Densities and volumes; walls take the materials' bulk density, total mass over total volume.
  const std::size_t n = c.size();
  ps.rho.assign(n, 0.0);
  ps.volume.assign(n, 0.0);
  double mass = 0, volume = 0;
  for (std::size_t a = 0; a < ps.nMaterial; ++a) {
    ps.rho[a] = materials[static_cast<std::size_t>(c.material[a])].rho();
    if (!(c.mass[a] > 0)) fatalError(fmt::format("cloud '{}': material particle {} has mass {}", c.name, a, c.mass[a]));
    ps.volume[a] = c.mass[a] / ps.rho[a];
    mass += c.mass[a];
    volume += ps.volume[a];
  }
  ps.wallRho = sumOverRanks(mass) / sumOverRanks(volume);
  const double wallArea = ps.dimension == 3 ? ps.dx * ps.dx * ps.dx : ps.dx * ps.dx;
  for (std::size_t a = ps.nMaterial; a < n; ++a) {
    ps.rho[a] = ps.wallRho;
    ps.volume[a] = wallArea;
  }
  ps.latticeSum = idealLatticeSum(kernel, ps.dx, c.properties.lattice, ps.dimension);

  // Each dummy particle extends the nearest wall particle (walls do not move: done once);
  // equally near walls are told apart by origId, so that a rank of a parallel run that holds
  // a dummy and its wall finds the same one (src/isph/parallel).
  ps.parentWall.assign(n, -1);
  if (ps.nWall > 0 && ps.nDummy > 0) {
    const auto first = [&](std::size_t i) { return c.positions.begin() + static_cast<long>(i); };
    const std::vector<Vec3> walls(first(ps.nMaterial), first(ps.dummyBegin()));
    const std::vector<label> wallIds(c.origId.begin() + static_cast<long>(ps.nMaterial),
                                     c.origId.begin() + static_cast<long>(ps.dummyBegin()));
    const std::vector<Vec3> dummies(first(ps.dummyBegin()), c.positions.end());
    const double radius = 2.0 * kernel.supportRadius();  // reaches the corners of the dummy layers
    const std::vector<int> parent = nearestPoints(walls, wallIds, dummies, radius, ps.dimension);
    for (std::size_t d = 0; d < ps.nDummy; ++d) {
      if (parent[d] < 0) {
        fatalError(fmt::format("cloud '{}': dummy particle at ({:.4g} {:.4g}) has no wall particle within {:.3g} m",
                               c.name, dummies[d].x(), dummies[d].y(), radius));
      }
      ps.parentWall[ps.dummyBegin() + d] = static_cast<int>(ps.nMaterial) + parent[d];
    }
  }
}

void markFrictionWalls(ParticleSystem& ps) {
  ps.frictionWall.assign(ps.size(), 0);
  for (std::size_t b = ps.wallBegin(); b < ps.size(); ++b) {
    const std::size_t w = ps.isWall(b) ? b : static_cast<std::size_t>(ps.parentWall[b]);
    const label patch = ps.cloud.patch[w];
    ps.frictionWall[b] = patch >= 0 && ps.cloud.properties.patches[static_cast<std::size_t>(patch)].frictionAngle > 0;
  }
}

std::vector<int> reorderMaterialParticles(ParticleSystem& ps, double cellSize) {
  std::vector<Vec3> x(ps.cloud.positions.begin(), ps.cloud.positions.begin() + static_cast<long>(ps.nMaterial));
  const std::vector<int> materialOrder = cellOrder(x, cellSize, ps.dimension);
  std::vector<int> order(ps.size());
  std::iota(order.begin(), order.end(), 0);
  std::copy(materialOrder.begin(), materialOrder.end(), order.begin());
  ps.cloud.permute(order);
  std::vector<double> rho(ps.rho), vol(ps.volume);
  for (std::size_t i = 0; i < ps.nMaterial; ++i) {
    ps.rho[i] = rho[static_cast<std::size_t>(order[i])];
    ps.volume[i] = vol[static_cast<std::size_t>(order[i])];
  }
  return materialOrder;
}

}  // namespace isph
