#include "postProcessing/functionObjects/MomentumBalanceFunctionObject.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/ParallelRun.hpp"
#include "parallel/Reduce.hpp"

namespace isph {

MomentumBalanceFunctionObject::MomentumBalanceFunctionObject(const std::string& name, const Dictionary& dict,
                                                             const Time& time)
    : FunctionObject(name, dict),
      width_(dict.getOptional<double>("width")),
      file_(time.path() / "postProcessing" / name / time.timeName() / "momentum.dat"),
      out_(file_, fmt::format("function object '{}'", name)) {
  if (isMasterRank()) dropHalfRows(file_.parent_path().parent_path(), file_.filename().string());
  if (width_ && !(*width_ > 0)) {
    fatalIOError(dict.entry("width").location(),
                 fmt::format("keyword 'width' of function object '{}' is {}; expected a positive width in metres",
                             name, *width_));
  }
}

void MomentumBalanceFunctionObject::execute(const Time& time, const SolverState& state) {
  if (!state.gravity) {
    fatalError(fmt::format("function object '{}' (momentumBalance) needs the solver's gravity", name()));
  }
  const ParticleCloud& c = state.cloud;
  const int dim = c.properties.dimension;
  if (width_ && dim != 2) {
    fatalError(fmt::format("function object '{}': 'width' scales 2D forces per metre; this case is {}D", name(), dim));
  }
  const double scale = width_ ? *width_ : 1.0;
  double M = 0;
  Vec3 P = Vec3::Zero();
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c.kind[i] != static_cast<label>(ParticleKind::material)) continue;
    if (state.owned && !(*state.owned)[i]) continue;  // a ghost: its owner counts it
    M += c.mass[i];
    P += c.mass[i] * c.U[i];
  }
  if (state.owned) M = sumOverRanks(M), P = sumOverRanks(P);  // a parallel run: all ranks
  M *= scale;
  P *= scale;
  const double t = time.value();
  if (!havePrevious_ || !(t > previousTime_)) {  // the first row needs a second momentum
    havePrevious_ = true;
    previousTime_ = t;
    previousMomentum_ = P;
    return;
  }
  const Vec3 dPdt = (P - previousMomentum_) / (t - previousTime_);
  const Vec3 W = M * *state.gravity;
  const Vec3 F = W - dPdt;
  previousTime_ = t;
  previousMomentum_ = P;

  if (!isMasterRank()) return;  // a parallel run's file is rank 0's
  const char* axes[] = {"x", "y", "z"};
  std::string text;
  if (!out_.started()) {
    const std::string mass = width_ ? "kg" : "kg/m";
    const std::string force = width_ ? "N" : "N/m";
    const std::string momentum = width_ ? "kg m/s" : "kg m/s/m";
    text = fmt::format("# Momentum balance of the material (function object '{}'), {}\n", name(),
                       width_ ? fmt::format("over a width of {} m", *width_) : std::string("per metre of width"));
    text += "# F = W - dP/dt: the force of the material on all walls together (W = M g; dP/dt the mean over the "
            "interval since the previous row)\n# Time [s]\tM [" + mass + "]";
    for (int d = 0; d < dim; ++d) text += fmt::format("\tP{} [{}]", axes[d], momentum);
    for (int d = 0; d < dim; ++d) text += fmt::format("\tdP{}/dt [{}]", axes[d], force);
    for (int d = 0; d < dim; ++d) text += fmt::format("\tW{} [{}]", axes[d], force);
    for (int d = 0; d < dim; ++d) text += fmt::format("\tF{} [{}]", axes[d], force);
    text += "\n";
  }
  text += fmt::format("{:.8g}\t{:.8g}", t, M);
  const Vec3* values[] = {&P, &dPdt, &W, &F};
  for (const Vec3* v : values) {
    for (int d = 0; d < dim; ++d) text += fmt::format("\t{:.8g}", (*v)[d]);
  }
  text += "\n";
  out_.write(text);
}

std::string MomentumBalanceFunctionObject::describe() const {
  return fmt::format("{}: momentumBalance of the material (F = M g - dP/dt, the force on all walls), {}, every {} "
                     "step(s) -> {}",
                     name(), width_ ? fmt::format("over a width of {} m (2D)", *width_) : "per metre of width (2D)",
                     writeInterval(), file_.string());
}

namespace {

const bool registered = FunctionObjectRegistry::add(
    "momentumBalance", [](const std::string& name, const Dictionary& dict, const Time& time) {
      return std::make_unique<MomentumBalanceFunctionObject>(name, dict, time);
    });

}  // namespace

}  // namespace isph
