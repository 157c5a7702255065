// `ccdlab report RESULTS.json... -o DIR [--title TEXT]`: the inputs are read and checked
// here as every command reads them (ccd::read_json_file, then validate_results), and the
// output folder is checked before the work; then scripts/report.py draws the charts and
// writes the report (see python_script.hpp).
#include "command.hpp"
#include "command_line.hpp"
#include "python_script.hpp"

#include "../experiments/results_file.hpp"

#include <ccd/io/atomic_file.hpp>
#include <ccd/io/json_reader.hpp>
#include <ccd/io/input_error.hpp>

#include <unistd.h>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string_view>
#include <vector>

namespace ccdlab {
namespace {

namespace fs = std::filesystem;

// The outputs scripts/report.py writes into DIR.
constexpr const char* kOutputs[] = {"report.md", "report.html", "missed.png", "cost.png"};

// Length of the valid UTF-8 sequence at text[i] (1 to 4), or 0 when the bytes there are not one.
std::size_t utf8_length(const std::string& text, std::size_t i) {
  const auto u = static_cast<unsigned char>(text[i]);
  const std::size_t n = u < 0x80                 ? 1
                        : u >= 0xc2 && u <= 0xdf ? 2
                        : u >= 0xe0 && u <= 0xef ? 3
                        : u >= 0xf0 && u <= 0xf4 ? 4
                                                 : 0;
  if (n == 0 || i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(text[i + k]) & 0xc0) != 0x80) return 0;
  return n;
}

// `text` on one line of UTF-8: control characters (a newline in a file name) and bytes
// that are not UTF-8 (in a file name, or quoted from a file) as \xNN escapes.
std::string one_line(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const auto u = static_cast<unsigned char>(text[i]);
    const std::size_t n = utf8_length(text, i);
    if (n == 0 || u < 0x20 || u == 0x7f) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\x%02x", u);
      out += esc;
      ++i;
    } else {
      out.append(text, i, n);
      i += n;
    }
  }
  return out;
}

// Every results file read and validated as `ccdlab merge` reads shards; each file once.
void check_inputs(const std::vector<std::string>& paths) {
  std::vector<nlohmann::json> seen;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const std::string& path = paths[i];
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (fs::exists(st) && !fs::is_regular_file(st))
      throw ccd::InputError(path, "", "not a regular file (the report reads each file twice)");
    nlohmann::json results = ccd::read_json_file(path);
    validate_results(results, path);
    for (std::size_t k = 0; k < i; ++k) {
      if (fs::equivalent(path, paths[k], ec))
        throw ccd::InputError(path, "", "given twice (also as " + paths[k] + ")");
      if (results == seen[k]) throw ccd::InputError(path, "", "the same results as " + paths[k]);
    }
    seen.push_back(std::move(results));
  }
}

// DIR is a folder (or does not exist yet and its nearest existing parent folder takes new
// files); every output in it is a plain file or absent, none is an input, and DIR takes new
// files (ccd::OutputFile creates and removes a temporary file there).
void check_output_folder(const std::string& dir, const std::vector<std::string>& inputs) {
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir, ec)) throw ccd::InputError(dir, "", "-o must name a folder");
    for (const char* name : kOutputs) ccd::OutputFile probe((fs::path(dir) / name).string(), inputs);
    return;
  }
  fs::path parent = fs::absolute(fs::path(dir), ec).parent_path();
  while (!parent.empty() && !fs::exists(parent, ec) && parent != parent.root_path())
    parent = parent.parent_path();
  if (!fs::is_directory(parent, ec))
    throw ccd::InputError(dir, "", "cannot be created: " + parent.string() + " is not a folder");
  if (::access(parent.c_str(), W_OK | X_OK) != 0)
    throw ccd::InputError(dir, "",
                          "cannot be created: the folder " + parent.string() + " does not take new files");
}

constexpr const char* kReportDescription =
    "Writes DIR/report.md and DIR/report.html (charts embedded; opens in a browser without a\n"
    "server), and the charts DIR/missed.png and DIR/cost.png: per method the zero-miss frontier\n"
    "(the largest dt at and below which it missed nothing), the missed fraction per dt and the\n"
    "cost; several results files (other scenes, other machines, another dt range) are overlaid\n"
    "on one chart and one table. When no method missed anything the report says so first.\n"
    "Runs scripts/report.py with /usr/bin/python3 (matplotlib).\n";

constexpr const char* kReportFooter =
    "The results files are checked as ccdlab merge checks them (each file once), and DIR before\n"
    "the work; the four outputs are written to temporary files and renamed into place together,\n"
    "so a failure (a full disk) leaves every old output as it was and no temporary file.\n"
    "\n"
    "Exit status: 0 success, 1 runtime failure, 2 bad input (one line naming the file and the field).";

int run_report(std::span<const std::string> args) {
  std::vector<std::string> results;
  std::string out, title;
  CommandLine cli("report", kReportDescription, "report");
  cli.footer(kReportFooter);
  cli.positionals("RESULTS.json", results, "results files (after --, names that begin with -)");
  cli.value(
      "-o,--output", "DIR", "the report's folder (created when missing)",
      [&](const std::string& v) {
        if (!out.empty()) cli.fail("-o given twice");
        if (v.empty()) cli.fail("-o needs a folder name");
        out = v;
      },
      "missing value after -o");
  CLI::Option* title_option =
      cli.text("--title", title, "TEXT", "the report's title (default: from the results)",
               "missing value after --title", /*once=*/true);
  try {
    if (!cli.parse(args)) return 0;
    if (results.empty()) cli.fail("missing RESULTS.json");
    if (out.empty()) cli.fail("missing -o DIR");
    check_inputs(results);
    check_output_folder(out, results);
  } catch (const ccd::InputError& e) {  // a file name or a quoted value on one line
    std::cerr << "ccdlab report: " << one_line(e.what()) << "\n";
    return kExitBadInput;
  } catch (const UsageError& e) {
    std::cerr << "ccdlab report: " << one_line(e.what()) << "\n";
    return kExitBadInput;
  } catch (...) {
    return command_failed("report");
  }
  const bool title_given = title_option->count() > 0;
  // The script gets the arguments in a form no file name can be mistaken in: options
  // joined to their values, the files after "--".
  std::vector<std::string> script_args;
  script_args.reserve(results.size() + 3);
  script_args.push_back("--output=" + out);
  if (title_given) script_args.push_back("--title=" + title);
  script_args.emplace_back(std::string_view("--"));
  script_args.insert(script_args.end(), results.begin(), results.end());
  return run_python_script("report", "report.py", script_args);
}

}  // namespace

extern const Command kReportCommand = {
    "report", "write report.md and a self-contained report.html of one or more results files", run_report};

}  // namespace ccdlab
