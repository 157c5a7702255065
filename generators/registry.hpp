#pragma once
// The one table of scene generators: {name, description, parameters, function}. The
// `ccdlab scene` command, the experiment runner, the tests and docs/generators.md all
// read it, so a new generator is one file under generators/ plus one entry
// in registry.cpp.
//
// Every generator has the parameters seed, bodies, horizon and offset (first, in this
// order), is deterministic in its parameters (std::mt19937_64 seeded with `seed`, draw
// order in docs/generators.md), puts every body inside its box, and builds its scene
// near the origin; generate_scene() then adds `offset` to every position and to the box
// (floating-point addition, the same for every body) and checks the result with
// ccd::validate_scene. Should rounding at a large offset put a body a few ulps outside a
// wall, that wall is moved out to the body (by at most a few ulps of |offset|): positions
// always move by exactly the offset, the box by the offset up to that widening.
//
// Errors: an unknown generator or parameter, or a value out of range, throws
// std::invalid_argument with a one-line message naming it (and listing the valid names);
// callers prefix their context. A generator that breaks its own guarantee throws
// std::logic_error.
#include <ccd/scene/scene.hpp>
#include <generators/generator_parameters.hpp>

#include <nlohmann/json.hpp>
#include <span>
#include <string_view>

namespace ccdlab {

struct Generator {
  std::string_view name;
  std::string_view description;  ///< one line
  std::span<const ParameterSpec> parameters;
  /// Builds the scene near the origin (offset not applied). May throw
  /// std::invalid_argument for a rule between parameters (r_min <= r_max).
  ccd::Scene (*generate)(const ParameterSet& params);
};

/// The table, in the order of `ccdlab scene --help`.
std::span<const Generator> generators();
/// The generator called `name`; std::invalid_argument listing the valid names otherwise.
const Generator& generator_named(std::string_view name);

/// Runs `gen` on checked parameters, applies the offset, validates the scene.
ccd::Scene generate_scene(const Generator& gen, const ParameterSet& params);
/// Checks `given` against the generator's table (resolve_parameters) and runs it.
ccd::Scene generate_scene(std::string_view name, std::span<const ParameterValue> given);
/// For experiment files: params is a JSON object such as {"bodies": 2000, "seed": 7}.
ccd::Scene generate_scene(std::string_view name, const nlohmann::json& params);

}  // namespace ccdlab
