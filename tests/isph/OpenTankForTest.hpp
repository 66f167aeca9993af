#pragma once
// Water in an open tank, hand-built as particleMesh lays it (WallLayers.hpp), 2D, Wendland C2
// with h = 1.3 dx, dx = 0.01 m: a 12 × 12 block of water (material particle j n + i at
// ((i + ½) dx, (j + ½) dx)) on a bed at y = 0 between side walls at x = 0 and x = n dx up to
// y = (n + 1) dx, wall particles on the surfaces, two dummy layers dx apart behind them, arcs of
// dummies round the two inside corners; its top row flagged as the free surface (`surface`).
// At rest, p = 0, frictionless walls. OpenTank(OpenTank::ThreeD{}) builds the same tank in 3D.
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "MaterialTableForTest.hpp"
#include "isph/discretisation/KernelGradientCorrection.hpp"
#include "isph/ParticleSystem.hpp"
#include "sph/kernels/Kernel.hpp"

namespace isph::test {

constexpr double dx = 0.01, rho = 1000;
constexpr int n = 12;  // material particles across and over the depth
inline const Vec3 g(0, -9.81, 0);

// The open tank: material particle j n + i at ((i + ½) dx, (j + ½) dx), the bed at y = 0 and
// the side walls at x = 0 and x = n dx up to y = (n + 1) dx, as generateWallLayers builds
// them for three layers (h = 1.3 dx: support 2.6 dx). `jitter`: each material particle moved by
// up to this many dx in x and y (uniform, fixed seed), except the top row, the free surface,
// if `flatSurface`.
struct OpenTank {
  std::unique_ptr<Kernel> kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  std::unique_ptr<MaterialTable> materials;
  ParticleSystem ps;
  KernelGradientCorrection L;
  std::vector<char> surface;  // the top row
  int side = n;               // material particles across and over the depth

