// SPDX-License-Identifier: BSL-1.0
#pragma once
// The command line of the programs built on CLI11, read with the exit statuses their manuals
// give.

#include <CLI/CLI.hpp>
#include <optional>

namespace seawire::tools {

/// Parses argv into `app`. Returns the status to exit with when the program is not to run on:
/// 0 after --help or --version (printed), 2 for a command line it refuses (told on stderr);
/// nothing when it is to run.
inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    (void)app.exit(e);
    return 2;
  }
  return std::nullopt;
}

}  // namespace seawire::tools
