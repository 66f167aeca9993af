#pragma once
// The particles of a parallel run (doc/parallel.md), spread over the MPI ranks: each rank owns
// a part of them (Zoltan's partition, system/decomposeParDict) and, for a step, holds ghosts,
// copies of the other ranks' particles within the kernel support (Halo), laid out as
// ParticleSystem.hpp says (own particles of each kind first, then that kind's ghosts).
// ParticleSolver keeps one when it runs with -parallel and calls it where its source says
// "parallel:":
//   read()        this rank's particles of the start time: processor<rank>/<start> of a
//                 decomposed case, or, for an undecomposed start, <start> read by rank 0;
//   distribute()  partitions them (every dummy particle goes with its wall particle) and moves
//                 each to its rank, before initialiseParticleSystem;
//   beginStep()   drops the last step's ghosts; on the steps the serial solver reorders its
//                 particles (every 50), moves those that have left their rank's part (by the
//                 partition's kept cuts) and partitions anew when the most loaded rank carries
//                 more than repartitionFactor × the mean load (both logged), then orders the own
//                 material by cell and numbers its rows; builds the ghosts and the
//                 ParticleSystem of own and ghost particles.
// Between two redistributions a rank owns the same particles, so the linear systems keep their
// numbering (and an AMG hierarchy its matrix shape), as in a serial run between reorderings.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/time/Time.hpp"
#include "isph/ParticleSystem.hpp"
#include "isph/materials/MaterialTable.hpp"
#include "parallel/DecompositionDict.hpp"
#include "parallel/Halo.hpp"
#include "parallel/ZoltanPartitioner.hpp"

namespace isph {

class DistributedParticles {
 public:
  // Reads system/decomposeParDict; FatalError when its numberOfSubdomains is not the number
  // of ranks, or when the processor directories do not match them.
  explicit DistributedParticles(const Time& time);
  ~DistributedParticles();

  // This rank's particles of cloud `name` at the start time (collective).
  ParticleCloud read(const Time& time, const std::string& name) const;
  // Partitions the particles and sends each to its rank (collective); `wallRadius` bounds the
  // search for a dummy particle's wall (as initialiseParticleSystem's).
  void distribute(ParticleCloud& cloud, double wallRadius);
  // See the header (collective). `time` names the step in the log of a repartition.
  void beginStep(ParticleSystem& ps, const MaterialTable& materials, double supportRadius, bool redistribute,
                 const Time& time);

  // The partition's balance: the largest rank's load over the mean load, now and over the
  // run's checks; for the log.
  std::string balanceSummary() const;

 private:
  void dropGhosts(ParticleSystem& ps);
  void redistribute(ParticleSystem& ps, double supportRadius, const Time& time);
  void buildGhosts(ParticleSystem& ps, const MaterialTable& materials, double supportRadius);
  // The load of each rank (collective) and its imbalance.
  double imbalanceOf(double load, std::vector<double>* loads = nullptr) const;

  DecompositionSettings settings_;
  std::filesystem::path processorDir_;  // processor<rank>: its decomposition record (DecompositionRecord.hpp)
  std::unique_ptr<ZoltanPartitioner> zoltan_;
  std::unique_ptr<Halo> halo_;
  std::vector<label> parentId_;  // per particle of ps.cloud: a dummy's wall particle's origId, else -1
  bool adopted_ = false;
  long firstRow_ = 0;
  int checks_ = 0, repartitions_ = 0;
  double lastImbalance_ = 1, worstImbalance_ = 1, imbalanceSum_ = 0;
  long ghostSum_ = 0, steps_ = 0;
};

// What a rank owns of a ParticleSystem (its output, its mean neighbours): OwnedParticles.hpp.

}  // namespace isph
