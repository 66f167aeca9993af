#pragma once
// system/decomposeParDict, as OpenFOAM's, for particles:
//
//   numberOfSubdomains  4;
//   method              zoltan;          // the only method: Zoltan's geometric partitioners
//   zoltanCoeffs
//   {
//       algorithm       RCB;             // RCB (recursive coordinate bisection) | HSFC (Hilbert
//                                        //   space-filling curve)
//   }
//   repartitionFactor   1.1;             // optional: the solver partitions the particles anew when
//                                        //   the most loaded rank carries more than this factor
//                                        //   times the mean load (checked every 50 steps)
//
// decomposePar writes numberOfSubdomains processor directories; a solver run with -parallel
// checks that mpirun started that many ranks.
#include <filesystem>
#include <string>

namespace isph {

class Dictionary;

struct DecompositionSettings {
  int numberOfSubdomains = 1;
  std::string algorithm = "RCB";  // Zoltan's LB_METHOD
  double repartitionFactor = 1.1;

  // FatalError at the keyword's line for a missing or bad entry.
  static DecompositionSettings read(const Dictionary& dict);
  // <case>/system/decomposeParDict; FatalError naming the file when it is missing.
  static DecompositionSettings read(const std::filesystem::path& caseDir);
};

}  // namespace isph
