// ccdlab: continuous collision detection laboratory. `ccdlab --help` lists the commands.
#include "command.hpp"

#include <ccd/io/atomic_file.hpp>

#include <cstdio>
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

// The running command's name, for the terminate handler (written before the command runs).
char g_command[64] = "ccdlab";

// The last line of defence: an exception that reaches std::terminate (one thrown where no
// handler may catch it, e.g. std::bad_alloc while a huge JSON value is destroyed under a
// memory limit) still ends with one line, status 1 for out of memory, and no temporary
// file, never an abort with a core dump.
[[noreturn]] void on_terminate() noexcept {
  ccd::remove_pending_temporary_files();
  const char* what = "internal error";
  if (const std::exception_ptr e = std::current_exception()) {
    try {
      std::rethrow_exception(e);
    } catch (const std::bad_alloc&) {
      what = "out of memory";
    } catch (...) {
    }
  }
  char line[128];  // no allocation: memory may have run out
  const int n = std::snprintf(line, sizeof line, "%s: %s\n", g_command, what);
  [[maybe_unused]] const auto written = ::write(STDERR_FILENO, line, n > 0 ? static_cast<std::size_t>(n) : 0);
  ::_exit(1);
}

}  // namespace

int main(int argc, char** argv) {
  ccd::install_temporary_file_cleanup();  // no FILE.tmp.* left behind by a signal
  std::set_terminate(on_terminate);
  std::vector<std::string> args(argv + 1, argv + argc);
  auto print_help = [](std::ostream& out) {
    out << "ccdlab " << ccdlab::version_string()
        << ": a research toolkit for continuous collision detection: exact ground truth for\n"
           "spheres and rigid bodies among static scenery, cloth and triangle meshes; discrete and\n"
           "conservative methods swept over the timestep against it; a viewer of every missed contact.\n\n"
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
    std::snprintf(g_command, sizeof g_command, "ccdlab %.*s", static_cast<int>(c.name.size()), c.name.data());
    std::vector<std::string> rest(args.begin() + 1, args.end());
    // Each command parses its arguments (--help included) and reports its own errors; this
    // is the last line of defence, so that no exception ends the process without a message
    // (and without removing temporaries).
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
