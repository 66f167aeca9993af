#pragma once
// One set of system/sampleForcesDict (or of the solver's forces function object): the wall
// patches whose forces are summed together, the centre of rotation of the moment, the
// out-of-plane width and an optional reference curve for the plot.
//
//   barrier
//   {
//       patches     (barrier);     // names from the cloud's cloudProperties
//       CofR        (0 0 0);       // optional, default (0 0 0)
//       width       0.3;           // optional (2D): force over this width; default per metre
//       facing      (-1 0 0);      // optional: only the wall particles whose normal lies within
//                                  // 60° of this direction (one face of a structure)
//       reference   "validation/barrierForce.csv";   // optional, relative to the case
//       referenceColumns (1 2);    // optional: the CSV's time and force columns (1-based)
//       filterWindow 0.01;         // optional [s]: the centred moving average of the filtered
//                                  // trace written beside the raw one (default 0.01 s, a load
//                                  // cell's rate; FilteredForces.hpp)
//       lateForceWindow 0.25;      // optional [s]: the late (deposit) force is the filtered
//                                  // trace's mean over the last this many seconds (default 0.25)
//   }
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "core/Types.hpp"
#include "particles/ParticleCloud.hpp"

namespace isph {

class Dictionary;

struct ForceSet {
  std::string name;
  std::vector<std::string> patchNames;
  Vec3 CofR = Vec3::Zero();
  std::optional<double> width;             // [m]; empty: per metre of width
  std::optional<Vec3> facing;              // only the faces whose normal is within 60° of it
  std::optional<std::string> reference;    // CSV file, relative to the case
  std::array<int, 2> referenceColumns{1, 2};
  double filterWindow = 0.01;              // [s] the filtered trace's moving-average window
  double lateForceWindow = 0.25;           // [s] the late force: the filtered mean over the last this long
  SourceLocation where;                    // the set's dictionary
  SourceLocation patchesWhere;             // its `patches` entry

  double widthOrUnit() const { return width.value_or(1.0); }
};

// Reads one set from its sub-dictionary (FatalError naming file, line and keyword for a
// missing or bad entry; warns about unknown keywords).
ForceSet readForceSet(const std::string& name, const Dictionary& dict);

// Every sub-dictionary of `dict` (FoamFile aside) as a set; FatalError when there is none.
// Top-level keywords listed in `topLevel` (e.g. cloud) are allowed beside the sets.
std::vector<ForceSet> readForceSets(const Dictionary& dict, const std::vector<std::string>& topLevel = {});

// The patch labels of `set` in a cloud with `props`; FatalError at the `patches` entry for
// an unknown name, listing the cloud's patches.
std::vector<label> patchLabels(const ForceSet& set, const CloudProperties& props);

}  // namespace isph
