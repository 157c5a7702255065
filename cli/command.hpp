#pragma once
// The ccdlab command line: one registry of subcommands. Each subcommand lives in its own
// file under cli/ and registers itself in commands.cpp's table; each
// parses its arguments, --help included, with CommandLine (command_line.hpp).
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
  int (*run)(std::span<const std::string> args);  ///< args exclude the command name
};

/// The one table of subcommands (cli/commands.cpp).
std::span<const Command> commands();

/// Version string "X.Y.Z (git HASH)".
std::string version_string();

/// Exit status for usage and input errors.
constexpr int kExitBadInput = 2;

/// Called from a `catch (...)` handler of command NAME: prints "ccdlab NAME: ..." for the
/// exception being handled and gives the exit status: kExitBadInput for an input error
/// (ccd::InputError) or a usage error (UsageError, command_line.hpp), 1 for running out of
/// memory ("out of memory", then `out_of_memory_detail`, e.g. what was being done) or
/// another std::exception. Anything else is rethrown.
int command_failed(std::string_view name, const std::string& out_of_memory_detail = {});

}  // namespace ccdlab
