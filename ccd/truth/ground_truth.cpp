#include <ccd/truth/ground_truth.hpp>

#include <ccd/motion/rigid_motion.hpp>
#include <ccd/truth/pair_contact.hpp>
#include <ccd/truth/truth.hpp>

#include <algorithm>
#include <tuple>

namespace ccd {

bool event_order(const ContactEvent& x, const ContactEvent& y) {
  return std::tie(x.enter, x.a, x.b) < std::tie(y.enter, y.a, y.b);
}

std::vector<ContactEvent> compute_truth(const Trajectories& traj, const TruthOptions& options) {
  const RigidMotion balls(traj);
  return compute_truth(balls, {}, options).events;
}

std::vector<ContactEvent> compute_truth_all_pairs(const Trajectories& traj) {
  std::vector<ContactEvent> events;
  std::vector<ContactInterval> iv;
  const auto n = static_cast<std::uint32_t>(traj.size());
  for (std::uint32_t a = 0; a < n; ++a) {
    for (std::uint32_t b = a + 1; b < n; ++b) {
      iv.clear();
      pair_contact_intervals(traj, a, b, 0.0, traj.horizon(), iv);
      for (const ContactInterval& x : iv) events.push_back({a, b, x.enter, x.exit});
    }
  }
  std::sort(events.begin(), events.end(), event_order);
  return events;
}

}  // namespace ccd
