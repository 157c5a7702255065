// `ccdlab scene GENERATOR [NAME=VALUE ...] -o SCENE.json`: writes a generated scene.
#include "command.hpp"

#include <ccd/io/atomic_file.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_io.hpp>
#include <experiments/generators/registry.hpp>

#include <algorithm>
#include <cstdint>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace ccdlab {
namespace {

// The usage text lists every generator of the registry with its parameters and defaults.
std::string make_scene_usage() {
  std::string text =
      "usage: ccdlab scene GENERATOR [NAME=VALUE ...] -o SCENE.json\n\n"
      "Writes a generated scene (format ccdlab-scene/1) atomically; -o - writes to standard output.\n"
      "The output is checked before generating: a regular file, in a folder that takes a file.\n"
      "Values are numbers; offset takes one number (all axes) or three: offset=1e6,0,-1e6.\n"
      "The same parameters give the same file (docs/generators.md lists the draw order).\n\n"
      "generators:\n";
  for (const Generator& g : generators()) {
    text += "  " + std::string(g.name) + ": " + std::string(g.description) + "\n";
    for (const ParameterSpec& s : g.parameters) {
      std::string left = "      " + std::string(s.name) + "=" + format_number(s.default_value);
      left.resize(std::max<std::size_t>(left.size() + 1, 30), ' ');
      text += left + std::string(s.doc) + "; " + describe_range(s) + "\n";
    }
  }
  text += "\nExit status: 0 success, 1 runtime failure (a failed write, out of memory), 2 bad generator,\n"
          "parameter, output file or usage (nothing written).\n";
  return text;
}

const std::string& scene_usage() {
  static const std::string text = make_scene_usage();
  return text;
}

int run_scene(std::span<const std::string> args) {
  std::string generator;
  std::string output;
  bool have_output = false;
  std::vector<std::string> assignments;  // NAME=VALUE, parsed once the generator is known
  std::uint64_t bodies = 0;
  try {
    for (std::size_t i = 0; i < args.size(); ++i) {
      const std::string& a = args[i];
      if (a == "-o") {
        if (i + 1 == args.size()) throw std::invalid_argument("-o needs a file name");
        output = args[++i];
        have_output = true;
      } else if (a.size() > 1 && a[0] == '-') {
        throw std::invalid_argument("unknown option '" + a + "'");
      } else if (generator.empty()) {
        generator = a;
      } else {
        assignments.push_back(a);
      }
    }
    if (generator.empty()) throw std::invalid_argument("missing GENERATOR (see ccdlab scene --help)");
    const Generator& gen = generator_named(generator);
    if (!have_output) throw std::invalid_argument("missing -o SCENE.json");
    ccd::ParameterSet params;
    try {
      std::vector<ParameterValue> given;
      for (const std::string& a : assignments) given.push_back(parameter_value_from_text(a));
      params = resolve_parameters(gen.parameters, given);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(generator + ": " + e.what());
    }
    ccd::OutputFile out(output);
    bodies = params.integer("bodies");
    const ccd::Scene scene = generate_scene(gen, params);
    out.commit(ccd::scene_to_json(scene).dump(1) + "\n");
  } catch (const std::invalid_argument& e) {
    std::cerr << "ccdlab scene: " << e.what() << "\n";
    return kExitBadInput;
  } catch (...) {
    return command_failed("scene", "generating " + generator + " with bodies=" + std::to_string(bodies));
  }
  return 0;
}

}  // namespace

// Dynamically initialised (the usage text is built from the registry); commands() reads
// it only after that, since it odr-uses this object.
extern const Command kSceneCommand = {"scene", "generate a scene (ccdlab scene --help lists the generators)",
                                      scene_usage(), run_scene};

}  // namespace ccdlab
