#pragma once
// A solid boundary as the particle generator sees it: a chain of segments oriented so that
// the material (fluid) side is on its LEFT. Two kinds:
//  - an open polyline (`type polyline;`): the surface of a solid that lies behind it, on the
//    side away from the material, however deep (a bed, a slope, a floor, a back wall);
//  - a closed chain (`type box;`, `type polygon;`): the boundary of a solid, walked
//    clockwise, so the material side is outside.
// Wall types are chosen by name from Registry<WallSurface, const Dictionary&, const ShapeContext&>.
#include "geometry/Polyline.hpp"

namespace isph {

class WallSurface {
 public:
  WallSurface(Polyline chain, std::string type)
      : chain_(std::move(chain)), type_(std::move(type)) {}

  const std::string& type() const { return type_; }
  const Polyline& chain() const { return chain_; }
  bool isClosed() const { return chain_.closed(); }
  BoundingBox boundingBox() const { return chain_.boundingBox(); }

  // Signed distance, positive on the material side; `beside` past an open end.
  Polyline::Distance distance(const Vec2& p) const { return chain_.signedDistance(p); }
  // Whether p lies in the solid: behind the surface (not past an open end).
  bool inSolid(const Vec2& p) const {
    const auto d = distance(p);
    return d.signedDistance < 0 && !d.beside;
  }

  // Put the material on the other side (open polylines: `materialSide right;` or auto).
  void flip() { chain_ = chain_.reversed(); }

 private:
  Polyline chain_;
  std::string type_;
};

}  // namespace isph
