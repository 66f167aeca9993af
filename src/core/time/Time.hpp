#pragma once
// The run-time controller, modelled on OpenFOAM's Time: reads system/controlDict, picks the
// start time (startFrom), restores the time state of a restart (<start>/uniform/time),
// advances the time step by step, decides when to write, re-reads a modified controlDict
// between steps and turns SIGINT/SIGTERM/SIGHUP into "write now and stop".
//
//   Time runTime(caseDir);
//   while (runTime.run()) {
//     runTime.adjustDeltaT(dtFromCourantNumber);  // or runTime.settings().deltaT
//     ++runTime;
//     ... solve ...
//     if (runTime.writeTime()) { ... write runTime.timePath() ...; runTime.purgeOldWrites(); }
//   }
#include <chrono>
#include <deque>
#include <filesystem>
#include <optional>
#include <string>

#include "core/Types.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "core/time/ControlDict.hpp"
#include "core/time/TimeName.hpp"

namespace isph {

class Time {
 public:
  explicit Time(const std::filesystem::path& caseDir);
  // The time of one rank of a parallel run (the solver with -parallel, doc/parallel.md): the
  // case's own system/controlDict, and the times of <case>/<processorDir> (processor<rank>):
  // the start time is chosen among them if that folder holds any (a decomposed case), else
  // among the case's own (an undecomposed start, which the solver decomposes in memory).
  // Time directories are written to, and purged from, <case>/<processorDir>.
  Time(const std::filesystem::path& caseDir, const std::string& processorDir);

  double value() const { return value_; }
  const std::string& timeName() const { return name_; }
  double deltaT() const { return deltaT_; }
  double deltaT0() const { return deltaT0_; }  // the step before the last one
  label timeIndex() const { return index_; }
  double startTime() const { return startTime_; }
  double endTime() const { return endTime_; }
  int timePrecision() const { return precision_; }  // grows when names would collide
  const std::filesystem::path& path() const { return caseDir_; }
  std::filesystem::path timePath() const { return timesDir_ / name_; }
  // Where the start time was read from: timePath() at the start, but for the undecomposed
  // start of a parallel run the case's own <start> (rank 0 reads it, the others nothing).
  const std::filesystem::path& startPath() const { return startPath_; }
  // A parallel run that starts from a decomposed case (processor<rank>/<start>).
  bool decomposedStart() const { return !processorDir_.empty() && startPath_.parent_path() == timesDir_; }
  const ControlSettings& settings() const { return settings_; }
  const Dictionary& controlDict() const { return controlDict_; }  // for `functions` etc.

  // True while the end time is not reached (within half a step) and no stop is due.
  bool run() const;
  void setDeltaT(double dt);
  // Set deltaT to dtWanted clipped to maxDeltaT; with adjustableRunTime shrink it so that
  // the next write time is hit exactly; never step past endTime (the last steps before
  // it are split evenly).
  void adjustDeltaT(double dtWanted);
  // Re-read a modified controlDict, then advance one step and decide writeTime().
  Time& operator++();
  // Take back the last ++ and advance again by `dt` (a failed step redone with a smaller
  // one): time, index, name, the step history and the write decision are those of the
  // step start, then advanced as ++ does (without re-reading controlDict). Only one step
  // back: FatalError when called before any ++.
  void redoStep(double dt);
  bool writeTime() const { return writeTime_; }

  // Write <timeDir>/uniform/time (value, name, index, deltaT, deltaT0, and the grid of write
  // times) atomically; timeDir may be a staging directory that becomes timePath().
  void writeTimeState(const std::filesystem::path& timeDir) const;
  // After a write: keep only the purgeWrite newest times written by this run (never the
  // start time); purgeWrite 0 keeps all.
  void purgeOldWrites();
  // If runTimeModifiable and controlDict's modification time changed, re-read it; returns
  // whether it was re-read. stopAt writeNow/noWriteNow, endTime and deltaT are honoured.
  bool readModifiedControlDict();

  // "ExecutionTime = 1.23 s  ClockTime = 2 s" (process CPU time, wall-clock since construction).
  std::string executionTimeLine() const;

 private:
  void restoreTimeState();
  // Parallel, startFrom latestTime: `times` cut to the latest time every rank holds (collective).
  void keepCommonTimes(std::vector<Instant>& times) const;
  void advance();
  void setWriteTime();

  // What ++ changes, saved before it for redoStep.
  struct StepStart {
    double value, deltaT0, deltaTSave, endTime;
    std::string name;
    label index;
    int precision;
    long writeTimeIndex;
  };
  std::optional<StepStart> stepStart_;

  std::filesystem::path caseDir_;
  std::string processorDir_;      // "processor<rank>" in a parallel run, else empty
  std::filesystem::path timesDir_;   // where time directories are written: the case or its processor folder
  std::filesystem::path startPath_;  // the start time's folder
  std::filesystem::path controlDictFile_;
  std::filesystem::file_time_type controlDictTime_{};
  Dictionary controlDict_;
  ControlSettings settings_;

  double value_ = 0;
  std::string name_;
  std::string startName_;
  double deltaT_ = 0;
  double deltaT0_ = 0;
  double deltaTSave_ = 0;
  label index_ = 0;
  double startTime_ = 0;
  double writeOrigin_ = 0;  // write times are writeOrigin_ + k writeInterval (runTime controls)
  double endTime_ = 0;
  int precision_ = 6;
  StopAt stopAt_ = StopAt::endTime;
  bool writeTime_ = false;
  bool signalHandled_ = false;
  long writeTimeIndex_ = 0;
  std::deque<std::string> writtenTimes_;
  std::chrono::steady_clock::time_point wallStart_;
};

}  // namespace isph
