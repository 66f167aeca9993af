#pragma once
// Nearest-point and within-radius queries over a fixed set of points: a k-d tree (median
// splits on the widest axis, eight points per leaf), so one query costs about log(n) instead of
// a loop over all points. Built once (the wall particles of a scene); queries are thread-safe.
#include <vector>

#include "core/Types.hpp"

namespace isph {

class PointTree {
 public:
  PointTree() = default;
  explicit PointTree(std::vector<Vec3> points);

  // The index of the point closest to x (the lowest index among equally close ones); -1 when
  // the tree is empty.
  long nearest(const Vec3& x) const;
  // The indices of the points within `radius` of x (distance <= radius), in no set order.
  std::vector<long> within(const Vec3& x, double radius) const;

  std::size_t size() const { return points_.size(); }
  const Vec3& point(long i) const { return points_[static_cast<std::size_t>(i)]; }

 private:
  struct Node {
    Vec3 lo, hi;                // bounding box of its points
    int begin = 0, end = 0;     // range in order_ (leaves)
    int left = -1, right = -1;  // children (inner nodes)
  };
  int build(int begin, int end);
  static double boxDistanceSquared(const Node& n, const Vec3& x);
  void nearest(int node, const Vec3& x, long& best, double& bestSquared) const;

  std::vector<Vec3> points_;
  std::vector<long> order_;
  std::vector<Node> nodes_;
};

}  // namespace isph
