// Staging names: making and parsing ".<name>.<kind>.<pid>[.<serial>]@<host>".
#include "core/io/StagingNames.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <array>
#include <charconv>

namespace isph {

namespace fs = std::filesystem;

namespace {

constexpr std::array<std::string_view, 3> kinds{"tmp", "old", "trash"};

}  // namespace

const std::string& thisHost() {
  static const std::string host = [] {
    char buffer[256] = {};
    if (::gethostname(buffer, sizeof buffer - 1) != 0 || buffer[0] == '\0')
      return std::string("localhost");
    std::string name(buffer);
    for (char& c : name) {
      if (c == '/' || c == '@') c = '_';
    }
    return name;
  }();
  return host;
}

fs::path stagingName(const fs::path& target, std::string_view kind,
                     std::optional<unsigned> serial) {
  fs::path t = target;
  if (!t.has_filename() && t.has_parent_path()) t = t.parent_path();
  const std::string suffix =
      serial ? fmt::format("{}.{}", ::getpid(), *serial) : fmt::format("{}", ::getpid());
  return t.parent_path() /
         fmt::format(".{}.{}.{}@{}", t.filename().string(), kind, suffix, thisHost());
}

std::optional<StagingEntry> parseStagingName(std::string_view name) {
  if (name.size() < 2 || name[0] != '.') return std::nullopt;
  StagingEntry e;
  std::string_view head = name;
  if (const auto at = name.rfind('@'); at != std::string_view::npos) {
    e.host = std::string(name.substr(at + 1));
    head = name.substr(0, at);
    if (e.host == thisHost()) e.host.clear();
  }
  for (const std::string_view kind : kinds) {
    const std::string marker = fmt::format(".{}.", kind);
    const auto pos = head.rfind(marker);
    if (pos == std::string_view::npos || pos < 2) continue;
    // <pid>[.<serial>]: digits, then optionally '.' and digits.
    const std::string_view tail = head.substr(pos + marker.size());
    long pid = 0;
    const auto [ptr, ec] = std::from_chars(tail.data(), tail.data() + tail.size(), pid);
    if (ec != std::errc{} || ptr == tail.data() || pid <= 0) continue;
    const std::string_view rest(ptr, static_cast<std::size_t>(tail.data() + tail.size() - ptr));
    if (!rest.empty() &&
        (rest[0] != '.' || rest.size() == 1 ||
         rest.substr(1).find_first_not_of("0123456789") != std::string_view::npos)) {
      continue;
    }
    e.target = std::string(head.substr(1, pos - 1));
    e.kind = std::string(kind);
    e.pid = pid;
    return e;
  }
  return std::nullopt;
}

}  // namespace isph
