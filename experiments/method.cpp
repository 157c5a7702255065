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
  m.bound = ccd::parse_bound(name.substr(0, slash));
  m.broad_phase = &ccd::find_broad_phase(name.substr(slash + 1));
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "x" + std::string.
  m.name = std::string(m.bound.info->name);
  if (m.bound.info->parameterised) {
    m.name.push_back(':');
    m.name.append(std::to_string(m.bound.parameter));
  }
  m.name.push_back('/');
  m.name.append(m.broad_phase->name);
  return m;
}

std::vector<std::string> all_method_names() {
  std::vector<std::string> out;
  for (const ccd::BoundInfo& b : ccd::bound_registry()) {
    std::string bound(b.name);
    if (b.parameterised) {
      bound += ':';
      bound += std::to_string(b.default_parameter);
    }
    for (const ccd::BroadPhaseInfo& p : ccd::broad_phase_registry()) out.push_back(bound + "/" + std::string(p.name));
  }
  return out;
}

}  // namespace ccdlab
