#include "view_volumes.hpp"

#include "method.hpp"
#include "view_data.hpp"

#include <ccd/motion/rigid_motion.hpp>
#include <pipeline/fixed_step_scheduler.hpp>
#include <pipeline/window_policy.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace ccdlab {
namespace {

using nlohmann::json;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

json view_vec(const ccd::Vec3& v) { return json::array({view_number(v.x()), view_number(v.y()), view_number(v.z())}); }

json volume_json(const ccd::Volume& v) {
  json j{{"kind", std::string(ccd::to_string(v.kind))}, {"t", json::array({v.t0, v.t1})}};  // times in full
  switch (v.kind) {
    case ccd::Volume::Kind::Box:
      j["lo"] = view_vec(v.a);
      j["hi"] = view_vec(v.b);
      break;
    case ccd::Volume::Kind::Sphere:
      j["c"] = view_vec(v.a);
      j["r"] = view_number(v.radius);
      break;
    case ccd::Volume::Kind::Capsule:
      j["a"] = view_vec(v.a);
      j["b"] = view_vec(v.b);
      j["r"] = view_number(v.radius);
      break;
    case ccd::Volume::Kind::OrientedBox: {
      json axes = json::array();
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) axes.push_back(view_number(v.axes(k, c)));
      j["c"] = view_vec(v.a);
      j["axes"] = std::move(axes);
      j["half"] = view_vec(v.b);
      break;
    }
  }
  return j;
}

// What one run built its bound with, and over which windows.
class RunVolumes {
 public:
  RunVolumes(const ccd::Scene& scene, const ccd::Trajectories& traj, const ccd::RigidMotion& motion,
             const MethodSpec& method, double dt, double acceleration_bound)
      : scene_(scene), traj_(traj), dt_(dt), bound_(method.bound.make()) {
    continuous_ = method.continuous();
    steps_ = ccd::fixed_step_count(scene.horizon, dt, continuous_);
    if (method.scheduled()) {
      double radii = 0.0;
      for (std::size_t i = 0; i < traj.size(); ++i) radii += traj.radius(i);
      const double reach = method.scheduler.options.number("reach");
      policy_ = ccd::WindowPolicy{dt, scene.horizon, acceleration_bound,
                                  reach > 0.0 && traj.size() ? reach * radii / double(traj.size()) : 0.0,
                                  method.scheduler.options.integer("align") != 0};
    }
    ctx_.acceleration_bound = acceleration_bound;
    ctx_.walls = scene.box;
    ctx_.exact = method.bound.info->knowledge == ccd::Knowledge::Exact ? &traj : nullptr;
    ctx_.motion = &motion;
    states_.resize(traj.size());
  }

  // The window of body i that holds t (the first at a window's end); empty when none.
  std::optional<ccd::Window> window_at(std::size_t i, double t) const {
    if (steps_ == 0) return std::nullopt;
    if (!policy_) {
      std::uint64_t k = static_cast<std::uint64_t>(std::max(0.0, std::floor(t / dt_)));
      k = std::min(k, steps_ - 1);
      while (k > 0 && double(k) * dt_ > t) --k;
      return step(k);
    }
    ccd::Window w{0.0, 0.0};
    do {
      w = next_window(i, w.t1);
    } while (w.t1 < t && w.t1 < scene_.horizon);
    return w;
  }

  // Every window of body i in time order, or empty when there are more than `limit`.
  std::vector<ccd::Window> windows(std::size_t i, double limit) const {
    std::vector<ccd::Window> out;
    if (!policy_) {
      if (double(steps_) > limit) return {};
      for (std::uint64_t k = 0; k < steps_; ++k) out.push_back(step(k));
      return out;
    }
    double t = 0.0;
    do {
      if (double(out.size()) >= limit) return {};
      out.push_back(next_window(i, t));
      t = out.back().t1;
    } while (t < scene_.horizon);
    return out;
  }

  // Appends to `out` body i's entry [w0, w1, [volumes]] for window w.
  void append(std::size_t i, const ccd::Window& w, json& out) {
    const std::uint32_t body = static_cast<std::uint32_t>(i);
    ctx_.t0 = w.t0;
    ctx_.t1 = continuous_ ? w.t1 : w.t0;
    if (!continuous_) {  // an instant bound has no refresh: the whole sample, once per sample
      if (!prepared_ || *prepared_ != w.t0) {
        for (std::size_t j = 0; j < traj_.size(); ++j) states_[j] = state(j, w.t0);
        ctx_.start = states_;
        bound_->prepare(ctx_, boxes_);
        prepared_ = w.t0;
      }
    } else {
      states_[i] = state(i, w.t0);
      ctx_.start = states_;
      boxes_.resize(traj_.size());
      bound_->refresh(ctx_, std::span<const std::uint32_t>(&body, 1), boxes_);
    }
    volumes_.clear();
    bound_->volumes(body, volumes_);
    json list = json::array();
    for (const ccd::Volume& v : volumes_) list.push_back(volume_json(v));
    out.push_back(json::array({w.t0, w.t1, std::move(list)}));
  }

  bool scheduled() const { return policy_.has_value(); }

  // Volumes per body-window (the same for every body and window of a bound).
  std::size_t per_window() {
    if (traj_.size() == 0 || steps_ == 0) return 0;
    json probe = json::array();
    append(0, *window_at(0, 0.0), probe);
    return probe[0][2].size();
  }

