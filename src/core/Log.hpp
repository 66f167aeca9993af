#pragma once
// The log an application writes on stdout (runApplication redirects it to log.<app>).
// Formatting is fmt's: isph::info("Time = {}", t.name());
#include <fmt/format.h>

#include <string>
#include <string_view>

namespace isph {

void infoLine(std::string_view line);

template <class... Args>
void info(fmt::format_string<Args...> format, Args&&... args) {
  infoLine(fmt::format(format, std::forward<Args>(args)...));
}

// Echo "<what> <value>" once per distinct key during a run, so that users see every
// default the run used; returns false when this key was already echoed.
bool echoDefaultOnce(const std::string& key, const std::string& line);

}  // namespace isph
