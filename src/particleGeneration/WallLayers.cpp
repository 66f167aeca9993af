#include "particleGeneration/WallLayers.hpp"

#include <algorithm>
#include <cmath>

#include "particleGeneration/SpatialHash.hpp"

namespace isph {

namespace {

struct Candidate {
  Vec2 x;
  Vec2 n;  // wall layer: unit normal into the material
};

Vec2 rotate(const Vec2& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

// Turning angle at each vertex (positive: turns left, towards the material). Open chains
// have no turn at their end points.
std::vector<double> turnAngles(const Polyline& c) {
  const std::size_t nSeg = c.segmentCount();
  std::vector<double> turn(c.points().size(), 0.0);
  for (std::size_t v = 0; v < c.points().size(); ++v) {
    if (!c.closed() && (v == 0 || v == nSeg)) continue;
    const Vec2 in = c.tangent((v + nSeg - 1) % nSeg), out = c.tangent(v % nSeg);
    turn[v] = std::atan2(cross(in, out), in.dot(out));
  }
  return turn;
}

// Normal of a wall particle at vertex v: the mean of the two segments' normals.
Vec2 vertexNormal(const Polyline& c, std::size_t v) {
  const std::size_t nSeg = c.segmentCount();
  if (!c.closed() && v == 0) return c.normal(0);
  if (!c.closed() && v == nSeg) return c.normal(nSeg - 1);
  return (c.normal((v + nSeg - 1) % nSeg) + c.normal(v % nSeg)).normalized();
}

// Layer k of one chain, in order along it. `stats` collects the length and spacing of layer 0.
std::vector<Candidate> layerCandidates(const Polyline& c, int k, double dx, WallLayerStats& stats) {
  const std::size_t nSeg = c.segmentCount();
  const std::size_t nPts = c.points().size();
  const std::vector<double> turn = turnAngles(c);
  const double depth = k * dx;
  auto trim = [&](std::size_t v) { return turn[v] < 0 ? depth * std::tan(-0.5 * turn[v]) : 0.0; };

  std::vector<Candidate> out;
  for (std::size_t s = 0; s < nSeg; ++s) {
    const std::size_t v0 = s, v1 = (s + 1) % nPts;
    const Vec2 t = c.tangent(s), n = c.normal(s);
    const double a = trim(v0), b = trim(v1);
    const double length = c.segmentLength(s) - a - b;
    if (length >= -1e-9 * dx) {
      const Vec2 p = c.segmentStart(s) + a * t - depth * n;
      const Vec2 q = c.segmentEnd(s) - b * t - depth * n;
      const long parts = length <= 1e-9 * dx ? 0 : std::max(1L, std::lround(length / dx));
      if (k == 0 && parts > 0) {
        const double spacing = length / static_cast<double>(parts);
        stats.minSpacing = stats.minSpacing == 0 ? spacing : std::min(stats.minSpacing, spacing);
        stats.maxSpacing = std::max(stats.maxSpacing, spacing);
        stats.surfaceLength += length;
      }
      for (long i = 0; i < std::max(parts, 1L); ++i) {
        const Vec2 x =
            parts == 0 ? p
                       : Vec2(p + (static_cast<double>(i) / static_cast<double>(parts)) * (q - p));
        out.push_back({x, i == 0 ? vertexNormal(c, v0) : n});
      }
      if (!c.closed() && s + 1 == nSeg && parts > 0) out.push_back({q, vertexNormal(c, v1)});
    }
    // Convex corner: the offset segments meet on the bisector at `depth` / cos(turn/2) from
    // the vertex. A sharp corner leaves a thin solid between there and the vertex, too thin
    // for the layers: fill it along the bisector, dx apart, down to a depth of (k - 1/2) dx.
    if (depth > 0 && turn[v1] < 0 && (c.closed() || v1 + 1 < nPts)) {
      const Vec2 bisector = (-n - c.normal((s + 1) % nSeg)).normalized();
      const double cosHalf = std::cos(0.5 * turn[v1]);
      for (double r = depth / cosHalf - dx; r * cosHalf >= (k - 0.5) * dx; r -= dx) {
        out.push_back({c.points()[v1] + r * bisector, Vec2::Zero()});
      }
    }
    // Concave corner (seen from the material): the arc of radius `depth` about the vertex,
    // from the end of this offset segment (included) to the start of the next (excluded).
    if (depth > 0 && turn[v1] > 0) {
      const long parts = std::max(1L, std::lround(turn[v1] * depth / dx));
      for (long j = 0; j < parts; ++j) {
        const double angle = turn[v1] * static_cast<double>(j) / static_cast<double>(parts);
        out.push_back({c.points()[v1] + depth * rotate(-n, angle), Vec2::Zero()});
      }
    }
  }
  return out;
}

// Whether x lies on or behind `wall`'s surface within its layers.
bool withinLayers(const WallSurface& wall, const Vec2& x, int layers, double dx, double front) {
  const BoundingBox box = wall.boundingBox().inflated(layers * dx);
  if (!box.contains(toVec3(x))) return false;
  const auto d = wall.distance(x);
  return !d.beside && d.signedDistance < front && d.signedDistance > -(layers - 0.5) * dx;
}

}  // namespace

WallLayerResult generateWallLayers(const std::vector<WallSurface>& walls, int layers, double dx) {
  WallLayerResult result;
  result.stats.resize(walls.size());
  SpatialHash kept(dx);
  std::vector<WallParticle> accepted;

  for (int k = 0; k < layers; ++k) {
    for (std::size_t w = 0; w < walls.size(); ++w) {
      WallLayerStats& stats = result.stats[w];
      for (const Candidate& c : layerCandidates(walls[w].chain(), k, dx, stats)) {
        if (k > 0) {
          const auto own = walls[w].distance(c.x);
          if (own.beside || own.signedDistance > -(k - 0.5) * dx) continue;
        }
        bool covered = false;
        for (std::size_t a = 0; a < w && !covered; ++a)
          covered = withinLayers(walls[a], c.x, layers, dx, 0.25 * dx);
        if (covered || kept.anyCloserThan(c.x, 0.5 * dx * (1 - 1e-9))) {
          ++stats.dropped;
          continue;
        }
        WallParticle p{c.x, Vec2::Zero(), static_cast<int>(w), k, false};
        if (k == 0) {
          const Vec2 probe = c.x + 0.5 * dx * c.n;
          bool buried = false;
          for (std::size_t a = 0; a < walls.size() && !buried; ++a) {
            buried = a != w && withinLayers(walls[a], probe, layers, dx, 0.0);
          }
          p.isWall = !buried;
          if (p.isWall) p.normal = c.n;
          if (buried) ++stats.demoted;
        }
        (p.isWall ? stats.wallParticles : stats.dummyParticles) += 1;
        kept.insert(c.x);
        accepted.push_back(p);
      }
    }
  }
  // A dummy beyond (layers + 1/2) dx of every wall particle is dropped (under a demoted
  // stretch of surface: the middle of a wide barrier's foot).
  const double reach = (layers + 0.5) * dx;
  SpatialHash wallParticles(reach);
  for (const WallParticle& p : accepted)
    if (p.isWall) wallParticles.insert(p.position);
  std::erase_if(accepted, [&](const WallParticle& p) {
    const bool unreachable = !p.isWall && !wallParticles.anyCloserThan(p.position, reach);
    if (unreachable) {
      WallLayerStats& stats = result.stats[static_cast<std::size_t>(p.wall)];
      --stats.dummyParticles;
      if (p.layer == 0) --stats.demoted;
      ++stats.dropped;
    }
    return unreachable;
  });
  std::stable_sort(accepted.begin(), accepted.end(),
                   [](const WallParticle& a, const WallParticle& b) { return a.wall < b.wall; });
  result.particles = std::move(accepted);
  return result;
}

}  // namespace isph
