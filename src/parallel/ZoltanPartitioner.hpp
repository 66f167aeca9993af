#pragma once
// Zoltan's geometric partitioners (RCB, HSFC) over a set of weighted points spread over the
// ranks of MPI_COMM_WORLD: a partition into nParts parts of nearly equal weight, and, from the
// cuts it keeps, the part of any point (where a particle that has moved belongs now).
//
//   ZoltanPartitioner zoltan("RCB", 2, nRanks());
//   std::vector<int> part = zoltan.partition(positions, weights, ids);  // collective
//   int p = zoltan.partOf(x);                                           // local
//
// nParts may differ from the number of ranks: decomposePar partitions a whole case on one
// rank into numberOfSubdomains parts. The partition is Zoltan's with the parameters listed in
// the source (REMAP: a new partition keeps each part on the rank that holds most of it), so
// it is repeatable for the same points. Nothing here assumes 2D: `dimension` coordinates of
// each point are used.
#include <string>
#include <vector>

#include "core/Types.hpp"

struct Zoltan_Struct;

namespace isph {

class ZoltanPartitioner {
 public:
  // algorithm: RCB | HSFC; FatalError for another name.
  ZoltanPartitioner(const std::string& algorithm, int dimension, int nParts);
  ~ZoltanPartitioner();
  ZoltanPartitioner(const ZoltanPartitioner&) = delete;
  ZoltanPartitioner& operator=(const ZoltanPartitioner&) = delete;

  // The part of each of this rank's points (collective): a new partition of all ranks'
  // points, each point in the part of its region by the kept cuts (equal points, one part).
  // `ids` are unique over all ranks (the particles' origId).
  std::vector<int> partition(const std::vector<Vec3>& points, const std::vector<double>& weights,
                             const std::vector<label>& ids);
  // The part whose region holds x, from the cuts of the last partition (FatalError before one).
  int partOf(const Vec3& x) const;

  const std::string& algorithm() const { return algorithm_; }
  int nParts() const { return nParts_; }

 private:
  std::string algorithm_;
  int dimension_;
  int nParts_;
  Zoltan_Struct* zz_ = nullptr;
  bool partitioned_ = false;
};

// The largest load of the parts over their mean (1 for a perfect balance), from each part's
// load; 1 for no load.
double imbalance(const std::vector<double>& loads);

}  // namespace isph
