#pragma once
// A uniform grid of square (cubic) cells of side = the kernel support, over the bounding
// box of a set of points: the spatial hash behind the neighbour search. Cells are
// numbered x fastest, then y, then z.
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

 private:
  int dimension_ = 2;
  double cellSize_ = 1.0;
  Vec3 origin_ = Vec3::Zero();
  std::array<int, 3> n_{1, 1, 1};
  std::vector<int> cellStart_;
  std::vector<int> sorted_;
};

}  // namespace isph
