#include "core/time/StopSignal.hpp"

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <iostream>

namespace isph::stopSignal {

namespace {

volatile std::sig_atomic_t signalCaught = 0;

extern "C" void onStopSignal(int sig) {
  if (signalCaught) {  // second signal: abort as the default action does
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  signalCaught = sig;
  static const char message[] =
      "\n--> Signal caught: writing at the end of the next time step and stopping"
      " (send it again to abort)\n";
  [[maybe_unused]] const auto n = ::write(STDERR_FILENO, message, sizeof message - 1);
}

}  // namespace

void install() {
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  sigaction(SIGHUP, &action, nullptr);  // the terminal closed (or ssh dropped): as SIGTERM
}

int caught() { return signalCaught; }

void setCaught(int sig) { signalCaught = sig; }

void exitIfCaught() {
  const int sig = signalCaught;
  if (sig == 0) return;
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace isph::stopSignal
