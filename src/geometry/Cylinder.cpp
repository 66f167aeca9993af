#include "geometry/Cylinder.hpp"

#include <cmath>

#include "geometry/Box.hpp"

namespace isph {

Cylinder::Cylinder(const Vec3& baseCentre, double radius, double height)
    : base_(baseCentre), radius_(radius), height_(height) {}

bool Cylinder::contains(const Vec3& p) const {
  const double dx = p.x() - base_.x(), dz = p.z() - base_.z();
  return dx * dx + dz * dz < radius_ * radius_ && p.y() >= base_.y() && p.y() < base_.y() + height_;
}

BoundingBox Cylinder::boundingBox() const {
  return {base_ - Vec3(radius_, 0, radius_), base_ + Vec3(radius_, height_, radius_)};
}

double Cylinder::measure() const { return M_PI * radius_ * radius_ * height_; }

void Cylinder::rayCrossings(const Vec3& o, const Vec3& d, std::vector<double>& t) const {
  // The mantle: |(o + t d - base) projected on x-z|² = R², within the height.
  const double ox = o.x() - base_.x(), oz = o.z() - base_.z();
  const double a = d.x() * d.x() + d.z() * d.z(), b = 2 * (ox * d.x() + oz * d.z());
  const double c = ox * ox + oz * oz - radius_ * radius_;
  const auto within = [&](double s) {
    const double y = o.y() + s * d.y();
    return s > 0 && y >= base_.y() && y <= base_.y() + height_;
  };
  if (a > 0) {
    const double disc = b * b - 4 * a * c;
    if (disc >= 0) {
      for (const double s : {(-b - std::sqrt(disc)) / (2 * a), (-b + std::sqrt(disc)) / (2 * a)})
        if (within(s)) t.push_back(s);
    }
  }
  // The caps: y = y0 and y = y0 + H, inside the circle.
  if (d.y() != 0) {
    for (const double y : {base_.y(), base_.y() + height_}) {
      const double s = (y - o.y()) / d.y();
      const double px = ox + s * d.x(), pz = oz + s * d.z();
      if (s > 0 && px * px + pz * pz <= radius_ * radius_) t.push_back(s);
    }
  }
}

std::unique_ptr<Region> Cylinder::sectionAt(double z) const {
  const double dz = z - base_.z();
  const double w2 = radius_ * radius_ - dz * dz;
  if (w2 <= 0) return nullptr;
  const double w = std::sqrt(w2);
  return std::make_unique<Box>(Vec2(base_.x() - w, base_.y()), Vec2(base_.x() + w, base_.y() + height_));
}

std::unique_ptr<Region> Cylinder::outline() const { return sectionAt(base_.z()); }

}  // namespace isph
