#include "method.hpp"

#include <stdexcept>

namespace ccdlab {

MethodSpec parse_method(std::string_view full_name) {
  const auto at = full_name.find('@');
  const std::string_view name = full_name.substr(0, at);
  const auto slash = name.find('/');
  if (slash == std::string_view::npos || name.find('/', slash + 1) != std::string_view::npos) {
    std::string valid;
    for (const std::string& m : all_method_names()) {
      if (!valid.empty()) valid += ", ";
      valid += m;
    }
    throw std::invalid_argument("method '" + std::string(full_name) +
                                "' is not of the form BOUND/BROADPHASE[@SCHEDULER]; valid methods: " + valid);
  }
  MethodSpec m;
  m.name = std::string(full_name);
  m.bound_text = std::string(name.substr(0, slash));
  m.broad_phase_text = std::string(name.substr(slash + 1));
  m.scheduler_named = at != std::string_view::npos;
  if (m.scheduler_named) m.scheduler_text = std::string(full_name.substr(at + 1));
  m.bound = ccd::parse_bound(m.bound_text);
  m.broad_phase = ccd::parse_broad_phase(m.broad_phase_text);
  m.scheduler = m.scheduler_named ? ccd::parse_scheduler(m.scheduler_text) : ccd::default_scheduler();
  if (m.scheduled() && !m.continuous())
    throw std::invalid_argument("method '" + std::string(full_name) + "': bound '" +
                                std::string(m.bound.info->name) +
                                "' is an instant bound; the earliest scheduler needs a space-time bound");
  return m;
}

std::vector<std::string> method_names(const std::vector<MethodSpec>& methods) {
  std::vector<std::string> out;
  for (const MethodSpec& m : methods) out.push_back(m.name);
  return out;
}

nlohmann::json options_json(const MethodSpec& method) {
  nlohmann::json j = {{"bound", method.bound.options.to_json()},
                      {"broad_phase", method.broad_phase.options.to_json()}};
  if (method.scheduler_named) {
    nlohmann::json s = method.scheduler.options.to_json();
    s["name"] = std::string(method.scheduler.info->name);
    j["scheduler"] = std::move(s);
  }
  return j;
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

std::vector<std::string> scheduled_method_names() {
  std::vector<std::string> out;
  for (const std::string& m : all_method_names())
    if (parse_method(m).continuous()) out.push_back(m + "@earliest");
  return out;
}

}  // namespace ccdlab
