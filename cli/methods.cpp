// `ccdlab methods [--names]`: the bounds, the broad phases, and how they compose.
#include "command.hpp"
#include "command_line.hpp"

#include "../experiments/method.hpp"

#include <iomanip>
#include <iostream>

namespace ccdlab {
namespace {

// One line per option: "option: name=default unit (doc; range)".
void print_options(std::span<const ccd::ParameterSpec> parameters) {
  for (const ccd::ParameterSpec& p : parameters)
    std::cout << "  " << std::setw(18) << "" << "option: " << ccd::describe_parameter(p) << "\n";
}

int run_methods(std::span<const std::string> args) {
  CommandLine cli("methods",
                  "Lists every bound (with what it may know and whether it is conservative), every\n"
                  "broad phase and every scheduler, each with its options (default, unit, range).\n",
                  "methods");
  bool names = false;
  cli.flag("--names", names, "print every composed fixed-step method name with default options, one per line");
  try {
    if (!cli.parse(args)) return 0;
  } catch (...) {
    return command_failed("methods");
  }
  if (names) {
    for (const std::string& m : all_method_names()) std::cout << m << "\n";
    return 0;
  }
  std::cout << "A method is BOUND/BROADPHASE[@SCHEDULER], e.g. aabb/sap, capsule/grid, horn:4/sap,\n"
               "horn:4/grid@earliest; each part may set its options as NAME:option=value,...\n"
               "(capsule/grid:cell=2, horn:pieces=8/sap, capsule/sap@earliest:stale=0.5).\n\nBounds:\n";
  std::cout << "  " << std::left << std::setw(18) << "name" << std::setw(9) << "knows" << std::setw(14)
            << "conservative" << "description\n";
  for (const ccd::BoundInfo& b : ccd::bound_registry()) {
    std::string name(b.name);
    if (!b.parameters.empty()) name += ":M";
    std::cout << "  " << std::setw(18) << name << std::setw(9) << ccd::to_string(b.knowledge) << std::setw(14)
              << (b.knowledge == ccd::Knowledge::Instant ? "no (samples)"
              : b.knowledge == ccd::Knowledge::Bounded && b.conservative ? "if |a| <= A"
              : b.conservative ? "yes" : "no")
              << b.description << "\n";
    print_options(b.parameters);
  }
  std::cout << "\nBroad phases:\n";
  for (const ccd::BroadPhaseInfo& p : ccd::broad_phase_registry())
  {
    std::cout << "  " << std::setw(18) << p.name << p.description << "\n";
    print_options(p.parameters);
  }
  std::cout << "\nSchedulers (after @; none means fixed; earliest needs a space-time bound):\n";
  for (const ccd::SchedulerInfo& x : ccd::scheduler_registry()) {
    std::cout << "  " << std::setw(18) << x.name << x.description << "\n";
    print_options(x.parameters);
  }
  std::cout << "\n" << all_method_names().size() << " methods with default parameters (ccdlab methods --names;\n"
            << "each space-time one also runs as NAME@earliest).\n";
  return 0;
}

}  // namespace

extern const Command kMethodsCommand = {
    "methods", "list the bounds and broad phases that compose methods BOUND/BROADPHASE", run_methods};

}  // namespace ccdlab
