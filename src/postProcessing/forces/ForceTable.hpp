#pragma once
// The columns of a set's force history, postProcessing/sampleForces/<firstTime>/<set>.dat
// (and the solver's patchForces function object, postProcessing/<name>/<startTime>/force.dat):
// comment lines that state the set and the conventions, then a `# Time [s] Fx [N/m] ...`
// line naming every column with its unit, then one tab-separated row per time.
//
// Columns in 2D (3D adds the z components and the x, y moments):
//   Time  Fx Fy Fn Ft  Fpx Fpy Fpn Fpt  Fdx Fdy Fdn Fdt  Ffx Ffy Ffn Fft  Mz Mpz Mdz Mfz  nWall
// F: total force, Fp: pressure part, Fd: deviatoric part, Ff: friction part; n/t: normal and tangential
// components (PatchForces.hpp); M: moment about CofR; nWall: wall particles summed.
// Units: N and N m when the set has a width, else N/m and N m/m (per metre of width).
#include <string>
#include <vector>

#include "postProcessing/forces/ForceSet.hpp"
#include "postProcessing/forces/PatchForces.hpp"

namespace isph {

struct ForceColumn {
  std::string name;
  std::string unit;
};

class ForceTable {
 public:
  ForceTable(const ForceSet& set, int dimension);

  const std::vector<ForceColumn>& columns() const { return columns_; }
  // 1-based column number of `name` (gnuplot's numbering); FatalError for an unknown name.
  int column(const std::string& name) const;

  // The comment lines; `first` gives the mean normal and tangent they state.
  std::string header(const PatchForces& first) const;
  std::string row(double time, const PatchForces& f) const;

 private:
  ForceSet set_;
  int dimension_;
  std::vector<ForceColumn> columns_;
};

}  // namespace isph
