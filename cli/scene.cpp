// `ccdlab scene GENERATOR [NAME=VALUE ...] -o SCENE.json`: writes a generated scene.
#include "command.hpp"
#include "command_line.hpp"

#include <ccd/io/atomic_file.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_io.hpp>
#include <generators/registry.hpp>

#include <algorithm>
#include <cstdint>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace ccdlab {
namespace {

constexpr const char* kSceneDescription =
    "Writes a generated scene (format ccdlab-scene/1) atomically; -o - writes to standard output.\n"
    "The output is checked before generating: a regular file, in a folder that takes a file.\n"
    "Values are numbers; offset takes one number (all axes) or three: offset=1e6,0,-1e6.\n"
    "The same parameters give the same file (docs/generators.md lists the draw order).\n";

// The text below the options lists every generator of the registry with its parameters
// and defaults.
std::string make_scene_footer() {
  std::string text = "generators:\n";
  for (const Generator& g : generators()) {
    text += "  " + std::string(g.name) + ": " + std::string(g.description) + "\n";
    for (const ParameterSpec& s : g.parameters) {
      std::string left = "      " + std::string(s.name) + "=" + format_number(s.default_value);
      left.resize(std::max<std::size_t>(left.size() + 1, 30), ' ');
      text += left + std::string(s.doc) + "; " + describe_range(s) + "\n";
    }
  }
  text += "\nExit status: 0 success, 1 runtime failure (a failed write, out of memory), 2 bad generator,\n"
          "parameter, output file or usage (nothing written).";
  return text;
}

int run_scene(std::span<const std::string> args) {
  std::string generator;
  std::string output;
  bool have_output = false;
  std::vector<std::string> assignments;  // NAME=VALUE, parsed once the generator is known
  std::uint64_t bodies = 0;
  CommandLine cli("scene", kSceneDescription, "");  // its errors name the generator, not --help
  cli.footer(make_scene_footer());
  cli.positional("GENERATOR", generator, "a generator (listed below)");
  cli.positionals("NAME=VALUE", assignments, "the generator's parameters (listed below with their defaults)", false);
  cli.value(
      "-o,--output", "SCENE.json", "the scene file ('-' = standard output)",
      [&](const std::string& v) {
        output = v;
        have_output = true;
      },
      "-o needs a file name");
  try {
    if (!cli.parse(args)) return 0;
    if (generator.empty()) cli.fail("missing GENERATOR (see ccdlab scene --help)");
    // The registry reports a bad generator or parameter as std::invalid_argument: bad usage.
    const Generator& gen = [&]() -> const Generator& {
      try {
        return generator_named(generator);
      } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
      }
    }();
    if (!have_output) cli.fail("missing -o SCENE.json");
    ccd::ParameterSet params;
    try {
      std::vector<ParameterValue> given;
      for (const std::string& a : assignments) given.push_back(parameter_value_from_text(a));
      params = resolve_parameters(gen.parameters, given);
    } catch (const std::invalid_argument& e) {
      throw UsageError(generator + ": " + e.what());
    }
    ccd::OutputFile out(output);
    bodies = params.integer("bodies");
    const ccd::Scene scene = [&] {
      try {
        return generate_scene(gen, params);
      } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
      }
    }();
    out.commit(ccd::scene_to_json(scene).dump(1) + "\n");
  } catch (...) {
    return command_failed("scene", "generating " + generator + " with bodies=" + std::to_string(bodies));
  }
  return 0;
}

}  // namespace

extern const Command kSceneCommand = {"scene", "generate a scene (ccdlab scene --help lists the generators)",
                                      run_scene};

}  // namespace ccdlab
