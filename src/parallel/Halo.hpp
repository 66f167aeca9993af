#pragma once
// The ghost (halo) particles of a rank: copies of the other ranks' particles within the kernel
// support of any of its own, so that every pair loop over its own particles sees all their
// neighbours. A particle is sent to each rank whose particles' bounding box, grown by the
// support radius on every side, holds it: a superset of the pairs (exact for the pair loops),
// from one gather of the boxes, whatever the shape of the parts. A particle may name a
// companion that travels with it wherever it goes as a ghost (a dummy particle's wall, whose
// normal the dummy uses).
//
// After the caller has placed the ghosts in its arrays (setLayout), exchange(field) copies
// each owner's value of a field to its ghosts: the "halo exchange" after every update of a
// field that a pair loop reads. A field of the length of the material particles alone
// exchanges only theirs. Everything here is collective but nGhosts() and the index lists.
#include <memory>
#include <vector>

#include "core/Types.hpp"
#include "parallel/CommPlan.hpp"
#include "parallel/ParticleFields.hpp"

namespace isph {

class Halo {
 public:
  // positions: this rank's particles; radius: the kernel support; companion[i] >= 0: the
  // particle that goes with i (empty: none).
  Halo(const std::vector<Vec3>& positions, double radius, int dimension, const std::vector<int>& companion = {});

  std::size_t nSent() const { return sent_.size(); }
  std::size_t nGhosts() const { return plan_->nReceived(); }
  // The index (in `positions`) of each particle sent, in send order (one entry per rank sent to).
  const std::vector<std::size_t>& sent() const { return sent_; }

  // Sends the fields of the particles (`owned`, indexed as `positions`) and appends the
  // ghosts, in receive order, to `ghosts` (the same fields).
  void sendParticles(const ParticleFields& owned, ParticleFields& ghosts) const;

  // Where exchange() reads and writes in the caller's arrays of nLocal particles: the index of
  // each sent particle (send order) and of each ghost (receive order). Those below nMaterial
  // are the material particles, the only ones exchanged for a field of length nMaterial.
  void setLayout(std::vector<std::size_t> sendLocal, std::vector<std::size_t> ghostLocal, std::size_t nLocal,
                 std::size_t nMaterial);

  // Each ghost's entry of `field` from its owner (collective). The field's length is nLocal,
  // or nMaterial (the material particles' entries alone); FatalError otherwise.
  template <class T>
  void exchange(std::vector<T>& field) const;

 private:
  struct Exchange {
    const CommPlan* plan = nullptr;
    std::vector<std::size_t> from, to;
  };
  const Exchange& exchangeFor(std::size_t length) const;

  std::vector<std::size_t> sent_;
  std::vector<int> destination_;  // of each sent item
  std::unique_ptr<CommPlan> plan_, materialPlan_;
  Exchange all_, material_;
  std::size_t nLocal_ = 0, nMaterial_ = 0;
  bool laidOut_ = false;
};

template <class T>
void Halo::exchange(std::vector<T>& field) const {
  const Exchange& e = exchangeFor(field.size());
  std::vector<T> out(e.from.size());
  for (std::size_t k = 0; k < e.from.size(); ++k) out[k] = field[e.from[k]];
  const std::vector<T> in = e.plan->exchange(out);
  for (std::size_t k = 0; k < e.to.size(); ++k) field[e.to[k]] = in[k];
}

}  // namespace isph
