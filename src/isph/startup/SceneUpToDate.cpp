#include "isph/startup/SceneUpToDate.hpp"

#include <fmt/format.h>

#include <chrono>

#include "core/Error.hpp"

namespace isph {

namespace fs = std::filesystem;

namespace {

// The newest modification time of the files under `dir`.
fs::file_time_type newestFile(const fs::path& dir) {
  fs::file_time_type newest = fs::file_time_type::min();
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    if (it->is_regular_file(ec)) newest = std::max(newest, it->last_write_time(ec));
  }
  return newest;
}

}  // namespace

void checkSceneUpToDate(const fs::path& caseDir, bool force) {
  const fs::path scene = caseDir / "system" / "particleMeshDict";
  const fs::path zero = caseDir / "0";
  std::error_code ec;
  if (!fs::is_regular_file(scene, ec) || !fs::is_directory(zero, ec)) return;
  const fs::file_time_type made = newestFile(zero);
  if (made == fs::file_time_type::min()) return;
  const fs::file_time_type edited = fs::last_write_time(scene, ec);
  if (ec) return;
  const double later = std::chrono::duration<double>(edited - made).count();
  if (later <= copySlackSeconds) return;
  const std::string what = fmt::format(
      "{} was changed {:.0f} s after the particles in {} were made: the run would be of the old scene "
      "(its particles, wall friction and walls are those of 0/).\n"
      "    Run particleMesh again (./Allclean first if the case holds a run), or -force to run 0/ as it is",
      scene.string(), later, zero.string());
  if (!force) fatalError(what);
  warning(what + " (-force: running 0/ as it is)");
}

}  // namespace isph
