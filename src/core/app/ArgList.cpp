#include "core/app/ArgList.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "core/Error.hpp"
#include "core/Strings.hpp"

namespace isph {

namespace {

std::vector<OptionSpec> allOptions(const ApplicationSpec& spec) {
  std::vector<OptionSpec> options = {
      {"case", "dir", "case directory (default: the current directory)"},
      {"help", "", "print this usage and exit"},
  };
  if (spec.timeOptions) {
    options.push_back({"time", "ranges", "times to process, e.g. '0.1' '0:0.5' ':0.2,1:' (comma-separated)"});
    options.push_back({"latestTime", "", "process the latest time only"});
    options.push_back({"noZero", "", "exclude the 0 directory"});
  }
  if (spec.parallel) options.push_back({"parallel", "", "run in parallel on the decomposed case (processor*/)"});
  options.insert(options.end(), spec.options.begin(), spec.options.end());
  return options;
}

}  // namespace

std::string ArgList::usage(const ApplicationSpec& spec) {
  std::string out = fmt::format("\nUsage: {} [OPTIONS]", spec.name);
  for (const auto& a : spec.arguments) out += fmt::format(" <{}>", a);
  out += "\n\n";
  if (!spec.description.empty()) out += spec.description + "\n\n";
  out += "Options:\n";
  for (const auto& o : allOptions(spec)) {
    const std::string flag = o.argName.empty() ? "-" + o.name : fmt::format("-{} <{}>", o.name, o.argName);
    out += fmt::format("  {:<22} {}\n", flag, o.help);
  }
  return out;
}

ArgList::ArgList(const ApplicationSpec& spec, int argc, const char* const* argv)
    : executable_(spec.name) {
  const auto options = allOptions(spec);
  std::vector<std::string> names;
  for (const auto& o : options) names.push_back("-" + o.name);

  for (int i = 0; i < argc; ++i) all_.emplace_back(argv[i]);
  for (std::size_t i = 1; i < all_.size(); ++i) {
    const std::string& arg = all_[i];
    if (arg.size() > 1 && arg[0] == '-' && !(std::isdigit(static_cast<unsigned char>(arg[1])) || arg[1] == '.')) {
      const std::string name = arg.substr(arg[1] == '-' ? 2 : 1);  // -help and --help
      if (name == "help" || name == "h") throw HelpRequested{usage(spec)};
      const auto it = std::find_if(options.begin(), options.end(), [&](const OptionSpec& o) { return o.name == name; });
      if (it == options.end()) {
        fatalError(fmt::format("unknown option '{}'{} for {}\n    run '{} -help' for the options", arg,
                               didYouMean("-" + name, names), spec.name, spec.name));
      }
      if (it->argName.empty()) {
        options_[name] = "";
      } else {
        if (i + 1 >= all_.size()) {
          fatalError(fmt::format("option '-{}' expects an argument <{}>", name, it->argName));
        }
        options_[name] = all_[++i];
      }
    } else {
      arguments_.push_back(arg);
    }
  }
  if (arguments_.size() != spec.arguments.size()) {
    fatalError(fmt::format("{} expects {} argument(s){}, got {}\n    run '{} -help' for the usage", spec.name,
                           spec.arguments.size(),
                           spec.arguments.empty() ? "" : " <" + join(spec.arguments, "> <") + ">",
                           arguments_.size(), spec.name));
  }

  std::error_code ec;
  const std::filesystem::path given = option("case").value_or(".");
  casePath_ = std::filesystem::weakly_canonical(std::filesystem::absolute(given, ec), ec);
  if (ec || !std::filesystem::is_directory(casePath_)) {
    fatalError(fmt::format("case directory '{}' does not exist (option -case)", given.string()));
  }
}

std::optional<std::string> ArgList::option(const std::string& name) const {
  const auto it = options_.find(name);
  if (it == options_.end()) return std::nullopt;
  return it->second;
}

std::string ArgList::commandLine() const {
  std::string out;
  for (std::size_t i = 0; i < all_.size(); ++i) {
    const std::string& a = i == 0 ? executable_ : all_[i];
    if (i) out += ' ';
    const bool quote = a.empty() || a.find_first_of(" \t'\"()$") != std::string::npos;
    out += quote ? "'" + a + "'" : a;
  }
  return out;
}

}  // namespace isph
