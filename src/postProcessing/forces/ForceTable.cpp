#include "postProcessing/forces/ForceTable.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/Error.hpp"

namespace isph {

namespace {

const char* const axes = "xyz";

std::string vec(const Vec3& v) { return fmt::format("({:.6g} {:.6g} {:.6g})", v.x(), v.y(), v.z()); }

}  // namespace

ForceTable::ForceTable(const ForceSet& set, int dimension) : set_(set), dimension_(dimension) {
  const bool perMetre = dimension == 2 && !set.width;
  const std::string force = perMetre ? "N/m" : "N";
  const std::string moment = perMetre ? "N m/m" : "N m";
  columns_.push_back({"Time", "s"});
  for (const std::string part : {"F", "Fp", "Fd", "Ff"}) {
    for (int d = 0; d < dimension; ++d) columns_.push_back({part + axes[d], force});
    columns_.push_back({part + "n", force});
    columns_.push_back({part + "t", force});
  }
  for (const std::string part : {"M", "Mp", "Md", "Mf"}) {
    for (int d = dimension == 2 ? 2 : 0; d < 3; ++d) columns_.push_back({part + axes[d], moment});
  }
  columns_.push_back({"nWall", "-"});
}

int ForceTable::column(const std::string& name) const {
  for (std::size_t k = 0; k < columns_.size(); ++k) {
    if (columns_[k].name == name) return static_cast<int>(k) + 1;
  }
  fatalError(fmt::format("force table of set '{}' has no column '{}'", set_.name, name));
}

std::string ForceTable::header(const PatchForces& first) const {
  std::string h = fmt::format("# Forces of the material on set '{}': patches ({}){}, CofR {}", set_.name,
                              fmt::join(set_.patchNames, " "),
                              set_.facing ? fmt::format(" (the faces facing {})", vec(*set_.facing)) : std::string(),
                              vec(set_.CofR));
  if (dimension_ == 2) {
    h += set_.width ? fmt::format(", width {} m (forces over the width)\n", *set_.width)
                    : ", per metre of width\n";
  } else {
    h += "\n";
  }
  h += "# F = Fp + Fd + Ff: pressure part Fp = sum p A (-n), deviatoric part Fd = sum A tau.n, friction part "
       "Ff = sum A t over the wall particles (n: wall normal, into the material; t: the Coulomb wall friction "
       "traction; where the material slides on the walls the walls act on it by p and t only, and Fd = 0)\n";
  h += fmt::format("# n: normal component -F.nMean (positive into the structure), nMean = {}\n", vec(first.meanNormal));
  if (dimension_ == 2) {
    h += fmt::format("# t: tangential component F.t, t = nMean x z = {}\n", vec(first.tangent));
  } else {
    h += "# t: magnitude of the tangential part |F - (F.nMean) nMean|\n";
  }
  h += "# M: moment about CofR (Mp, Md, Mf: of the pressure, deviatoric and friction parts); nWall: wall particles "
       "summed\n";
  h += "#";
  for (std::size_t k = 0; k < columns_.size(); ++k) {
    h += fmt::format("{}{} [{}]", k ? "\t" : " ", columns_[k].name, columns_[k].unit);
  }
  return h + "\n";
}

std::string ForceTable::row(double time, const PatchForces& f) const {
  std::string r = fmt::format("{:.8g}", time);
  auto add = [&](double v) { r += fmt::format("\t{:.8g}", v == 0 ? 0.0 : v); };  // no "-0"
  for (const Vec3* F : {&f.total, &f.pressure, &f.deviatoric, &f.friction}) {
    for (int d = 0; d < dimension_; ++d) add((*F)[d]);
    add(f.normal(*F));
    add(f.tangential(*F));
  }
  for (const Vec3* M : {&f.momentTotal, &f.momentPressure, &f.momentDeviatoric, &f.momentFriction}) {
    for (int d = dimension_ == 2 ? 2 : 0; d < 3; ++d) add((*M)[d]);
  }
  r += fmt::format("\t{}", f.nWall);
  return r + "\n";
}

}  // namespace isph
