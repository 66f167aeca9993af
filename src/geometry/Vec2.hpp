#pragma once
// Points and vectors of plane-strain scenes (the x-y plane). Particles are stored as Vec3
// with z = 0; the 2D shapes work on Vec2.
#include <Eigen/Core>

#include "core/Types.hpp"

namespace isph {

using Vec2 = Eigen::Vector2d;

// z component of a x b.
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// `t` turned by +90° (counter-clockwise): the normal on the left of a direction of travel.
inline Vec2 leftNormal(const Vec2& t) { return {-t.y(), t.x()}; }

inline Vec2 toVec2(const Vec3& p) { return p.head<2>(); }
inline Vec3 toVec3(const Vec2& p) { return {p.x(), p.y(), 0.0}; }

}  // namespace isph