 private:
  ccd::Window step(std::uint64_t k) const {
    // An instant bound's volumes are at k dt; the page shows them until the next sample.
    return {double(k) * dt_, std::min(double(k + 1) * dt_, scene_.horizon)};
  }
  ccd::BodyState state(std::size_t i, double t) const {
    const ccd::Piece& q = traj_.piece_at(i, t);
    return {q.position(t), q.velocity(t), traj_.radius(i)};
  }
  // The earliest scheduler's window of body i that starts at t.
  ccd::Window next_window(std::size_t i, double t) const {
    return {t, policy_->end(policy_->length(state(i, t).velocity), t)};
  }

  const ccd::Scene& scene_;
  const ccd::Trajectories& traj_;
  double dt_;
  std::unique_ptr<ccd::Bound> bound_;
  bool continuous_ = false;
  std::uint64_t steps_ = 0;
  std::optional<ccd::WindowPolicy> policy_;
  ccd::StepContext ctx_;
  std::vector<ccd::BodyState> states_;
  std::vector<ccd::Aabb> boxes_;
  std::vector<ccd::Volume> volumes_;
  std::optional<double> prepared_;  // the sample an instant bound was last prepared at
};

std::string limit_text() {
  char text[32];
  std::snprintf(text, sizeof text, "%g", kMaxViewVolumes);
  return text;
}

json none(const std::string& reason) { return {{"coverage", "none"}, {"reason", reason}, {"bodies", json::array()}}; }

}  // namespace

void add_run_volumes(const ccd::Scene& scene, const ccd::Trajectories& traj, json& runs) {
  const std::size_t n = traj.size();
  const ccd::RigidMotion motion(scene, traj);
  // Each run's method, or why it has no volumes.
  std::vector<std::optional<MethodSpec>> methods(runs.size());
  for (std::size_t r = 0; r < runs.size(); ++r) {
    json& run = runs[r];
    if (traj.periodic()) {
      run["volumes"] = none("a scene that wraps around: its bounds are built on images of the bodies");
      continue;
    }
    try {
      methods[r] = parse_method(run.value("method", std::string()));
    } catch (const std::exception& e) {  // std::invalid_argument, or a record's method not a string
      run["volumes"] = none(std::string("unknown method: ") + e.what());
    }
  }
  // Every window of every run, when the page can hold them all.
  std::vector<std::unique_ptr<RunVolumes>> plans(runs.size());
  double total = 0.0;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    if (!methods[r]) continue;
    plans[r] = std::make_unique<RunVolumes>(scene, traj, motion, *methods[r],
                                            runs[r].value("dt", 0.0), runs[r].value("acceleration_bound", 0.0));
    const double per = static_cast<double>(plans[r]->per_window());
    for (std::size_t i = 0; i < n && total <= kMaxViewVolumes && per > 0.0; ++i) {
      const std::size_t windows = plans[r]->windows(i, kMaxViewVolumes / per + 1.0).size();
      total = windows == 0 ? kInfinity : total + per * static_cast<double>(windows);  // none: over the limit
    }
    if (total > kMaxViewVolumes) break;
  }
  const bool all = total <= kMaxViewVolumes;
  double left = kMaxViewVolumes;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    if (!plans[r]) continue;
    json& run = runs[r];
    RunVolumes& plan = *plans[r];
    json bodies = json::array();
    for (std::size_t i = 0; i < n; ++i) bodies.push_back(json::array());
    if (all) {
      if (plan.scheduled()) {
        for (std::size_t i = 0; i < n; ++i)
          for (const ccd::Window& w : plan.windows(i, kMaxViewVolumes + 1.0)) plan.append(i, w, bodies[i]);
      } else if (n > 0) {  // the same steps for every body: one sample of an instant bound each
        for (const ccd::Window& w : plan.windows(0, kMaxViewVolumes + 1.0))
          for (std::size_t i = 0; i < n; ++i) plan.append(i, w, bodies[i]);
      }
      run["volumes"] = {{"coverage", "all"}, {"bodies", std::move(bodies)}};
      continue;
    }
    // Only the windows of the missed contacts' bodies that hold each contact's middle.
    std::map<std::pair<std::size_t, double>, bool> done;
    bool partial = false;
    const double per = static_cast<double>(plan.per_window());
    if (auto m = run.find("missed_events"); m != run.end())
      for (const json& e : *m) {
        const double t = 0.5 * (e["enter"].get<double>() + e["exit"].get<double>());
        for (const char* k : {"a", "b"}) {
          const std::size_t i = e[k].get<std::size_t>();
          const std::optional<ccd::Window> w = plan.window_at(i, t);
          if (!w || done[{i, w->t0}]) continue;
          if (left < per) {
            partial = true;
            continue;
          }
          done[{i, w->t0}] = true;
          left -= per;
          plan.append(i, *w, bodies[i]);
        }
      }
    for (json& list : bodies)  // in time order
      std::sort(list.begin(), list.end(), [](const json& x, const json& y) { return x[0].get<double>() < y[0].get<double>(); });
    run["volumes"] = {{"coverage", "missed"},
                      {"reason", "the bounds of every step would exceed " + limit_text() +
                                     " volumes: only at the missed contacts" +
                                     (partial ? " (not all of them: the same limit)" : "")},
                      {"bodies", std::move(bodies)}};
  }
}

}  // namespace ccdlab
