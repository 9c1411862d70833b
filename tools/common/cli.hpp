// SPDX-License-Identifier: BSL-1.0
#pragma once
// The command line of the programs built on CLI11, read with the exit statuses their manuals
// give: 0 after --help or --version, 2 and one line on stderr for a command line refused.

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

namespace seawire::tools {

/// Parses argv into `app`. Returns the status to exit with when the program is not to run on:
/// 0 after --help or --version (printed on stdout), 2 for a command line it refuses (one line on
/// stderr: the program's name and CLI11's reason, which names the option); nothing when it is to
/// run. Every program reads its command line here, never with CLI11_PARSE (whose statuses are
/// CLI11's error numbers, 105 for a value out of range).
inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string why = e.what();
    for (char& c : why)
      if (c == '\n') c = ' ';
    std::fprintf(stderr, "%s: %s\n", app.get_name().c_str(), why.c_str());
    return 2;
  }
  return std::nullopt;
}

/// The check of every floating-point option, before any range check: the value is a number
/// and finite. strtod reads "nan", "inf" and "1e999" (as infinity), which would pass a range
/// check (every comparison with NaN is false) or stand for "never": refused here.
inline const CLI::Validator finite_number(
    [](const std::string& text) -> std::string {
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      if (text.empty() || end != text.c_str() + text.size()) return "not a number: " + text;
      if (!std::isfinite(v)) return "not a finite number: " + text;
      return {};
    },
    "FINITE");

}  // namespace seawire::tools
