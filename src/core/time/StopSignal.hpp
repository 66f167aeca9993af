#pragma once
// A run stopped from outside (Ctrl-C, `kill`, a closed terminal or a dropped ssh): the first
// SIGINT, SIGTERM or SIGHUP asks the run to write at the end of the next time step and stop
// (Time::operator++ reads it); a second one aborts, as the default action does. After the run
// has written and shut down, the application ends by the signal it caught, with its default
// action (status 130 for SIGINT, 143 for SIGTERM, 129 for SIGHUP), so that a calling script
// (Allrun) stops too instead of post-processing a run that did not reach endTime.
namespace isph::stopSignal {

// Installs the handlers of SIGINT, SIGTERM and SIGHUP.
void install();
// The signal caught so far (0: none).
int caught();
// A signal another rank caught: a parallel run's ranks stop at the same step.
void setCaught(int sig);
// Ends the process by the caught signal's default action; returns (doing nothing) when none was
// caught.
void exitIfCaught();

}  // namespace isph::stopSignal
