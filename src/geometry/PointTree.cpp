#include "geometry/PointTree.hpp"

#include <algorithm>
#include <numeric>

namespace isph {

namespace {
constexpr int leafSize = 8;
}

PointTree::PointTree(std::vector<Vec3> points) : points_(std::move(points)) {
  order_.resize(points_.size());
  std::iota(order_.begin(), order_.end(), 0L);
  if (!points_.empty()) build(0, static_cast<int>(points_.size()));
}

int PointTree::build(int begin, int end) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back({});
  Node node;
  node.begin = begin;
  node.end = end;
  node.lo = node.hi = points_[static_cast<std::size_t>(order_[static_cast<std::size_t>(begin)])];
  for (int k = begin; k < end; ++k) {
    const Vec3& x = points_[static_cast<std::size_t>(order_[static_cast<std::size_t>(k)])];
    node.lo = node.lo.cwiseMin(x);
    node.hi = node.hi.cwiseMax(x);
  }
  if (end - begin > leafSize) {
    int axis = 0;
    (node.hi - node.lo).maxCoeff(&axis);
    const int middle = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                     [&](long a, long b) {
                       return points_[static_cast<std::size_t>(a)][axis] < points_[static_cast<std::size_t>(b)][axis];
                     });
    node.left = build(begin, middle);
    node.right = build(middle, end);
  }
  nodes_[static_cast<std::size_t>(index)] = node;
  return index;
}

double PointTree::boxDistanceSquared(const Node& n, const Vec3& x) {
  const Vec3 d = (n.lo - x).cwiseMax(x - n.hi).cwiseMax(Vec3::Zero());
  return d.squaredNorm();
}

void PointTree::nearest(int node, const Vec3& x, long& best, double& bestSquared) const {
  const Node& n = nodes_[static_cast<std::size_t>(node)];
  if (boxDistanceSquared(n, x) > bestSquared) return;
  if (n.left < 0) {
    for (int k = n.begin; k < n.end; ++k) {
      const long i = order_[static_cast<std::size_t>(k)];
      const double d2 = (points_[static_cast<std::size_t>(i)] - x).squaredNorm();
      if (d2 < bestSquared || (d2 == bestSquared && i < best)) {
        best = i;
        bestSquared = d2;
      }
    }
    return;
  }
  // The nearer child first: its points usually prune the other.
  const double dl = boxDistanceSquared(nodes_[static_cast<std::size_t>(n.left)], x);
  const double dr = boxDistanceSquared(nodes_[static_cast<std::size_t>(n.right)], x);
  const int first = dl <= dr ? n.left : n.right, second = dl <= dr ? n.right : n.left;
  nearest(first, x, best, bestSquared);
  nearest(second, x, best, bestSquared);
}

long PointTree::nearest(const Vec3& x) const {
  if (nodes_.empty()) return -1;
  long best = -1;
  double bestSquared = 1e300;
  nearest(0, x, best, bestSquared);
  return best;
}

std::vector<long> PointTree::within(const Vec3& x, double radius) const {
  std::vector<long> found;
  if (nodes_.empty()) return found;
  const double r2 = radius * radius;
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const Node& n = nodes_[static_cast<std::size_t>(stack.back())];
    stack.pop_back();
    if (boxDistanceSquared(n, x) > r2) continue;
    if (n.left >= 0) {
      stack.push_back(n.left);
      stack.push_back(n.right);
      continue;
    }
    for (int k = n.begin; k < n.end; ++k) {
      const long i = order_[static_cast<std::size_t>(k)];
      if ((points_[static_cast<std::size_t>(i)] - x).squaredNorm() <= r2) found.push_back(i);
    }
  }
  return found;
}

}  // namespace isph
