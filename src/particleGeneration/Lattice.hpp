#pragma once
// The lattice of material particle sites (`lattice square|hexagonal;` in particleMeshDict).
// Square: cells dx × dx. Hexagonal: rows dy = (√3/2) dx apart, every other row shifted by
// dx/2, so each site has six neighbours at dx. Site (i, j) is the centre of its cell:
//     origin + ((i + 1/2 + s_j) dx, (j + 1/2) dy),   s_j = 1/2 on odd rows (hexagonal), else 0,
// so a box whose sides lie on cell faces holds whole cells and its particles sit dx/2 inside.
#include <string>

#include "geometry/BoundingBox.hpp"
#include "geometry/Vec2.hpp"

namespace isph {

enum class LatticeType { square, hexagonal };

const char* toString(LatticeType type);

struct SiteRange {
  long i0 = 0, i1 = -1;  // columns, inclusive
  long j0 = 0, j1 = -1;  // rows, inclusive
  long rows() const { return j1 - j0 + 1; }
  long columns() const { return i1 - i0 + 1; }
};

class Lattice {
 public:
  Lattice(LatticeType type, double dx, const Vec2& origin = Vec2::Zero());

  LatticeType type() const { return type_; }
  double spacing() const { return dx_; }
  double rowSpacing() const { return dy_; }
  // Area that one site stands for (per unit width): dx², or (√3/2) dx² hexagonal.
  double siteArea() const { return dx_ * dy_; }

  Vec2 site(long i, long j) const {
    const double shift = (type_ == LatticeType::hexagonal && (j & 1)) ? 0.5 : 0.0;
    return origin_ +
           Vec2((static_cast<double>(i) + 0.5 + shift) * dx_, (static_cast<double>(j) + 0.5) * dy_);
  }
  // Rows and columns whose sites may lie in `box` (every site inside it is in the range).
  SiteRange range(const BoundingBox& box) const;

 private:
  LatticeType type_;
  double dx_, dy_;
  Vec2 origin_;
};

}  // namespace isph
