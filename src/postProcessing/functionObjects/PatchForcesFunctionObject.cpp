#include "postProcessing/functionObjects/PatchForcesFunctionObject.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <utility>

#include "core/Log.hpp"
#include "core/ParallelRun.hpp"
#include "core/io/ReadFile.hpp"
#include "postProcessing/forces/FilteredForces.hpp"
#include "postProcessing/forces/SetForces.hpp"

namespace isph {

namespace {

namespace fs = std::filesystem;

// The rows of the earlier runs of a continued case: postProcessing/<name>/<t0>/force.dat for
// every start time t0 before `start`, in time order, each up to and with the next start time
// (a run writes no row at its own start).
std::vector<std::vector<double>> earlierRows(const fs::path& dir, const std::string& fileName, double start) {
  std::vector<std::pair<double, fs::path>> starts;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    double t = 0;
    const auto [ptr, err] = std::from_chars(name.data(), name.data() + name.size(), t);
    if (err != std::errc() || ptr != name.data() + name.size() || !(t < start)) continue;
    if (fs::is_regular_file(it->path() / fileName)) starts.emplace_back(t, it->path() / fileName);
  }
  std::sort(starts.begin(), starts.end());
  std::vector<std::vector<double>> rows;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const double until = k + 1 < starts.size() ? starts[k + 1].first : start;
    for (auto& r : readForceRows(readFileBytes(starts[k].second))) {
      if (r[0] <= until) rows.push_back(std::move(r));  // the later run has no row at its start time
    }
  }
  return rows;
}

}  // namespace

PatchForcesFunctionObject::PatchForcesFunctionObject(const std::string& name, const Dictionary& dict,
                                                     const Time& time)
    : FunctionObject(name, dict),
      set_{readForceSet(name, dict)},
      file_(time.path() / "postProcessing" / name / time.timeName() / "force.dat"),
      out_(file_, fmt::format("function object '{}'", name)) {
  if (isMasterRank()) {
    dropHalfRows(file_.parent_path().parent_path(), file_.filename().string());
    rows_ = earlierRows(file_.parent_path().parent_path(), file_.filename().string(), time.value());
  }
}

void PatchForcesFunctionObject::execute(const Time& time, const SolverState& state) {
  const auto forces = setForces({.cloud = state.cloud,
                                 .sets = set_,
                                 .tau = state.tau,
                                 .kernel = state.kernel,
                                 .neighbours = state.neighbours,
                                 .wallFriction = state.wallFriction,
                                 .owned = state.owned});
  if (!isMasterRank()) return;  // a parallel run's file is rank 0's
  std::string text;
  if (!table_) {
    table_.emplace(set_[0], state.cloud.properties.dimension);
    header_ = table_->header(forces[0]);
    text = header_;
    // Rows of earlier runs from another table (a changed set or dimension) are not joined.
    std::erase_if(rows_, [&](const auto& r) { return r.size() != table_->columns().size(); });
  }
  const std::string row = table_->row(time.value(), forces[0]);
  text += row;
  out_.write(text);
  rows_.push_back(readForceRows(row).front());
  if (time.writeTime()) writeFiltered();
}

void PatchForcesFunctionObject::end(const Time& /*time*/) {
  if (!isMasterRank() || !table_) return;
  const ForceFigures f = writeFiltered();
  const std::string unit = table_->columns()[1].unit;
  info("{}: filtered ({:g} s) peak Fn {:.6g} {} at {:.6g} s, late force {:.6g} {} (last {:g} s), raw maximum {:.6g} {} "
       "-> {}",
       name(), set_[0].filterWindow, f.filteredPeak, unit, f.filteredPeakTime, f.lateForce, unit,
       set_[0].lateForceWindow, f.rawMax, unit, (file_.parent_path() / "forceFigures.txt").string());
}

ForceFigures PatchForcesFunctionObject::writeFiltered() const {
  return writeFilteredForces(set_[0], *table_, header_, rows_, file_.parent_path() / "forceFiltered.dat",
                             file_.parent_path() / "forceFigures.txt");
}

std::string PatchForcesFunctionObject::describe() const {
  const ForceSet& s = set_[0];
  return fmt::format("{}: patchForces on ({}){}, CofR ({} {} {}), {}, every {} step(s) -> {}", name(),
                     fmt::join(s.patchNames, " "),
                     s.facing ? fmt::format(" facing ({} {} {})", s.facing->x(), s.facing->y(), s.facing->z())
                              : std::string(),
                     s.CofR.x(), s.CofR.y(), s.CofR.z(),
                     s.width ? fmt::format("over a width of {} m (2D)", *s.width) : "per metre of width (2D)",
                     writeInterval(), file_.string()) +
         fmt::format(" (filtered over {:g} s: forceFiltered.dat, forceFigures.txt)", s.filterWindow);
}

namespace {

const bool registered = FunctionObjectRegistry::add(
    "patchForces", [](const std::string& name, const Dictionary& dict, const Time& time) {
      return std::make_unique<PatchForcesFunctionObject>(name, dict, time);
    });

}  // namespace

}  // namespace isph
