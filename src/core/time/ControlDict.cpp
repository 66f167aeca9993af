// Reading and validating the controlDict run controls.
#include "core/time/ControlDict.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "core/Error.hpp"

namespace isph {

namespace {

// A FatalError at `key`'s entry: "keyword 'deltaT' in system/controlDict: <what>".
[[noreturn]] void invalid(const Dictionary& dict, std::string_view key, const std::string& what) {
  const Entry* e = dict.findEntry(key);
  fatalIOError(e ? e->location() : dict.location(),
               fmt::format("keyword '{}' in {}: {}", key,
                           dict.name().empty() ? "<unnamed>" : dict.name(), what));
}

template <class E>
E choice(const Dictionary& dict, std::string_view key, std::initializer_list<E> values,
         E fallback) {
  std::vector<std::string> names;
  for (E v : values) names.emplace_back(toString(v));
  const std::string word = dict.getChoiceOrDefault(key, names, toString(fallback));
  for (E v : values) {
    if (word == toString(v)) return v;
  }
  return fallback;
}

void checkPrecision(const Dictionary& dict, std::string_view key, int value) {
  if (value < 1 || value > 17)
    invalid(dict, key, fmt::format("must be between 1 and 17, found {}", value));
}

}  // namespace

const char* toString(StartFrom v) {
  switch (v) {
    case StartFrom::firstTime:
      return "firstTime";
    case StartFrom::startTime:
      return "startTime";
    case StartFrom::latestTime:
      return "latestTime";
  }
  return "?";
}

const char* toString(StopAt v) {
  switch (v) {
    case StopAt::endTime:
      return "endTime";
    case StopAt::writeNow:
      return "writeNow";
    case StopAt::noWriteNow:
      return "noWriteNow";
  }
  return "?";
}

const char* toString(WriteControl v) {
  switch (v) {
    case WriteControl::timeStep:
      return "timeStep";
    case WriteControl::runTime:
      return "runTime";
    case WriteControl::adjustableRunTime:
      return "adjustableRunTime";
  }
  return "?";
}

ControlSettings ControlSettings::read(const Dictionary& d) {
  using enum StartFrom;
  ControlSettings s;
  s.startFrom = choice(d, "startFrom", {firstTime, startTime, latestTime}, latestTime);
  if (s.startFrom == startTime) {
    s.startTime = d.get<double>("startTime");
  } else {
    s.startTime = d.getOptional<double>("startTime").value_or(0);  // valid, unused
  }
  s.stopAt =
      choice(d, "stopAt", {StopAt::endTime, StopAt::writeNow, StopAt::noWriteNow}, StopAt::endTime);
  s.endTime = d.get<double>("endTime");
  s.deltaT = d.get<double>("deltaT");
  s.writeControl =
      choice(d, "writeControl",
             {WriteControl::timeStep, WriteControl::runTime, WriteControl::adjustableRunTime},
             WriteControl::timeStep);
  s.writeInterval = d.get<double>("writeInterval");
  s.purgeWrite = d.getOrDefault<int>("purgeWrite", 0);
  s.writeFormat = d.getChoiceOrDefault("writeFormat", {"ascii", "binary"}, "ascii") == "binary"
                      ? WriteFormat::binary
                      : WriteFormat::ascii;
  s.writePrecision = d.getOrDefault<int>("writePrecision", 6);
  s.timePrecision = d.getOrDefault<int>("timePrecision", 6);
  s.adjustTimeStep = d.getOrDefault<bool>("adjustTimeStep", false);
  s.maxCo = d.getOrDefault<double>("maxCo", 1.0);
  s.maxDeltaT = d.getOrDefault<double>("maxDeltaT", 1e15);
  s.runTimeModifiable = d.getOrDefault<bool>("runTimeModifiable", true);

  if (s.startFrom == startTime && s.endTime < s.startTime) {
    invalid(d, "endTime", fmt::format("endTime {} is before startTime {}", s.endTime, s.startTime));
  }
  if (!(s.deltaT > 0)) invalid(d, "deltaT", fmt::format("must be positive, found {}", s.deltaT));
  if (!(s.writeInterval > 0))
    invalid(d, "writeInterval", fmt::format("must be positive, found {}", s.writeInterval));
  if (s.writeControl == WriteControl::timeStep &&
      (s.writeInterval != std::floor(s.writeInterval) ||
       s.writeInterval > std::numeric_limits<label>::max())) {
    invalid(d, "writeInterval",
            fmt::format("must be a whole number of time steps with writeControl timeStep, found {}",
                        s.writeInterval));
  }
  if (s.purgeWrite < 0)
    invalid(d, "purgeWrite", fmt::format("must be 0 (keep all) or more, found {}", s.purgeWrite));
  checkPrecision(d, "writePrecision", s.writePrecision);
  checkPrecision(d, "timePrecision", s.timePrecision);
  if (!(s.maxCo > 0)) invalid(d, "maxCo", fmt::format("must be positive, found {}", s.maxCo));
  if (!(s.maxDeltaT > 0))
    invalid(d, "maxDeltaT", fmt::format("must be positive, found {}", s.maxDeltaT));
  return s;
}

}  // namespace isph
