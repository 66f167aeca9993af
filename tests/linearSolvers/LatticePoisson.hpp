#pragma once
// Manufactured 2D Poisson problems on an n x n lattice of unknowns in the unit square,
// with Dirichlet values (from an exact field) on the lattice points outside, assembled as
// A = -L (positive diagonal, non-positive off-diagonals) and b = -f + boundary terms:
//   FivePoint   the standard 5-point Laplacian;
//   Sph21       an SPH-like (Brookshaw) Laplacian, weights 2 |W'(r)| / r of the Wendland C2
//               kernel at h = 1.3 dx (21 neighbours, self included), scaled to be exact for
//               x^2 + y^2; two layers of boundary points.
// Used by the tests and by benchLinearSolvers.
#include "linearSolvers/SparseSystem.hpp"

namespace isph::test {

enum class Stencil { FivePoint, Sph21 };

// Rows numbered from firstRow, row-major over the lattice (row = firstRow + j*n + i).
SparseSystem latticePoisson(int n, Stencil stencil, long firstRow = 0);

}  // namespace isph::test
