// ccdlab: continuous collision detection laboratory. `ccdlab --help` lists the commands.
#include "commands/command.hpp"

#include <ccd/io/atomic_file.hpp>

#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  ccd::install_temporary_file_cleanup();  // no FILE.tmp.* left behind by a signal
  std::vector<std::string> args(argv + 1, argv + argc);
  auto print_help = [](std::ostream& out) {
    out << "ccdlab " << ccdlab::version_string()
        << ": a research toolkit for continuous collision detection of moving spheres.\n\n"
           "usage: ccdlab COMMAND [ARGS...]\n       ccdlab COMMAND --help\n       ccdlab --version\n\n"
           "commands:\n";
    for (const ccdlab::Command& c : ccdlab::commands())
      out << "  " << c.name << std::string(c.name.size() < 10 ? 10 - c.name.size() : 1, ' ') << c.summary
          << "\n";
    out << "\nExit status: 0 success, 1 runtime failure, 2 bad input or usage (no output file written).\n";
  };
  if (args.empty()) {
    print_help(std::cerr);
    return ccdlab::kExitBadInput;
  }
  if (args[0] == "-h" || args[0] == "--help" || args[0] == "help") {
    print_help(std::cout);
    return 0;
  }
  if (args[0] == "--version" || args[0] == "version") {
    std::cout << "ccdlab " << ccdlab::version_string() << "\n";
    return 0;
  }
  for (const ccdlab::Command& c : ccdlab::commands()) {
    if (c.name != args[0]) continue;
    std::vector<std::string> rest(args.begin() + 1, args.end());
    if (ccdlab::wants_help(rest)) {
      std::cout << c.usage;
      return 0;
    }
    // Each command reports its own errors; this is the last line of defence, so that no
    // exception ends the process without a message (and without removing temporaries).
    try {
      return c.run(rest);
    } catch (const std::bad_alloc&) {
      std::cerr << "ccdlab " << c.name << ": out of memory\n";
    } catch (const std::exception& e) {
      std::cerr << "ccdlab " << c.name << ": " << e.what() << "\n";
    }
    return 1;
  }
  std::cerr << "ccdlab: unknown command '" << args[0] << "'; valid commands:";
  for (const ccdlab::Command& c : ccdlab::commands()) std::cerr << " " << c.name;
  std::cerr << "\n";
  return ccdlab::kExitBadInput;
}
