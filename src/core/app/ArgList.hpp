#pragma once
// Command-line arguments in OpenFOAM's style: `app -case DIR -time '0:0.5' -latestTime`.
// Every application takes -case and -help; post-processing utilities also the time options.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace isph {

struct OptionSpec {
  std::string name;     // without the leading '-'
  std::string argName;  // empty for a switch
  std::string help;
};

// What an application restores or clears at start of what interrupted writes, replaces and
// purges left in the case (StagingRecovery.hpp).
enum class CaseRecovery {
  none,      // the application reads no case (isphDictionary reads a file)
  thisHost,  // leftovers of processes of this host that are gone
  allHosts,  // also those of other hosts: the applications that write time directories (the
             // solver, particleMesh, decomposePar, reconstructPar), of which one runs on a case at
             // a time: they hold the case lock (CaseLock.hpp)
};

struct ApplicationSpec {
  std::string name;
  std::string description;
  std::vector<OptionSpec> options;            // in addition to the standard ones
  std::vector<std::string> arguments;         // positional arguments, by name (all required)
  bool timeOptions = false;                   // -time, -latestTime, -noZero
  // -parallel: the decomposed case (processor<i>/), as OpenFOAM's; the solver then runs on the
  // ranks of `mpirun -np N`, a post-processing utility reads the processor directories.
  bool parallel = false;
  bool banner = true;                         // false for tools whose output is parsed
  CaseRecovery recovery = CaseRecovery::thisHost;
};

// Thrown by the parser for -help: the application prints usage and exits 0.
struct HelpRequested {
  std::string usage;
};

class ArgList {
 public:
  // FatalError on an unknown option, a missing option argument, a wrong argument count or
  // a case directory that does not exist.
  ArgList(const ApplicationSpec& spec, int argc, const char* const* argv);

  const std::string& executable() const { return executable_; }
  const std::filesystem::path& casePath() const { return casePath_; }  // absolute
  std::string caseName() const { return casePath_.filename().string(); }
  std::string commandLine() const;

  bool found(const std::string& option) const { return options_.count(option) > 0; }
  std::optional<std::string> option(const std::string& name) const;
  const std::vector<std::string>& arguments() const { return arguments_; }

  static std::string usage(const ApplicationSpec& spec);

 private:
  std::string executable_;
  std::vector<std::string> all_;
  std::filesystem::path casePath_;
  std::map<std::string, std::string> options_;
  std::vector<std::string> arguments_;
};

}  // namespace isph
