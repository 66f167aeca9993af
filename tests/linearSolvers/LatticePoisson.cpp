#include "LatticePoisson.hpp"

#include <cmath>
#include <vector>

namespace isph::test {

namespace {

struct Neighbour {
  int di, dj;
  double weight;  // c_ab > 0: A_aa += c, A_ab = -c
};

// u = x^2 + y^2 + sin(3x) cos(2y); f = -lap u.
double exactU(double x, double y) { return x * x + y * y + std::sin(3 * x) * std::cos(2 * y); }
double minusLaplacian(double x, double y) {
  return -4.0 + 13.0 * std::sin(3 * x) * std::cos(2 * y);
}

std::vector<Neighbour> stencilOf(Stencil stencil, double dx) {
  std::vector<Neighbour> out;
  if (stencil == Stencil::FivePoint) {
    const double c = 1.0 / (dx * dx);
    for (const auto& [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}})
      out.push_back({di, dj, c});
    return out;
  }
  // Wendland C2 derivative shape |W'(r)| ∝ q (1 - q/2)^3; constants cancel in the scaling.
  const double h = 1.3 * dx;
  double secondMoment = 0.0;  // sum c r^2, scaled to 2 * dimension = 4
  for (int dj = -2; dj <= 2; ++dj) {
    for (int di = -2; di <= 2; ++di) {
      const double r = dx * std::hypot(di, dj);
      const double q = r / h;
      if ((di == 0 && dj == 0) || q >= 2.0) continue;
      const double a = 1.0 - 0.5 * q;
      const double c = 2.0 * q * a * a * a / r;
      out.push_back({di, dj, c});
      secondMoment += c * r * r;
    }
  }
  for (auto& nb : out) nb.weight *= 4.0 / secondMoment;
  return out;
}

}  // namespace

SparseSystem latticePoisson(int n, Stencil stencil, long firstRow) {
  const double dx = 1.0 / (n + 1);
  const std::vector<Neighbour> neighbours = stencilOf(stencil, dx);
  SparseSystem A;
  A.firstRow = firstRow;
  A.rowStart.reserve(static_cast<std::size_t>(n) * n + 1);
  A.rowStart.push_back(0);
  A.columns.reserve(static_cast<std::size_t>(n) * n * (neighbours.size() + 1));
  A.values.reserve(A.columns.capacity());
  A.rhs.reserve(static_cast<std::size_t>(n) * n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double x = (i + 1) * dx;
      const double y = (j + 1) * dx;
      double diagonal = 0.0;
      double rhs = minusLaplacian(x, y);
      const std::size_t diagonalAt = A.columns.size();
      A.columns.push_back(firstRow + static_cast<long>(j) * n + i);
      A.values.push_back(0.0);
      for (const Neighbour& nb : neighbours) {
        diagonal += nb.weight;
        const int ii = i + nb.di;
        const int jj = j + nb.dj;
        if (ii >= 0 && ii < n && jj >= 0 && jj < n) {
          A.columns.push_back(firstRow + static_cast<long>(jj) * n + ii);
          A.values.push_back(-nb.weight);
        } else {  // Dirichlet point: its known value moves to the right-hand side
          rhs += nb.weight * exactU((ii + 1) * dx, (jj + 1) * dx);
        }
      }
      A.values[diagonalAt] = diagonal;
      A.rhs.push_back(rhs);
      A.rowStart.push_back(static_cast<int>(A.columns.size()));
    }
  }
  return A;
}

}  // namespace isph::test
