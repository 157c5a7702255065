#include <generators/box_scene.hpp>

namespace ccdlab {

ccd::Scene box_scene(const ParameterSet& params, const ccd::Vec3& box_max) {
  ccd::Scene scene;
  scene.horizon = params.number("horizon");
  scene.box = ccd::WallBox{ccd::Vec3::Zero(), box_max};
  scene.bodies.resize(params.integer("bodies"));
  return scene;
}

}  // namespace ccdlab
