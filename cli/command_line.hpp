#pragma once
// The one argument parser of every ccdlab command (CLI11, Debian's libcli11-dev): options,
// positional arguments and their help text are declared once; `--help` prints the usage
// CLI11 formats from them; every usage error is thrown as a UsageError, which
// command_failed() prints as one line ("ccdlab NAME: WHAT (see ccdlab NAME --help)") with
// exit status 2.
#include <CLI/App.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace ccdlab {

/// Bad usage of a command: an unknown option, a missing or malformed value. The message
/// is the whole line after "ccdlab NAME: ", the pointer to --help included.
class UsageError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

class CommandLine {
 public:
  /// `name`: the command as typed ("run", "cloth queries"); `description`: the text above
  /// the usage line; `help_name`: the command whose --help an error points to ("" for
  /// none).
  CommandLine(const std::string& name, const std::string& description, const std::string& help_name);

  /// The text below the option list (exit status, further forms).
  void footer(const std::string& text);

  /// An option with a text value. `missing`: the error when the value is absent (default
  /// "NAME needs VALUE"); `once`: a second use is an error ("NAME given twice").
  CLI::Option* text(const std::string& names, std::string& out, const std::string& value_name,
                    const std::string& help, const std::string& missing = {}, bool once = false);
  /// An integer option in [lo, hi]; anything else is "NAME: must be an integer in [lo, hi],
  /// got 'TEXT'".
  CLI::Option* integer(const std::string& names, std::uint64_t lo, std::uint64_t hi,
                       const std::string& value_name, const std::string& help,
                       const std::function<void(std::uint64_t)>& set);
  /// A finite number option at least `lo` (above it when `open`); otherwise "NAME: must be
  /// a finite number >= lo, got 'TEXT'".
  CLI::Option* number(const std::string& names, double lo, bool open, const std::string& value_name,
                      const std::string& help, const std::function<void(double)>& set);
  /// An option whose value `parse` reads (throwing UsageError via fail() when it is bad).
  CLI::Option* value(const std::string& names, const std::string& value_name, const std::string& help,
                     const std::function<void(const std::string&)>& parse, const std::string& missing = {});
  CLI::Option* flag(const std::string& names, bool& out, const std::string& help);
  /// A positional argument (one, or every one when `out` is a vector); a required one
  /// that is absent is "missing NAME".
  CLI::Option* positional(const std::string& name, std::string& out, const std::string& help,
                          bool required = true);
  CLI::Option* positionals(const std::string& name, std::vector<std::string>& out, const std::string& help,
                           bool required = true);

  /// Parses `args` (those after the command's name). True: run the command; false: the
  /// help was printed on stdout (exit 0). Throws UsageError for anything else.
  bool parse(std::span<const std::string> args);

  /// Throws UsageError("WHAT (see ccdlab HELP --help)").
  [[noreturn]] void fail(const std::string& what) const;

  /// The help text (what --help prints).
  std::string help() const;

  CLI::App& app() { return app_; }

 private:
  struct Missing {
    const CLI::Option* option;
    std::string message;
  };
  CLI::Option* register_value(const std::string& names, const std::string& value_name,
                              const std::string& help, std::function<void(const std::string&)> parse,
                              const std::string& missing, bool once);

  CLI::App app_;
  std::string name_;
  std::string help_name_;
  std::vector<Missing> missing_;
};

/// The first name of `names` ("-o,--output" -> "-o"), as error messages call an option.
std::string option_name(const std::string& names);

}  // namespace ccdlab
