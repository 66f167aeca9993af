#pragma once
// Nearest-segment queries over the segments of a chain: a bounding-volume hierarchy (median
// splits, four segments per leaf), so one query costs about log(n) box tests instead of a
// loop over all segments. Built once per shape; queries are thread-safe.
#include <vector>

#include "geometry/Vec2.hpp"

namespace isph {

class SegmentTree {
 public:
  struct Hit {
    int segment = -1;  // index into the segments given to the constructor
    double t = 0;      // position along it, 0 at its first point, 1 at its second
    double distanceSquared = 1e300;
    Vec2 point = Vec2::Zero();  // the closest point
  };

  SegmentTree() = default;
  // Segment i runs from first[i] to second[i].
  SegmentTree(std::vector<Vec2> first, std::vector<Vec2> second);

  // The segment closest to p (the lowest index among equally close ones).
  Hit nearest(const Vec2& p) const;
  std::size_t size() const { return a_.size(); }

 private:
  struct Node {
    Vec2 lo, hi;
    int begin = 0, end = 0;     // range in order_ (leaves)
    int left = -1, right = -1;  // children (inner nodes)
  };
  int build(int begin, int end);
  static double boxDistanceSquared(const Node& n, const Vec2& p);

  std::vector<Vec2> a_, b_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

}  // namespace isph
