#pragma once
// The ccdlab command line: one registry of subcommands. Each subcommand lives in its own
// file under experiments/commands/ and registers itself in commands.cpp's table.
//
// Exit status: 0 success, 1 runtime failure, 2 bad input or usage (nothing written).
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ccdlab {

struct Command {
  std::string_view name;
  std::string_view summary;  ///< one line for `ccdlab --help`
  std::string_view usage;    ///< full text for `ccdlab NAME --help`
  int (*run)(std::span<const std::string> args);  ///< args exclude the command name
};

/// The one table of subcommands (experiments/commands/commands.cpp).
std::span<const Command> commands();

/// Version string "X.Y.Z (git HASH)".
std::string version_string();

/// True when `args` contains -h or --help.
bool wants_help(std::span<const std::string> args);

/// Exit status for usage and input errors.
constexpr int kExitBadInput = 2;

}  // namespace ccdlab
