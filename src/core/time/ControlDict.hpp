#pragma once
// The run controls of system/controlDict, as OpenFOAM reads them:
//   startFrom latestTime; startTime 0; stopAt endTime; endTime 2; deltaT 1e-3;
//   writeControl adjustableRunTime; writeInterval 0.1; purgeWrite 0; writeFormat binary;
//   writePrecision 6; timePrecision 6; adjustTimeStep yes; maxCo 0.4; maxDeltaT 1e-3;
//   runTimeModifiable true;
// Every default used is echoed in the log; invalid values are errors naming the file, line
// and keyword.
#include "core/dictionary/Dictionary.hpp"
#include "core/fields/FieldIO.hpp"  // WriteFormat

namespace isph {

enum class StartFrom { firstTime, startTime, latestTime };
enum class StopAt { endTime, writeNow, noWriteNow };
enum class WriteControl { timeStep, runTime, adjustableRunTime };

struct ControlSettings {
  StartFrom startFrom = StartFrom::latestTime;
  double startTime = 0;  // read when startFrom is startTime (required then)
  StopAt stopAt = StopAt::endTime;
  double endTime = 0;  // required
  double deltaT = 0;   // required
  WriteControl writeControl = WriteControl::timeStep;
  double writeInterval = 1;  // required; a whole number of steps with writeControl timeStep
  int purgeWrite = 0;        // keep only the N newest written times (0: keep all)
  WriteFormat writeFormat = WriteFormat::ascii;
  int writePrecision = 6;
  int timePrecision = 6;
  bool adjustTimeStep = false;
  double maxCo = 1;
  double maxDeltaT = 1e15;  // OpenFOAM's GREAT: no limit
  bool runTimeModifiable = true;

  // Read and validate the controls (does not warn about unknown keywords: Time does that
  // once the whole controlDict has been read).
  static ControlSettings read(const Dictionary& controlDict);
};

const char* toString(StartFrom v);
const char* toString(StopAt v);
const char* toString(WriteControl v);

}  // namespace isph
