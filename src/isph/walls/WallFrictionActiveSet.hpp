#pragma once
// The stick/slip state of each particle on a Coulomb wall inside the implicit velocity solve
// (ImplicitViscousStep): a semi-smooth Newton (primal-dual active set) iteration on the
// regularised Coulomb law
//
//   f_a = −K_a u_t            |u_t| ≤ u_slip   (stick: K_a = F_a/u_slip)
//   f_a = −F_a u_t/|u_t|      |u_t| > u_slip   (slide: the Coulomb force)
//
// with F_a the capacity of WallFriction and u_t the tangential velocity u* − (u*·n_a) n_a.
// The law is continuous (K_a u_slip = F_a). Each pass solves the velocity system with every
// particle's law linearised in the state of the last pass: a sticking particle adds
// K_a (I − n nᵀ) to its block; a sliding one puts the constant force −F_a t on the right-hand
// side (t the slip direction of the last pass) and, in 3D, adds F_a/|u_t| (I − n nᵀ − t tᵀ),
// the stiffness of the direction. After the solve each particle is classified again from u*:
// stick → slide where |u_t| > u_slip (the stick force would exceed F_a); slide → stick where
// u_t·t ≤ u_slip (the Coulomb force would reverse the slip, or has stopped it). The iteration
// has converged when no state changes (in 3D: no slip direction turns by more than 0.01 rad):
// the last solve then satisfies the law exactly. For one particle the two states exclude
// each other (stick holds iff the driving force is at most F_a + m u_slip/dt, the condition
// for which the slide would reverse), so it settles in two passes, three if it starts
// sliding the wrong way (slide → stick → slide); coupled particles take a few more (2-4 on
// the landslide tutorials).
//
// It replaces a Picard (lagged-rate) iteration on the smooth law F_a u_t/(|u_t| + u_slip),
// which converges geometrically with the ratio of the driving force to the capacity: on the
// Bui column at 2 mm, 340 of 524 floor rods were still unsettled after 4 passes and 97 after
// 20, each step leaving the stopping ones creeping at 0.1-10 mm/s.
#include <cstddef>
#include <vector>

#include "core/Types.hpp"
#include "isph/walls/WallFriction.hpp"

namespace isph {

class WallFrictionActiveSet {
 public:
  enum class State : unsigned char { free, stick, slide };

  // The states to start from: each particle's state at the end of the last step (by origId,
  // so that reordering does not lose it), and for a particle new to the wall the one its
  // velocity at time n gives (the first n entries of u are the material's). The converged
  // states do not depend on it, only the number of passes to reach them.
  void start(const WallFriction& friction, const std::vector<Vec3>& u, const std::vector<label>& origId,
             std::size_t n);
  // The same from the capacities F_a (0: not on a friction wall), wall normals n_a and u_slip.
  void start(const std::vector<double>& capacity, const std::vector<Vec3>& normal, double slipSpeed,
             const std::vector<Vec3>& u, const std::vector<label>& origId);
  // Keep the states for the next step's start.
  void remember(const std::vector<label>& origId);
  // The kept states and slip directions, by origId: a restart writes and restores them
  // (StepState.hpp), so that its first step starts from the states the last one ended in.
  const std::vector<State>& keptStates() const { return keptState_; }
  const std::vector<Vec3>& keptDirections() const { return keptDir_; }
  void restoreKept(std::vector<State> states, std::vector<Vec3> directions) {
    keptState_ = std::move(states);
    keptDir_ = std::move(directions);
  }

  State state(std::size_t a) const { return state_[a]; }
  // Particle a's drag block, added to its diagonal block of the velocity matrix (dim × dim):
  // entry (d, e); 0 for a free particle.
  double block(std::size_t a, int d, int e) const;
  // The constant force on a's right-hand side: −F_a t while sliding, else 0.
  Vec3 force(std::size_t a) const;
  // The friction force of the wall on a in the solve of the current states with velocity u:
  // force(a) − block(a) u (stick: −K_a (I − n nᵀ) u; slide: −F_a t, plus the lateral term in 3D).
  Vec3 applied(std::size_t a, const Vec3& u, int dim) const;

  // Classify again from the solved velocities (interleaved, dim per particle); returns how
  // many particles changed state (or, sliding, turned).
  int update(const std::vector<double>& xv, int dim);


 private:
  void classify(std::size_t a, const Vec3& ut, bool& changed);
  Vec3 tangential(std::size_t a, const Vec3& u) const { return u - normal_[a] * normal_[a].dot(u); }

  double slipSpeed_ = 0;
  std::vector<State> state_;
  std::vector<Vec3> dir_;        // t, the slip direction (sliding)
  std::vector<double> stiff_;    // K_a (stick) or F_a/|u_t| (slide, the lateral stiffness)
  std::vector<double> capacity_;
  std::vector<Vec3> normal_;
  std::vector<State> keptState_;  // by origId
  std::vector<Vec3> keptDir_;
};

}  // namespace isph
