#include "particleGeneration/RegionFilling.hpp"

namespace isph {

namespace {

// The earlier region that owns site p, or -1.
int earlierOwner(const std::vector<const Region*>& regions, const std::vector<BoundingBox>& boxes,
                 std::size_t r, const Vec3& p) {
  for (std::size_t q = 0; q < r; ++q) {
    if (boxes[q].contains(p) && regions[q]->contains(p)) return static_cast<int>(q);
  }
  return -1;
}

}  // namespace

std::vector<RegionSites> fillRegions(const std::vector<const Region*>& regions,
                                     const Lattice& lattice) {
  std::vector<BoundingBox> boxes;
  for (const Region* r : regions) boxes.push_back(r->boundingBox());

  std::vector<RegionSites> out(regions.size());
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const SiteRange range = lattice.range(boxes[r]);
    const long rows = std::max(0L, range.rows());
    std::vector<std::vector<Vec2>> rowSites(static_cast<std::size_t>(rows));
    std::vector<std::vector<long>> rowLost(static_cast<std::size_t>(rows), std::vector<long>(r, 0));
    std::vector<long> rowInside(static_cast<std::size_t>(rows), 0);

#pragma omp parallel for schedule(dynamic, 16)
    for (long row = 0; row < rows; ++row) {
      const long j = range.j0 + row;
      auto& sites = rowSites[static_cast<std::size_t>(row)];
      for (long i = range.i0; i <= range.i1; ++i) {
        const Vec2 s = lattice.site(i, j);
        const Vec3 p = toVec3(s);
        if (!regions[r]->contains(p)) continue;
        ++rowInside[static_cast<std::size_t>(row)];
        const int owner = earlierOwner(regions, boxes, r, p);
        if (owner >= 0) {
          ++rowLost[static_cast<std::size_t>(row)][static_cast<std::size_t>(owner)];
        } else {
          sites.push_back(s);
        }
      }
    }

    RegionSites& result = out[r];
    result.lostTo.assign(r, 0);
    std::size_t total = 0;
    for (const auto& s : rowSites) total += s.size();
    result.sites.reserve(total);
    for (long row = 0; row < rows; ++row) {
      const auto k = static_cast<std::size_t>(row);
      result.sites.insert(result.sites.end(), rowSites[k].begin(), rowSites[k].end());
      result.inside += rowInside[k];
      for (std::size_t q = 0; q < r; ++q) result.lostTo[q] += rowLost[k][q];
    }
  }
  return out;
}

}  // namespace isph
