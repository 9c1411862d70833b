// SPDX-License-Identifier: BSL-1.0
#pragma once
// What the documentation's code snippets take as given: the library, `using namespace
// seawire` (as the tour says), and the program around them (a line read, a way to send).

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "seawire/seawire.hpp"

using namespace seawire;  // NOLINT(google-build-using-namespace): the tour's first line

namespace readme_context {
inline std::string_view line = "$GPRMC,,V,,,,,,,,,,N*53\r\n";  // the line just read
inline std::string_view chunk = line;                          // bytes just read
inline double speed = 1.5, sog = 0.145, cog = 156.78;          // values a program has
inline nmea::time_of_day now_tod{12, 0, 0};
inline void send(std::string_view) {}
inline void write(std::string_view) {}
inline void log(std::string_view, std::string_view) {}
template <class... T>
void use(const T&...) {}
template <class T>
std::optional<std::string> read_line_with_timeout(T) {
  return std::nullopt;
}
template <class T>
void sleep_until(T) {}
}  // namespace readme_context
using namespace readme_context;  // NOLINT(google-build-using-namespace)
