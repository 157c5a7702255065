#include "method.hpp"

#include <stdexcept>

namespace ccdlab {

MethodSpec parse_method(std::string_view name) {
  const auto slash = name.find('/');
  if (slash == std::string_view::npos || name.find('/', slash + 1) != std::string_view::npos) {
    std::string valid;
    for (const std::string& m : all_method_names()) {
      if (!valid.empty()) valid += ", ";
      valid += m;
    }
    throw std::invalid_argument("method '" + std::string(name) +
                                "' is not of the form BOUND/BROADPHASE; valid methods: " + valid);
  }
  MethodSpec m;
  m.name = std::string(name);
  m.bound = ccd::parse_bound(name.substr(0, slash));
  m.broad_phase = ccd::parse_broad_phase(name.substr(slash + 1));
  return m;
}

nlohmann::json options_json(const MethodSpec& method) {
  return {{"bound", method.bound.options.to_json()}, {"broad_phase", method.broad_phase.options.to_json()}};
}

std::vector<std::string> all_method_names() {
  std::vector<std::string> out;
  for (const ccd::BoundInfo& b : ccd::bound_registry()) {
    std::string bound(b.name);
    if (!b.parameters.empty()) {  // the first option's default, as ":M"
      bound += ':';
      bound += ccd::format_number(b.parameters[0].default_value);
    }
    for (const ccd::BroadPhaseInfo& p : ccd::broad_phase_registry()) out.push_back(bound + "/" + std::string(p.name));
  }
  return out;
}

}  // namespace ccdlab
