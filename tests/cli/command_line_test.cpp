// The one argument parser (cli/command_line.hpp): in-process, what it
// accepts and the one line it throws for each kind of bad usage; through the ccdlab
// program, that every command and subcommand prints a help listing each of its options
// with a description, names an unknown option (exit 2, one line), and names the option
// whose number is malformed.
#include "cli_support.hpp"

#include <cli/command.hpp>
#include <cli/command_line.hpp>

#include <catch2/catch.hpp>
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace cli_command_line_test {

using ccdlab::CommandLine;
using ccdlab::UsageError;
using ccdlab::test::Folder;
using ccdlab::test::run_ccdlab;

namespace {

// The message of the UsageError that parsing `args` throws ("" when none is thrown).
std::string usage_error(CommandLine& cli, const std::vector<std::string>& args) {
  try {
    cli.parse(args);
  } catch (const UsageError& e) {
    return e.what();
  }
  return {};
}

struct Parsed {
  std::string file, out, title;
  std::uint64_t threads = 0;
  double separation = -1.0;
  bool force = false;
};

void declare(CommandLine& cli, Parsed& p) {
  cli.positional("FILE", p.file, "the input");
  cli.text("-o,--output", p.out, "OUT", "the output", "-o needs a file name");
  cli.text("--title", p.title, "TEXT", "a title", "", /*once=*/true);
  cli.integer("--threads", 1, 64, "N", "threads", [&p](std::uint64_t n) { p.threads = n; });
  cli.number("--separation", 0.0, false, "D", "a distance", [&p](double d) { p.separation = d; });
  cli.flag("--force", p.force, "go on");
}

}  // namespace

TEST_CASE("CommandLine: options, positionals and the value each one takes", "[cli][command_line]") {
  CommandLine cli("demo", "A demonstration.\n", "demo");
  Parsed p;
  declare(cli, p);
  REQUIRE(cli.parse(std::vector<std::string>{"in.json", "--threads", "8", "-o", "-", "--separation=0.5", "--force"}));
  CHECK(p.file == "in.json");
  CHECK(p.out == "-");  // "-" is a value (standard output), not an option
  CHECK(p.threads == 8);
  CHECK(p.separation == 0.5);
  CHECK(p.force);
}

TEST_CASE("CommandLine: after --, every argument is positional", "[cli][command_line]") {
  CommandLine cli("demo", "A demonstration.\n", "demo");
  Parsed p;
  declare(cli, p);
  REQUIRE(cli.parse(std::vector<std::string>{"--force", "--", "-in.json"}));
  CHECK(p.file == "-in.json");
  CHECK(p.force);
  CommandLine again("demo", "A demonstration.\n", "demo");
  Parsed q;
  declare(again, q);
  CHECK(usage_error(again, {"--", "a.json", "-b.json"}) == "unexpected argument '-b.json' (see ccdlab demo --help)");
}

TEST_CASE("CommandLine: every usage error is one UsageError naming the option", "[cli][command_line]") {
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::string hint = " (see ccdlab demo --help)";
  const Case cases[] = {
      {{"in.json", "--threads", "-1"}, "--threads: must be an integer in [1, 64], got '-1'" + hint},
      {{"in.json", "--threads", "abc"}, "--threads: must be an integer in [1, 64], got 'abc'" + hint},
      {{"in.json", "--threads", "65"}, "--threads: must be an integer in [1, 64], got '65'" + hint},
      {{"in.json", "--threads"}, "--threads needs an integer in [1, 64]" + hint},
      {{"in.json", "--separation", "nan"}, "--separation: must be a finite number >= 0, got 'nan'" + hint},
      {{"in.json", "--separation", "-0.5"}, "--separation: must be a finite number >= 0, got '-0.5'" + hint},
      {{"in.json", "--separation", "1e999"}, "--separation: must be a finite number >= 0, got '1e999'" + hint},
      {{"in.json", "-o"}, "-o needs a file name" + hint},
      {{"in.json", "--output"}, "-o needs a file name" + hint},
      {{"in.json", "--title", "a", "--title", "b"}, "--title given twice" + hint},
      {{"in.json", "--bogus"}, "unknown option '--bogus'" + hint},
      {{"in.json", "-x"}, "unknown option '-x'" + hint},
      {{"in.json", "other.json"}, "unexpected argument 'other.json'" + hint},
      {{"--force"}, "missing FILE" + hint},
  };
  for (const Case& c : cases) {
    const std::string shown = c.args.size() > 1 ? c.args[1] : c.args[0];
    INFO(shown);
    CommandLine cli("demo", "A demonstration.\n", "demo");
    Parsed p;
    declare(cli, p);
    CHECK(usage_error(cli, c.args) == c.message);
  }
  // Without a command to point to, the line has no pointer.
  CommandLine quiet("demo", "", "");
  Parsed p;
  declare(quiet, p);
  CHECK(usage_error(quiet, {"in.json", "--threads", "0"}) == "--threads: must be an integer in [1, 64], got '0'");
  // fail() is the same line for the command's own checks.
  CHECK_THROWS_WITH(quiet.fail("missing -o OUT"), "missing -o OUT");
}

TEST_CASE("CommandLine: --help prints the usage and stops the command", "[cli][command_line]") {
  CommandLine cli("demo", "A demonstration.\n", "demo");
  cli.footer("Exit status: 0.");
  Parsed p;
  declare(cli, p);
  std::ostringstream captured;
  std::streambuf* old = std::cout.rdbuf(captured.rdbuf());
  const bool go_on = cli.parse(std::vector<std::string>{"--help"});  // the positional is not asked for
  std::cout.rdbuf(old);
  CHECK_FALSE(go_on);
  const std::string help = captured.str();
  CHECK(help == cli.help());
  CHECK(help.find("A demonstration.") == 0);
  CHECK(help.find("Usage: ccdlab demo [OPTIONS] FILE") != std::string::npos);
  for (const char* line : {"  -o,--output OUT", "  --threads N", "  --separation D", "  --force", "  --title TEXT"})
    CHECK(help.find(line) != std::string::npos);
  CHECK(help.find("Exit status: 0.") != std::string::npos);
}

namespace {

// Every command and subcommand with each option its --help must list.
const std::map<std::string, std::vector<std::string>>& command_options() {
  static const std::map<std::string, std::vector<std::string>> table = {
      {"run", {"--output", "--threads", "--shard", "--truth", "--quiet", "--force", "--list-missed", "--truth-cache"}},
      {"truth", {"--output", "--threads", "--windows", "--quiet", "--force"}},
      {"scene", {"--output"}},
      {"methods", {"--names"}},
      {"merge", {"--output"}},
      {"ccd",
       {"--output", "--kind", "--separation", "--tolerance", "--max-boxes", "--exact", "--write-hard", "--write-near-miss",
        "--keep-tolerance-stops", "--force",
        "--cull", "--threads", "--quiet"}},
      {"cloth", {"--output", "--n", "--steps", "--every", "--cull", "--force"}},
      {"cloth frames", {"--output", "--n", "--steps", "--force"}},
      {"cloth queries", {"--output", "--steps", "--culler", "--hard-below", "--n", "--threads", "--force"}},
      {"report", {"--output", "--title"}},
      {"animate", {"--results", "--method", "--dt", "--from", "--to", "--fps", "--frames-per-step", "--output", "--force"}},
      {"view", {"--results", "--truth", "--output", "--force"}},
      {"poses", {"--times", "--output", "--force"}},
      {"import", {"--output", "--radius", "--shapes", "--force"}},
      {"pack", {"--output", "--json"}},
      {"mesh-frames", {"--output", "--faces", "--seed", "--n", "--step", "--ascii", "--force"}},
  };
  return table;
}

// True when `help` has a line for option `name` ("  -o,--output FILE  text") with a description.
bool lists_option(const std::string& help, const std::string& name) {
  std::istringstream lines(help);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string names, word;
    words >> names;
    if (line.rfind("  -", 0) != 0) continue;
    std::vector<std::string> parts;
    for (std::size_t start = 0;;) {
      const std::size_t comma = names.find(',', start);
      parts.push_back(names.substr(start, comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (std::find(parts.begin(), parts.end(), name) == parts.end()) continue;
    int more = 0;
    while (words >> word) ++more;
    return more >= 2;  // a value name and a word, or two words
  }
  return false;
}

}  // namespace

TEST_CASE("every command's --help exits 0 and describes each of its options", "[cli][command_line]") {
  Folder dir;
  // The table covers every command of the program.
  for (const ccdlab::Command& c : ccdlab::commands()) {
    INFO(c.name);
    CHECK(command_options().count(std::string(c.name)) == 1);
  }
  for (const auto& [command, options] : command_options()) {
    INFO(command);
    std::string out, err;
    REQUIRE(run_ccdlab(command + " --help", dir, &out, &err) == 0);
    CHECK(err.empty());
    CHECK(out.find("Usage: ccdlab " + command + " [OPTIONS]") != std::string::npos);
    CHECK(lists_option(out, "--help"));
    for (const std::string& option : options) {
      INFO(option);
      CHECK(lists_option(out, option));
    }
    // -h is --help
    std::string short_out;
    REQUIRE(run_ccdlab(command + " -h", dir, &short_out) == 0);
    CHECK(short_out == out);
  }
}

TEST_CASE("every command names an unknown option in one line and exits 2", "[cli][command_line]") {
  Folder dir;
  for (const auto& entry : command_options()) {
    const std::string& command = entry.first;
    INFO(command);
    std::string out, err;
    CHECK(run_ccdlab(command + " in.json --no-such-option -o " + (dir / "out"), dir, &out, &err) == 2);
    CHECK(err.rfind("ccdlab " + command + ": unknown option '--no-such-option'", 0) == 0);
    CHECK(std::count(err.begin(), err.end(), '\n') == 1);
    CHECK(out.empty());
  }
  CHECK_FALSE(std::filesystem::exists(dir / "out"));
}

TEST_CASE("numbers given to options are checked, naming the option", "[cli][command_line]") {
  Folder dir;
  struct Case {
    std::string args, line;
  };
  const Case cases[] = {
      {"run e.json --threads -1", "ccdlab run: --threads: must be an integer in [1, 4096], got '-1' (see ccdlab run --help)"},
      {"run e.json --threads abc", "ccdlab run: --threads: must be an integer in [1, 4096], got 'abc' (see ccdlab run --help)"},
      {"run e.json --threads 2.5", "ccdlab run: --threads: must be an integer in [1, 4096], got '2.5' (see ccdlab run --help)"},
      {"run e.json --shard 3/2", "ccdlab run: --shard needs K/N with 1 <= K <= N (see ccdlab run --help)"},
      {"truth s.json --threads 0", "ccdlab truth: --threads needs a positive integer, got '0' (see ccdlab truth --help)"},
      {"animate s.json --dt nan",
       "ccdlab animate: --dt: must be a finite number > 0, got 'nan' (see ccdlab animate --help)"},
      {"animate s.json --dt 0", "ccdlab animate: --dt: must be a finite number > 0, got '0' (see ccdlab animate --help)"},
      {"animate s.json --from inf",
       "ccdlab animate: --from: must be a finite number, got 'inf' (see ccdlab animate --help)"},
      {"animate s.json --fps 0",
       "ccdlab animate: --fps: must be an integer in [1, 100], got '0' (see ccdlab animate --help)"},
      {"ccd q.csv --kind vf --separation nan",
       "ccdlab ccd: --separation: must be a finite number >= 0, got 'nan' (see ccdlab ccd --help)"},
      {"ccd q.csv --kind vf --max-boxes 0",
       "ccdlab ccd: --max-boxes: must be an integer in [1, 1073741824], got '0' (see ccdlab ccd --help)"},
      {"cloth drape --n 3", "ccdlab cloth: --n: must be an integer in [4, 1000], got '3' (see ccdlab cloth --help)"},
      {"cloth frames drape --steps 0",
       "ccdlab cloth frames: --steps: must be an integer in [1, 1000000], got '0' (see ccdlab cloth --help)"},
      {"cloth queries drape --threads x",
       "ccdlab cloth queries: --threads: must be an integer in [1, 1024], got 'x' (see ccdlab cloth --help)"},
      {"mesh-frames tori --faces 7",
       "ccdlab mesh-frames: --faces: must be an integer in [8, 67108864], got '7' (see ccdlab mesh-frames --help)"},
      {"import f.csv --radius -1", "ccdlab import: --radius must be a number > 0, got '-1' (see ccdlab import --help)"},
  };
  for (const Case& c : cases) {
    INFO(c.args);
    std::string err;
    CHECK(run_ccdlab(c.args + " -o " + (dir / "out"), dir, nullptr, &err) == 2);
    CHECK(err == c.line + "\n");
  }
  CHECK_FALSE(std::filesystem::exists(dir / "out"));
}

}  // namespace cli_command_line_test