  explicit OpenTank(double jitter = 0, bool flatSurface = true) {
    materials = materialTable("openTank", "water { model newtonian; rho 1000; nu 1e-6; }", {"water"});
    ParticleCloud& c = ps.cloud;
    c.properties.materials = {"water"};
    c.properties.patches = {{"tank", 0.0}};
    c.properties.spacing = dx;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> shift(-jitter * dx, jitter * dx);
    label id = 0;
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        Vec3 x((i + 0.5) * dx, (j + 0.5) * dx, 0);
        if (jitter > 0 && (j < n - 1 || !flatSurface)) x += Vec3(shift(rng), shift(rng), 0);
        c.push_back(x, id++, Vec3::Zero(), 0.0, 0, ParticleKind::material, -1, Vec3::Zero(),
                    rho * dx * dx);
      }
    }
    const double W = n * dx;
    const int top = n + 1;  // the walls reach y = (n + 1) dx
    auto wall = [&](double x, double y, const Vec3& normal) {
      c.push_back(Vec3(x, y, 0), id++, Vec3::Zero(), 0.0, -1, ParticleKind::wall, 0, normal, 0);
    };
    auto dummy = [&](double x, double y) {
      c.push_back(Vec3(x, y, 0), id++, Vec3::Zero(), 0.0, -1, ParticleKind::dummy, 0, Vec3::Zero(),
                  0);
    };
    const double s = std::numbers::sqrt2 / 2;
    wall(0, 0, Vec3(s, s, 0));  // the corners: the mean of their two faces' normals
    wall(W, 0, Vec3(-s, s, 0));
    for (int k = 1; k < n; ++k) wall(k * dx, 0, Vec3(0, 1, 0));
    for (int k = 1; k <= top; ++k) {
      wall(0, k * dx, Vec3(1, 0, 0));
      wall(W, k * dx, Vec3(-1, 0, 0));
    }
    for (int l = 1; l <= 2; ++l) {
      for (int k = 0; k <= n; ++k) dummy(k * dx, -l * dx);
      for (int k = 0; k <= top; ++k) {
        dummy(-l * dx, k * dx);
        dummy(W + l * dx, k * dx);
      }
      // The arc of radius l dx about each inside corner, round(l π/2) parts, its ends on the
      // bed's and the wall's layers (already placed).
      const long parts = std::lround(l * std::numbers::pi / 2);
      for (long m = 1; m < parts; ++m) {
        const double angle =
            std::numbers::pi / 2 * static_cast<double>(m) / static_cast<double>(parts);
        const double ax = l * dx * std::cos(angle), ay = l * dx * std::sin(angle);
        dummy(-ax, -ay);
        dummy(W + ax, -ay);
      }
    }
    finish();
    for (int i = 0; i < n; ++i) surface[static_cast<std::size_t>((n - 1) * n + i)] = 1;
  }

  // The same tank in three dimensions, n3 particles along each side (z the second horizontal
  // direction): material particle (k n3 + j) n3 + i at ((i + ½) dx, (j + ½) dx, (k + ½) dx), the
  // bed at y = 0 and four side walls at x = 0, x = n3 dx, z = 0, z = n3 dx up to y = (n3 + 1) dx
  // (`layers` in z in place of n3: z = layers dx),
  // wall particles on the lattice of the walls' surfaces (edges and corners: the mean of their
  // faces' normals), dummies on that lattice behind them within 2 dx of the tank (the 3D
  // counterpart of the 2D tank's two layers and corner arcs).
  struct ThreeD {
    int n3 = 6;
    int layers = 0;  // material particles along z (0: n3); 1 is a slab one spacing wide
  };
  explicit OpenTank(ThreeD three) : kernel(makeKernel("WendlandC2", 1.3 * dx, 3)) {
    materials = materialTable("openTank", "water { model newtonian; rho 1000; nu 1e-6; }", {"water"});
    ParticleCloud& c = ps.cloud;
    c.properties.materials = {"water"};
    c.properties.patches = {{"tank", 0.0}};
    c.properties.spacing = dx;
    c.properties.dimension = 3;
    const int m = three.n3, mz = three.layers > 0 ? three.layers : m, top = m + 1;
    side = m;
    label id = 0;
    for (int k = 0; k < mz; ++k)
      for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i)
          c.push_back(Vec3((i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx), id++, Vec3::Zero(), 0.0, 0,
                      ParticleKind::material, -1, Vec3::Zero(), rho * dx * dx * dx);
    // Lattice sites (i, j, k) dx: on the tank's surface a wall particle, outside it within 2 dx
    // a dummy (the walls first: the particle system orders material, wall, dummy).
    auto outside = [&](int i, int j, int k) {  // distance outside the box, in dx
      const double ox = std::max({0, -i, i - m}), oy = std::max(0, -j), oz = std::max({0, -k, k - mz});
      return std::sqrt(ox * ox + oy * oy + oz * oz);
    };
    for (const bool walls : {true, false}) {
      for (int k = -2; k <= mz + 2; ++k)
        for (int j = -2; j <= top; ++j)
          for (int i = -2; i <= m + 2; ++i) {
            const Vec3 x(i * dx, j * dx, k * dx);
            const bool onSurface = outside(i, j, k) == 0 && (i == 0 || i == m || k == 0 || k == mz || j == 0);
            if (walls && onSurface) {
              const Vec3 normal = Vec3(i == 0 ? 1 : i == m ? -1 : 0, j == 0 ? 1 : 0, k == 0 ? 1 : k == mz ? -1 : 0).normalized();
              c.push_back(x, id++, Vec3::Zero(), 0.0, -1, ParticleKind::wall, 0, normal, 0);
            } else if (!walls && outside(i, j, k) > 0 && outside(i, j, k) <= 2 + 1e-9) {
              c.push_back(x, id++, Vec3::Zero(), 0.0, -1, ParticleKind::dummy, 0, Vec3::Zero(), 0);
            }
          }
    }
    finish();
    for (int k = 0; k < mz; ++k)
      for (int i = 0; i < m; ++i) surface[static_cast<std::size_t>((k * m + m - 1) * m + i)] = 1;
  }

  // The particle system's state at rest, p = 0 (as the solver starts), the neighbours and L.
  void finish() {
    initialiseParticleSystem(ps, *materials, *kernel);  // material first, in the order above
    ps.neighbours.build(ps.cloud.positions, *kernel);
    ps.frictionWall.assign(ps.size(), 0);  // frictionless: G_a = ρ g along the walls
    ps.wallPullLimit.assign(ps.size(),
                            0.0);  // the first step from p = 0 (the solver: pⁿ, 0 on the surface)
    ps.wallTangentialGradient.assign(ps.nMaterial, Vec3(rho * g));
    ps.cloud.p.assign(ps.size(), 0.0);
    L.update(ps, true, 0.25);
    surface.assign(ps.size(), 0);
  }
};

}  // namespace isph::test
