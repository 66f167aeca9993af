// sampleLithostatic: how far a granular layer at rest is from the infinite-slope
// (lithostatic) pressure p = rho |g| cos(beta) depth, for the selected times, as
// system/sampleLithostaticDict says (gravity from constant/g):
//
//   rho        1800;        // the material's density [kg/m^3]
//   height     0.1;         // H: the spread is given as a fraction of rho |g| H [m]
//   normal     (0 1 0);     // optional: the bed normal, out of the layer (default y)
//   xMin       0.15;        // optional: the interior along x, away from the end walls [m]
//   xMax       0.45;
//   minDepth   0.01;        // optional: the interior is deeper than this [m] (default 0)
//   phi        30;          // optional: the friction angle [deg], to count the particles at yield
//   reference  0;           // optional: the time whose cloud the displacement is measured
//                           // from (default: the first time of the case)
//
// (src/postProcessing/sampling/Lithostatic.hpp has the definitions.) Writes
// postProcessing/sampleLithostatic/<firstTime>/lithostatic.dat: Time [s], the relative L2
// error of p, the interior spread of (p - p_lith)/(rho |g| H), the largest displacement [m];
// where the time has tau, what statics fix whatever the layer's K0 (SlopeTraction.hpp): the
// L2 errors and interior spreads of sigma_nn and sigma_nt, and the share of particles at yield.
#include <filesystem>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/app/Application.hpp"
#include "core/app/SkippedTimes.hpp"
#include "core/app/TimeOptions.hpp"
#include "parallel/DecomposedCase.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "core/io/AtomicFile.hpp"
#include "isph/Gravity.hpp"
#include "particles/CloudIO.hpp"
#include "postProcessing/forces/WallStress.hpp"
#include "postProcessing/sampling/Lithostatic.hpp"
#include "postProcessing/sampling/SlopeTraction.hpp"

namespace {

namespace fs = std::filesystem;

const isph::ApplicationSpec spec{
    .name = "sampleLithostatic",
    .description = "Error of a layer at rest against statics, from system/sampleLithostaticDict: the pressure against the "
                   "lithostatic one and, where tau is written, the traction on planes parallel to the bed (sigma_nn, sigma_nt).",
    .options = {{"cloud", "name", "the cloud (default: particles)"}, isph::SkippedTimes::option()},
    .arguments = {},
    .timeOptions = true,
    .parallel = true,
};

void run(const isph::ArgList& args) {
  const isph::Dictionary dict = isph::Dictionary::readFile(args.casePath() / "system" / "sampleLithostaticDict");
  isph::LithostaticSpec s;
  s.rho = dict.get<double>("rho");
  if (!(s.rho > 0)) isph::fatalIOError(dict.findEntry("rho")->location(), "rho: expected a positive density");
  s.height = dict.get<double>("height");
  if (!(s.height > 0)) isph::fatalIOError(dict.findEntry("height")->location(), "height: expected a positive length");
  s.normal = dict.getOrDefault("normal", s.normal);
  if (!(s.normal.norm() > 0)) isph::fatalIOError(dict.findEntry("normal")->location(), "normal: expected a non-zero vector");
  s.xMin = dict.getOrDefault("xMin", s.xMin);
  s.xMax = dict.getOrDefault("xMax", s.xMax);
  if (!(s.xMax > s.xMin)) isph::fatalIOError(dict.findEntry("xMax")->location(), "xMax: expected more than xMin");
  s.minDepth = dict.getOrDefault("minDepth", s.minDepth);
  const auto referenceTime = dict.getOptional<double>("reference");
  const double phi = dict.getOrDefault("phi", 0.0);  // [deg]: counts the particles at yield when given
  if (!(phi >= 0 && phi < 90)) isph::fatalIOError(dict.findEntry("phi")->location(), "phi: expected an angle in degrees in [0, 90)");
  dict.checkKeywords();
  s.g = isph::readGravity(args.casePath());

  const std::string cloudName = args.option("cloud").value_or("particles");
  const bool decomposed = args.found("parallel");
  const auto all = decomposed ? isph::decomposedTimes(args.casePath()) : isph::listTimes(args.casePath());
  if (all.empty()) isph::fatalError(fmt::format("no time directories in {}", args.casePath().string()));
  std::string referenceName = all.front().name;
  if (referenceTime) {
    const auto picked = isph::selectTimes(all, {.ranges = fmt::format("{}", *referenceTime)});
    if (picked.empty()) {
      isph::fatalIOError(dict.findEntry("reference")->location(), fmt::format("reference: no time {} in the case", *referenceTime));
    }
    referenceName = picked.front().name;
  }
  const auto times = isph::selectedTimes(args);
  const isph::ParticleCloud start =
      isph::readCloud(isph::DecomposedTime(args.casePath(), referenceName, decomposed).path(), cloudName);

  std::string text = fmt::format("# p against rho |g| cos(beta) depth, rho {} kg/m^3, g ({} {} {}), normal ({} {} {})\n", s.rho,
                                 s.g.x(), s.g.y(), s.g.z(), s.normal.x(), s.normal.y(), s.normal.z());
  text += fmt::format("# spread over {} < x < {}, depth > {} m, in units of rho |g| H, H = {} m; displacement from time {}\n",
                      s.xMin, s.xMax, s.minDepth, s.height, referenceName);
  text += "# Time[s] l2[-] spread[-] maxDisplacement[m] l2SigmaNn[-] l2SigmaNt[-] spreadSigmaNn[-] spreadSigmaNt[-] "
          "atYield[-]\n";
  isph::SkippedTimes skipped(args);  // a time that cannot be read: an error, or skipped (-skipDamaged)
  for (const auto& time : times) {
    std::optional<std::vector<isph::SymmTensor>> tau;
    const auto cloud = skipped.read(time, [&] {
      const isph::DecomposedTime at(args.casePath(), time.name, decomposed);
      isph::ParticleCloud c = isph::readCloud(at.path(), cloudName);
      tau = isph::readDeviatoricStress(at.path(), cloudName, c.size());
      return c;
    });
    if (!cloud) continue;
    const isph::LithostaticError e = isph::lithostaticError(*cloud, s);
    const double moved = isph::largestDisplacement(start, *cloud);
    isph::info("Time = {}  l2 {:.6g}  spread {:.6g}  maxDisplacement {:.6g} m  ({} interior particles)", time.name, e.l2,
               e.spread, moved, e.interior);
    text += fmt::format("{} {:.8g} {:.8g} {:.8g}", time.value, e.l2, e.spread, moved);
    if (tau) {  // statics: the traction on planes parallel to the bed (SlopeTraction.hpp)
      const isph::SlopeTractionError t = isph::slopeTractionError(*cloud, *tau, s, phi);
      isph::info("    sigma_nn: l2 {:.6g} spread {:.6g}; sigma_nt: l2 {:.6g} spread {:.6g}; at yield {:.4g}", t.l2Normal,
                 t.spreadNormal, t.l2Shear, t.spreadShear, t.atYield);
      text += fmt::format(" {:.8g} {:.8g} {:.8g} {:.8g} {:.8g}", t.l2Normal, t.l2Shear, t.spreadNormal, t.spreadShear,
                          t.atYield);
    }
    text += "\n";
  }
  skipped.finish(times.size());
  const fs::path out = args.casePath() / "postProcessing" / "sampleLithostatic" / times.front().name / "lithostatic.dat";
  fs::create_directories(out.parent_path());
  isph::writeFileAtomic(out, text);
  isph::info("\nWritten {}", out.string());
}

}  // namespace

int main(int argc, char* argv[]) { return isph::runApplication(spec, argc, argv, run); }
