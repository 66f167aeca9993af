#pragma once
// A region of space that material fills: a box, a polygon, a profile (2D now; a 3D region is
// another subclass). Regions are chosen by name in particleMeshDict (`type box;`) from a
// registry, so a new shape is an addition, not an edit of the particle generator.
#include <memory>
#include <string>
#include <vector>

#include "core/Types.hpp"
#include "geometry/BoundingBox.hpp"

namespace isph {

class Region {
 public:
  virtual ~Region() = default;

  // The name users write after `type` ("box", "polygon", "profile").
  virtual std::string type() const = 0;
  virtual int dimension() const { return 2; }
  // Whether the point lies inside. Boundaries are half-open (a point on a lower or left
  // edge is inside, on an upper or right edge outside), so regions that share an edge do
  // not both claim the lattice sites on it.
  virtual bool contains(const Vec3& p) const = 0;
  virtual BoundingBox boundingBox() const = 0;
  // Area in 2D (per unit width), volume in 3D.
  virtual double measure() const = 0;
  // Appends the parameters t > 0 at which the ray o + t d crosses the boundary (in any
  // order; a crossing may appear twice at a corner).
  virtual void rayCrossings(const Vec3& o, const Vec3& d, std::vector<double>& t) const = 0;

  // A 3D scene extrudes a 2D region along z; a 3D region (dimension() 3) is cut instead: its
  // x-y section at z (null where it has none), and its outline in x-y (the union of its
  // sections: where a wall looking for the material's side probes).
  virtual std::unique_ptr<Region> sectionAt(double /*z*/) const { return nullptr; }
  virtual std::unique_ptr<Region> outline() const { return nullptr; }
};

}  // namespace isph
