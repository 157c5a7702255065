#pragma once
// The common start of every generated scene: the horizon parameter, a box of elastic
// walls [0, box_max] (the offset is applied later by generate_scene), and `bodies`
// default-initialised bodies for the generator to fill in.
#include <ccd/scene/scene.hpp>
#include <generators/generator_parameters.hpp>

namespace ccdlab {

ccd::Scene box_scene(const ParameterSet& params, const ccd::Vec3& box_max);

}  // namespace ccdlab
