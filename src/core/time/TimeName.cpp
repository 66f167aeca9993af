// Time names, listing time directories and finding a time.
#include "core/time/TimeName.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace isph {

namespace fs = std::filesystem;

std::string timeName(double t, int precision) {
  if (t == 0) return "0";  // also -0
  return fmt::format("{:.{}g}", t, std::clamp(precision, 1, 17));
}

bool parseTimeName(std::string_view text, double& value) {
  if (text.empty()) return false;
  double v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v)) return false;
  value = v;
  return true;
}

std::vector<Instant> listTimes(const fs::path& caseDir) {
  std::vector<Instant> times;
  std::error_code ec;
  for (fs::directory_iterator it(caseDir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    double value = 0;
    if (name.empty() || name[0] == '.' || !parseTimeName(name, value)) continue;
    std::error_code typeError;
    if (!it->is_directory(typeError)) continue;
    times.push_back({value, name});
  }
  std::sort(times.begin(), times.end(), [](const Instant& a, const Instant& b) {
    return a.value < b.value || (a.value == b.value && a.name < b.name);
  });
  return times;
}

const Instant* findTime(const std::vector<Instant>& times, double value, double tolerance) {
  const Instant* best = nullptr;
  double bestDistance = 0;
  for (const auto& t : times) {
    const double distance = std::abs(t.value - value);
    if (!best || distance < bestDistance) {
      best = &t;
      bestDistance = distance;
    }
  }
  if (!best) return nullptr;
  return bestDistance <= tolerance * std::max(std::abs(value), std::abs(best->value)) ? best
                                                                                      : nullptr;
}

}  // namespace isph
