#include "postProcessing/sampling/SurfaceProfile.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/io/ReadFile.hpp"

namespace isph {

SurfaceProfile surfaceProfile(const ParticleCloud& cloud, const SurfaceSpec& spec) {
  if (!(spec.binWidth > 0)) fatalError(fmt::format("surface profile: binWidth {} must be positive", spec.binWidth));
  if (!(spec.xMax > spec.xMin)) {
    fatalError(fmt::format("surface profile: xMax {} must exceed xMin {}", spec.xMax, spec.xMin));
  }
  Vec3 e(spec.direction.x(), spec.direction.y(), 0);
  if (!(e.norm() > 0)) fatalError("surface profile: direction has no x-y component");
  e.normalize();
  const Vec3 n(-e.y(), e.x(), 0);
  // Bins of exactly the given width; a last bin that overhangs xMax is kept (the range is covered).
  const auto nBins = static_cast<std::size_t>(std::ceil((spec.xMax - spec.xMin) / spec.binWidth - 1e-9));
  SurfaceProfile out;
  out.binWidth = spec.binWidth;
  out.x.resize(nBins);
  out.height.assign(nBins, 0.0);
  out.filled.assign(nBins, false);
  for (std::size_t k = 0; k < nBins; ++k) out.x[k] = spec.xMin + (k + 0.5) * spec.binWidth;

  std::vector<double> top(nBins, -1e300);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.kind[i] != label(ParticleKind::material)) continue;
    const Vec3 r = cloud.positions[i] - spec.origin;
    const double s = r.dot(e);
    if (s < spec.xMin) continue;
    const auto k = static_cast<std::size_t>(std::floor((s - spec.xMin) / spec.binWidth));
    if (k >= nBins) continue;
    top[k] = std::max(top[k], r.dot(n));
    out.filled[k] = true;
  }
  const double halfDx = 0.5 * cloud.properties.spacing;
  for (std::size_t k = 0; k < nBins; ++k) {
    if (out.filled[k]) out.height[k] = top[k] + halfDx;
  }
  return out;
}

double SurfaceProfile::heightAt(double s) const {
  if (x.empty()) return 0.0;
  const double half = 0.5 * binWidth;
  if (s < x.front()) return s >= x.front() - half ? height.front() : 0.0;
  if (s >= x.back()) return s <= x.back() + half ? height.back() : 0.0;
  const auto upper = std::upper_bound(x.begin(), x.end(), s);
  const std::size_t k = static_cast<std::size_t>(upper - x.begin());  // x[k - 1] <= s < x[k]
  const double w = (s - x[k - 1]) / (x[k] - x[k - 1]);
  return (1 - w) * height[k - 1] + w * height[k];
}

std::vector<ProfilePoint> readProfileCsv(const std::filesystem::path& file) {
  // A regular file of reasonable size (a device such as /dev/zero would never end).
  std::istringstream in(readWholeFile(file, std::size_t{256} << 20, "a profile file"));
  std::vector<ProfilePoint> out;
  std::string line;
  int lineNo = 0;
  bool headerSeen = false;
  while (std::getline(in, line)) {
    ++lineNo;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::string text = line.substr(first);
    std::replace(text.begin(), text.end(), ',', ' ');
    std::istringstream s(text);
    ProfilePoint p{};
    if (!(s >> p.x >> p.height) || !std::isfinite(p.x) || !std::isfinite(p.height)) {
      if (out.empty() && !headerSeen) {  // the column names
        headerSeen = true;
        continue;
      }
      fatalError(fmt::format("{}, line {}: expected 'x,height', found '{}'", file.string(), lineNo, line));
    }
    out.push_back(p);
  }
  if (out.empty()) fatalError(fmt::format("{}: no profile point found", file.string()));
  return out;
}

double rmsDistance(const SurfaceProfile& computed, const std::vector<ProfilePoint>& reference) {
  if (reference.empty()) return 0.0;
  double sum = 0;
  for (const auto& p : reference) {
    const double d = computed.heightAt(p.x) - p.height;
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(reference.size()));
}

}  // namespace isph
