#include "mesh_ccd_json.hpp"

#include <cmath>

namespace ccd::cloth {

nlohmann::json mesh_ccd_json(const MeshCcdResult& r, const MeshCcdOptions& o, unsigned threads) {
  nlohmann::json j;
  j["format"] = "ccdlab-mesh-ccd/1";
  j["options"] = {{"separation", o.separation}, {"cull", o.culler}, {"threads", threads}, {"exact", o.exact}};
  j["vertices"] = r.vertices;
  j["edges"] = r.edges;
  j["faces"] = r.faces;
  j["candidates"] = {{"vf", r.candidates_vf}, {"ee", r.candidates_ee}};
  j["collisions"] = {{"vf", r.vf}, {"ee", r.ee}};
  if (r.toi) {
    j["toi"] = {{"time", r.toi->time}, {"error", nullptr}};
    if (std::isfinite(r.toi->error)) j["toi"]["error"] = r.toi->error;
  } else {
    j["toi"] = nullptr;
  }
  j["budget_spent"] = r.budget_spent;
  if (o.exact)
    j["exact"] = {{"false_positives", {{"vf", r.false_vf}, {"ee", r.false_ee}}}};
  else
    j["exact"] = nullptr;
  j["seconds"] = {{"boxes", r.seconds.boxes}, {"broad", r.seconds.broad}, {"narrow", r.seconds.narrow}};
  return j;
}

}  // namespace ccd::cloth
