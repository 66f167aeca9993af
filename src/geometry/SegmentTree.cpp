#include "geometry/SegmentTree.hpp"

#include <algorithm>

#include "geometry/Segment.hpp"

namespace isph {

SegmentTree::SegmentTree(std::vector<Vec2> first, std::vector<Vec2> second)
    : a_(std::move(first)), b_(std::move(second)) {
  order_.resize(a_.size());
  for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<int>(i);
  nodes_.reserve(2 * a_.size() / 4 + 2);
  if (!a_.empty()) build(0, static_cast<int>(a_.size()));
}

int SegmentTree::build(int begin, int end) {
  Node node;
  node.lo = Vec2::Constant(1e300);
  node.hi = Vec2::Constant(-1e300);
  for (int k = begin; k < end; ++k) {
    const int s = order_[k];
    node.lo = node.lo.cwiseMin(a_[s]).cwiseMin(b_[s]);
    node.hi = node.hi.cwiseMax(a_[s]).cwiseMax(b_[s]);
  }
  node.begin = begin;
  node.end = end;
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back(node);
  if (end - begin <= 4) return index;

  const Vec2 extent = node.hi - node.lo;
  const int axis = extent.x() >= extent.y() ? 0 : 1;
  const int mid = (begin + end) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](int i, int j) {
                     const double ci = a_[i][axis] + b_[i][axis];
                     const double cj = a_[j][axis] + b_[j][axis];
                     return ci < cj || (ci == cj && i < j);
                   });
  const int left = build(begin, mid);
  const int right = build(mid, end);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

double SegmentTree::boxDistanceSquared(const Node& n, const Vec2& p) {
  const Vec2 d = (n.lo - p).cwiseMax(p - n.hi).cwiseMax(Vec2::Zero());
  return d.squaredNorm();
}

SegmentTree::Hit SegmentTree::nearest(const Vec2& p) const {
  Hit best;
  if (nodes_.empty()) return best;
  int stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    if (boxDistanceSquared(n, p) > best.distanceSquared) continue;
    if (n.left < 0) {
      for (int k = n.begin; k < n.end; ++k) {
        const int s = order_[k];
        const double t = closestParameter(a_[s], b_[s], p);
        const Vec2 q = a_[s] + t * (b_[s] - a_[s]);
        const double d2 = (q - p).squaredNorm();
        if (d2 < best.distanceSquared || (d2 == best.distanceSquared && s < best.segment)) {
          best = {s, t, d2, q};
        }
      }
      continue;
    }
    // Visit the nearer child first (pushed last).
    const double dl = boxDistanceSquared(nodes_[n.left], p);
    const double dr = boxDistanceSquared(nodes_[n.right], p);
    if (dl <= dr) {
      stack[top++] = n.right;
      stack[top++] = n.left;
    } else {
      stack[top++] = n.left;
      stack[top++] = n.right;
    }
  }
  return best;
}

}  // namespace isph
