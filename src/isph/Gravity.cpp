#include "isph/Gravity.hpp"

#include <fmt/format.h>

#include "core/Log.hpp"
#include "core/Plausibility.hpp"
#include "core/dictionary/Dictionary.hpp"

namespace isph {

Vec3 readGravity(const std::filesystem::path& caseDir) {
  const Dictionary d = Dictionary::readFile(caseDir / "constant" / "g");
  if (const auto dims = d.found("dimensions") ? d.getDimensions("dimensions") : std::nullopt) {
    const DimensionSet acceleration{{0, 1, -2, 0, 0, 0, 0}};
    if (!(*dims == acceleration)) {
      fatalIOError(d.findEntry("dimensions")->location(),
                   "constant/g: dimensions must be those of an acceleration, [0 1 -2 0 0 0 0]");
    }
  }
  const Vec3 g = d.get<Vec3>("value");
  d.checkKeywords();
  warnIfImplausibleGravity(g, d.findEntry("value")->location());
  // (a note: runApplication shows it on the terminal)
  info("--> Note: g = ({:.4g} {:.4g} {:.4g}) m/s^2, |g| = {:.4g} m/s^2: {:.1f} deg from -y, the slope of a bed "
       "along x",
       g.x(), g.y(), g.z(), g.norm(), slopeFromGravity(g));
  return g;
}

}  // namespace isph
