// The run-time controller: start time, stepping, write times, controlDict re-reading (the
// signals that stop a run: StopSignal.hpp).
#include "core/time/Time.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <ctime>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/ParallelRun.hpp"
#include "core/io/AtomicFile.hpp"
#include "core/io/FoamFileHeader.hpp"
#include "core/time/StopSignal.hpp"
#include "core/time/TimeName.hpp"

namespace isph {

namespace fs = std::filesystem;

namespace {

const std::vector<std::string> otherControlDictKeywords{"application", "functions", "libs"};

fs::file_time_type modificationTime(const fs::path& file) {
  std::error_code ec;
  const auto t = fs::last_write_time(file, ec);
  return ec ? fs::file_time_type{} : t;
}

}  // namespace

Time::Time(const fs::path& caseDir) : Time(caseDir, std::string()) {}

Time::Time(const fs::path& caseDir, const std::string& processorDir)
    : caseDir_(caseDir),
      processorDir_(processorDir),
      timesDir_(processorDir.empty() ? caseDir : caseDir / processorDir),
      controlDictFile_(caseDir / "system" / "controlDict"),
      controlDictTime_(modificationTime(controlDictFile_)),
      controlDict_(Dictionary::readFile(controlDictFile_)),
      settings_(ControlSettings::read(controlDict_)),
      wallStart_(std::chrono::steady_clock::now()) {
  controlDict_.checkKeywords(otherControlDictKeywords);
  precision_ = settings_.timePrecision;
  deltaT_ = deltaT0_ = deltaTSave_ = settings_.deltaT;
  endTime_ = settings_.endTime;
  stopAt_ = settings_.stopAt;

  // A processor folder without times: the undecomposed start of a parallel run.
  std::vector<Instant> times = listTimes(timesDir_);
  fs::path startRoot = timesDir_;
  if (times.empty() && !processorDir_.empty()) {
    times = listTimes(caseDir_);
    startRoot = caseDir_;
  }
  if (!processorDir_.empty() && settings_.startFrom == StartFrom::latestTime) keepCommonTimes(times);
  const Instant* start = nullptr;
  switch (settings_.startFrom) {
    case StartFrom::firstTime:
      start = times.empty() ? nullptr : &times.front();
      break;
    case StartFrom::latestTime:
      start = times.empty() ? nullptr : &times.back();
      break;
    case StartFrom::startTime:
      start = findTime(times, settings_.startTime, 1e-12);
      break;
  }
  // Without time directories firstTime and latestTime start at 0, as in OpenFOAM.
  value_ = start ? start->value
                 : (settings_.startFrom == StartFrom::startTime ? settings_.startTime : 0.0);
  name_ = start ? start->name : isph::timeName(value_, precision_);
  writeOrigin_ = value_;
  startPath_ = startRoot / name_;
  restoreTimeState();
  startTime_ = value_;
  startName_ = name_;
}

// A parallel run's latest time is the latest that every processor directory holds: a run
// killed while its ranks wrote (or purged) leaves a time in some of them only.
void Time::keepCommonTimes(std::vector<Instant>& times) const {
  bool dropped = false;
  for (;;) {
    if (agreeOverRanks(times.empty())) break;  // (a rank without times: DistributedParticles says so)
    // (the ranks' times of one run have the same names, so the same values)
    const double common = agreeOnMinimum(times.back().value);
    for (; !times.empty() && times.back().value > common; dropped = true) times.pop_back();
    const bool held = !times.empty() && times.back().value == common;
    if (!agreeOverRanks(!held)) break;  // every rank holds it
    if (held) times.pop_back(), dropped = true;
  }
  if (agreeOverRanks(dropped) && !times.empty()) {
    warning(fmt::format("a time later than {} is not in every processor directory of {} (a parallel run was "
                        "stopped while it wrote): the run starts from {}, the latest time all of them hold",
                        times.back().name, caseDir_.string(), times.back().name));
  }
}

// Restart contract: <start>/uniform/time holds the exact value, the index and the steps.
void Time::restoreTimeState() {
  const fs::path file = startPath_ / "uniform" / "time";
  std::optional<double> stored;
  if (fs::exists(file)) {
    const Dictionary dict = Dictionary::readFile(file);
    // As OpenFOAM: the saved deltaT is the adapted one, used only with adjustTimeStep.
    if (settings_.adjustTimeStep) {
      if (auto dt = dict.getOptional<double>("deltaT"); dt && *dt > 0)
        deltaT_ = deltaT0_ = deltaTSave_ = *dt;
    }
    if (auto dt0 = dict.getOptional<double>("deltaT0"); dt0 && *dt0 > 0)
      deltaT0_ = deltaTSave_ = *dt0;
    if (auto index = dict.getOptional<label>("index")) index_ = *index;
    stored = dict.getOptional<double>("value");
    dict.markRead("name");
    // The write times continue on the grid of the run that wrote this time (origin + k
    // writeInterval, the same floating-point sums), so that a restart from a written time
    // steps as the uninterrupted run; a changed writeInterval starts a grid at this time.
    const auto origin = dict.getOptional<double>("writeOrigin");
    const auto writeIndex = dict.getOptional<long>("writeTimeIndex");
    const auto interval = dict.getOptional<double>("writeInterval");
    if (origin && writeIndex && interval && *interval == settings_.writeInterval &&
        settings_.writeControl != WriteControl::timeStep) {
      writeOrigin_ = *origin;
      writeTimeIndex_ = *writeIndex;
    }
  }
  // Use the exact stored value (the name is rounded) and the precision the name was made with.
  const double candidate = stored.value_or(value_);
  for (int p = precision_; p <= 17; ++p) {
    if (isph::timeName(candidate, p) == name_) {
      value_ = candidate;
      precision_ = p;
      return;
    }
  }
  if (stored) {
    warning(fmt::format("time {} read from {} differs from the time directory name {}; using {}",
                        *stored, file.string(), name_, value_));
  }
}

bool Time::run() const { return value_ < endTime_ - 0.5 * deltaT_; }

void Time::setDeltaT(double dt) {
  if (!(dt > 0) || !std::isfinite(dt))
    fatalError(fmt::format("the time step must be positive, found {}", dt));
  deltaT_ = dt;
}

void Time::adjustDeltaT(double dtWanted) {
  double dt = std::min(dtWanted, settings_.maxDeltaT);
  if (!(dt > 0) || !std::isfinite(dt))
    fatalError(fmt::format("the time step must be positive, found {}", dtWanted));
  const bool adjustable =
      settings_.writeControl == WriteControl::adjustableRunTime && stopAt_ == StopAt::endTime;
  double target = endTime_;
  if (adjustable) {
    target = std::min(
        target, writeOrigin_ + static_cast<double>(writeTimeIndex_ + 1) * settings_.writeInterval);
  }
  const double remaining = target - value_;
  if (remaining > 0) {
    const double steps = remaining / dt;
    // Away from endTime only adjustableRunTime changes the step.
    if ((adjustable || steps < 2) && steps < 1e9)
      dt = remaining / std::max(1.0, std::ceil(steps - 1e-6));
  }
  deltaT_ = dt;
}

Time& Time::operator++() {
  readModifiedControlDict();
  // A parallel run's ranks stop at the same step: a signal that one rank caught (mpirun passes
  // it on to each at its own moment) stops them all.
  const int sig = agreeOverRanks(stopSignal::caught());
  if (sig && !stopSignal::caught()) stopSignal::setCaught(sig);
  if (stopSignal::caught() && !signalHandled_) {
    signalHandled_ = true;
    stopAt_ = StopAt::writeNow;
    info("Signal caught: writing at the end of this time step and stopping");
  }
  stepStart_ = StepStart{value_, deltaT0_, deltaTSave_, endTime_, name_, index_, precision_, writeTimeIndex_};
  advance();
  return *this;
}

void Time::redoStep(double dt) {
  if (!stepStart_) fatalError("Time::redoStep: no step to redo (called before the first time step)");
  value_ = stepStart_->value;
  deltaT0_ = stepStart_->deltaT0;
  deltaTSave_ = stepStart_->deltaTSave;
  endTime_ = stepStart_->endTime;
  name_ = stepStart_->name;
  index_ = stepStart_->index;
  precision_ = stepStart_->precision;
  writeTimeIndex_ = stepStart_->writeTimeIndex;
  setDeltaT(dt);
  advance();
}

void Time::advance() {
  deltaT0_ = deltaTSave_;
  deltaTSave_ = deltaT_;
  const std::string oldName = name_;
  value_ += deltaT_;
  ++index_;

  // Land exactly on the write time or endTime that the step was sized to reach.
  auto snap = [this](double target) {
    if (std::abs(value_ - target) <= 1e-6 * deltaT_ + 1e-14 * std::abs(target)) value_ = target;
  };
  if (settings_.writeControl != WriteControl::timeStep) {
    snap(writeOrigin_ + static_cast<double>(writeTimeIndex_ + 1) * settings_.writeInterval);
  }
  snap(endTime_);
  if (std::abs(value_) < 1e-12 * deltaT_) value_ = 0;

  name_ = isph::timeName(value_, precision_);
  const int oldPrecision = precision_;
  while (name_ == oldName && precision_ < 17) name_ = isph::timeName(value_, ++precision_);
  if (precision_ != oldPrecision) {
    warning(fmt::format(
        "increased the timePrecision from {} to {} to distinguish between time names at time {}",
        oldPrecision, precision_, name_));
  }
  setWriteTime();
}

void Time::setWriteTime() {
  writeTime_ = false;
  if (settings_.writeControl == WriteControl::timeStep) {
    writeTime_ = index_ % static_cast<label>(settings_.writeInterval) == 0;
  } else {
    const auto index = static_cast<long>(
        std::floor((value_ - writeOrigin_ + 0.5 * deltaT_) / settings_.writeInterval));
    if (index > writeTimeIndex_) {
      writeTime_ = true;
      writeTimeIndex_ = index;
    }
  }
  // stopAt writeNow/noWriteNow end the run after this step (with or without a write).
  if (stopAt_ != StopAt::endTime) endTime_ = value_;
  if (stopAt_ == StopAt::writeNow) writeTime_ = true;
  if (stopAt_ == StopAt::endTime && value_ >= endTime_ - 0.5 * deltaT_) writeTime_ = true;
}

void Time::writeTimeState(const fs::path& timeDir) const {
  Dictionary dict("time");
  dict.set("value", value_);
  dict.set("name", name_);
  dict.set("index", index_);
  dict.set("deltaT", deltaT_);
  dict.set("deltaT0", deltaT0_);
  if (settings_.writeControl != WriteControl::timeStep) {
    dict.set("writeOrigin", writeOrigin_);
    dict.set("writeTimeIndex", writeTimeIndex_);
    dict.set("writeInterval", settings_.writeInterval);
  }
  const fs::path uniform = timeDir / "uniform";
  std::error_code ec;
  fs::create_directories(uniform, ec);
  if (ec) fatalError(fmt::format("cannot create {}: {}", uniform.string(), ec.message()));
  writeFileAtomic(uniform / "time",
                  foamFileHeader("dictionary", "time", name_ + "/uniform", false) + dict.write() +
                      foamFileFooter());
}

void Time::purgeOldWrites() {
  if (settings_.purgeWrite <= 0 || !writeTime_ || name_ == startName_) return;
  if (writtenTimes_.empty() || writtenTimes_.back() != name_) writtenTimes_.push_back(name_);
  while (writtenTimes_.size() > static_cast<std::size_t>(settings_.purgeWrite)) {
    // Out of view first (a hidden name), then deleted: a kill meanwhile leaves no half time.
    // (A parallel run's rank purges its own processor<rank>/<time>.)
    try {
      removeDirectoryAtomically(timesDir_ / writtenTimes_.front());
    } catch (const FatalError& e) {
      warning(fmt::format("purgeWrite: {}", e.what()));
    }
    writtenTimes_.pop_front();
  }
}

bool Time::readModifiedControlDict() {
  if (!settings_.runTimeModifiable) return false;
  const auto mtime = modificationTime(controlDictFile_);
  // (every rank of a parallel run re-reads it at the same step, when any of them sees it changed)
  if (!agreeOverRanks(mtime != controlDictTime_)) return false;
  controlDictTime_ = mtime;
  info("Re-reading system/controlDict");
  try {
    Dictionary dict = Dictionary::readFile(controlDictFile_);
    ControlSettings s = ControlSettings::read(dict);
    dict.checkKeywords(otherControlDictKeywords);
    if (s.deltaT != settings_.deltaT) deltaT_ = s.deltaT;
    if (s.writeControl != settings_.writeControl || s.writeInterval != settings_.writeInterval) {
      writeTimeIndex_ =
          static_cast<long>(std::floor((value_ - writeOrigin_ + 0.5 * deltaT_) / s.writeInterval));
    }
    if (s.timePrecision != settings_.timePrecision) precision_ = s.timePrecision;
    stopAt_ = s.stopAt;
    if (stopAt_ == StopAt::endTime) endTime_ = s.endTime;
    settings_ = s;
    controlDict_ = std::move(dict);
  } catch (const FatalError& e) {
    warning(fmt::format("cannot re-read {}; the run goes on with the previous controls:\n{}",
                        controlDictFile_.string(), e.report()));
    return false;
  }
  return true;
}

std::string Time::executionTimeLine() const {
  const double cpu = static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
  const auto wall = std::chrono::duration_cast<std::chrono::seconds>(
      std::chrono::steady_clock::now() - wallStart_);
  return fmt::format("ExecutionTime = {:.6g} s  ClockTime = {} s", cpu, wall.count());
}

}  // namespace isph
