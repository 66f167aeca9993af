#include "geometry/Profile.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/Segment.hpp"

namespace isph {

double interpolateProfile(const std::vector<Vec2>& curve, double x) {
  if (x <= curve.front().x()) return curve.front().y();
  if (x >= curve.back().x()) return curve.back().y();
  const auto it = std::upper_bound(curve.begin(), curve.end(), x,
                                   [](double v, const Vec2& p) { return v < p.x(); });
  const Vec2& b = *it;
  const Vec2& a = *(it - 1);
  return a.y() + (x - a.x()) * (b.y() - a.y()) / (b.x() - a.x());
}

namespace {

void increasingX(std::vector<Vec2>& curve) {
  if (curve.size() > 1 && curve.front().x() > curve.back().x())
    std::reverse(curve.begin(), curve.end());
}

}  // namespace

Profile::Profile(std::vector<Vec2> upper, std::vector<Vec2> lower, std::optional<double> thickness)
    : upper_(std::move(upper)), lower_(std::move(lower)), thickness_(thickness) {
  increasingX(upper_);
  increasingX(lower_);
  x0_ = lower_.front().x();
  x1_ = lower_.back().x();
  if (!upper_.empty()) {
    x0_ = std::max(x0_, upper_.front().x());
    x1_ = std::min(x1_, upper_.back().x());
  }
  // Breakpoints: every point of both curves inside the range, then the crossings of the
  // two candidate tops, so that top - bottom is linear between consecutive breakpoints.
  breaks_ = {x0_, x1_};
  for (const auto* curve : {&upper_, &lower_}) {
    for (const Vec2& p : *curve) {
      if (p.x() > x0_ && p.x() < x1_) breaks_.push_back(p.x());
    }
  }
  std::sort(breaks_.begin(), breaks_.end());
  breaks_.erase(std::unique(breaks_.begin(), breaks_.end()), breaks_.end());
  if (thickness_ && !upper_.empty()) {
    std::vector<double> crossings;
    for (std::size_t k = 0; k + 1 < breaks_.size(); ++k) {
      const double a = breaks_[k], b = breaks_[k + 1];
      const double da = interpolateProfile(upper_, a) - bottom(a) - *thickness_;
      const double db = interpolateProfile(upper_, b) - bottom(b) - *thickness_;
      if (da * db < 0) crossings.push_back(a + (b - a) * da / (da - db));
    }
    breaks_.insert(breaks_.end(), crossings.begin(), crossings.end());
    std::sort(breaks_.begin(), breaks_.end());
  }
  // Exact area (trapezoids of a piecewise linear height) and bounding box.
  for (std::size_t k = 0; k < breaks_.size(); ++k) {
    const double x = breaks_[k];
    box_.extend(Vec3(x, bottom(x), 0));
    box_.extend(Vec3(x, top(x), 0));
    if (k + 1 < breaks_.size()) {
      const double xb = breaks_[k + 1];
      const double ha = std::max(0.0, top(x) - bottom(x));
      const double hb = std::max(0.0, top(xb) - bottom(xb));
      area_ += 0.5 * (ha + hb) * (xb - x);
    }
  }
  for (double x : breaks_) outline_.emplace_back(x, bottom(x));
  for (auto it = breaks_.rbegin(); it != breaks_.rend(); ++it) outline_.emplace_back(*it, top(*it));
}

double Profile::top(double x) const {
  if (upper_.empty()) return bottom(x) + *thickness_;
  const double u = interpolateProfile(upper_, x);
  return thickness_ ? std::min(u, bottom(x) + *thickness_) : u;
}

void Profile::rayCrossings(const Vec3& o, const Vec3& d, std::vector<double>& t) const {
  isph::rayCrossings(outline_, toVec2(o), toVec2(d), t);
}

bool Profile::contains(const Vec3& p) const {
  if (p.x() < x0_ || p.x() >= x1_) return false;
  return p.y() >= bottom(p.x()) && p.y() < top(p.x());
}

}  // namespace isph
