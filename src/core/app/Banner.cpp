#include "core/app/Banner.hpp"

#include <fmt/chrono.h>
#include <fmt/format.h>
#include <unistd.h>

#include <ctime>

#include "core/ParallelRun.hpp"
#include "core/Version.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace isph {

int threadCount() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

std::string banner(const ArgList& args) {
  char host[256] = "unknown";
  ::gethostname(host, sizeof host - 1);
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  ::localtime_r(&now, &local);
  const std::string rule(77, '-');
  std::string out;
  out += fmt::format("/*{}*\\\n", rule);
  out += fmt::format("| {:<76}|\n", "isphLandslide: incompressible SPH for flow-like landslides");
  out += fmt::format("| {:<76}|\n", fmt::format("Version: {}", gitVersion()));
  out += fmt::format("\\*{}*/\n", rule);
  out += fmt::format("Build    : {}\n", ISPH_BUILD_TYPE);
  out += fmt::format("Exec     : {}\n", args.commandLine());
  out += fmt::format("Date     : {:%b %d %Y}\n", local);
  out += fmt::format("Time     : {:%H:%M:%S}\n", local);
  out += fmt::format("Host     : {}\n", host);
  out += fmt::format("PID      : {}\n", ::getpid());
  out += fmt::format("Case     : {}\n", args.casePath().string());
  const int nProcs = parallelRun().nProcs;
  out += fmt::format("nProcs   : {}{}\n", nProcs, nProcs > 1 ? " (MPI ranks)" : "");
  out += fmt::format("nThreads : {}{}{}\n", threadCount(), nProcs > 1 ? " per rank" : "",
#ifdef _OPENMP
                     " (OpenMP: OMP_NUM_THREADS, else 1: core/app/DefaultThreads.hpp)"
#else
                     " (built without OpenMP)"
#endif
  );
  return out;
}

}  // namespace isph
