#pragma once
// A uniform grid of square (cubic) cells of side = the kernel support, over the bounding
// box of a set of points: the spatial hash behind the neighbour search. Cells are
// numbered x fastest, then y, then z.
#include <algorithm>
#include <array>
#include <vector>

#include "core/Types.hpp"

namespace isph {

class CellGrid {
 public:
  CellGrid() = default;
  CellGrid(const std::vector<Vec3>& points, double cellSize, int dimension);

  int dimension() const { return dimension_; }
  double cellSize() const { return cellSize_; }
  long nCells() const { return static_cast<long>(n_[0]) * n_[1] * n_[2]; }
  const std::array<int, 3>& counts() const { return n_; }

  // Cell coordinates (clamped into the grid) and linear index of a point.
  std::array<int, 3> cellOf(const Vec3& x) const;
  long index(const std::array<int, 3>& c) const {
    return (static_cast<long>(c[2]) * n_[1] + c[1]) * n_[0] + c[0];
  }

  // Points sorted by cell: cellStart[c] .. cellStart[c+1] index into `sorted`.
  const std::vector<int>& cellStart() const { return cellStart_; }
  const std::vector<int>& sorted() const { return sorted_; }

  // Calls f(point index) for every point in the 3^d cells around x's cell: every point within
  // one cell size of x is among them. Cell rows are visited z, y outer and x inner, in order.
  template <class F>
  void forEachCandidate(const Vec3& x, F&& f) const {
    const auto c = cellOf(x);
    const int dz = dimension_ == 3 ? 1 : 0;
    for (int k = c[2] - dz; k <= c[2] + dz; ++k) {
      if (k < 0 || k >= n_[2]) continue;
      for (int j = c[1] - 1; j <= c[1] + 1; ++j) {
        if (j < 0 || j >= n_[1]) continue;
        const int i0 = std::max(c[0] - 1, 0), i1 = std::min(c[0] + 1, n_[0] - 1);
        // Cells i0..i1 of one row are contiguous in the sorted array.
        const auto first = static_cast<std::size_t>(index({i0, j, k})), last = static_cast<std::size_t>(index({i1, j, k}));
        for (int s = cellStart_[first]; s < cellStart_[last + 1]; ++s) f(sorted_[static_cast<std::size_t>(s)]);
      }
    }
  }

 private:
  int dimension_ = 2;
  double cellSize_ = 1.0;
  Vec3 origin_ = Vec3::Zero();
  std::array<int, 3> n_{1, 1, 1};
  std::vector<int> cellStart_;
  std::vector<int> sorted_;
};

}  // namespace isph
