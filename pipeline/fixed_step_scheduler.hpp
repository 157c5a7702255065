#pragma once
// The `fixed` scheduler of pipeline/scheduler_registry.hpp: steps of dt over [0, T], one
// StepPipeline::run each (pipeline/step_pipeline.hpp). Step k starts at t_k = k dt (the
// product in double, never accumulated):
//  - a space-time bound checks [t_k, min(t_{k+1}, T)] for every k with t_k < T
//    (fixed_step_count), each contact reported over its step;
//  - an instant bound checks the samples t_k <= T (sample_count), each contact reported at
//    its sample (from == to == t_k).
// Every body's bound is built over every step; the stats add up the steps' stages
// (ScheduleStats: candidates and pair checks, passed pairs and narrow calls, the broad
// phase's own counters, its rebuilds) and `batches` counts the steps.
#include <pipeline/scheduler.hpp>
#include <pipeline/step_pipeline.hpp>

#include <cstdint>
#include <memory>

namespace ccd {

/// The samples k dt <= horizon, k >= 0 (0 for a dt that is not positive and finite).
std::uint64_t sample_count(double horizon, double dt);

/// The steps of a fixed-step run: samples for a discrete method, steps [k dt, (k+1) dt]
/// starting before the horizon for a continuous one.
std::uint64_t fixed_step_count(double horizon, double dt, bool continuous);

class FixedStepScheduler final : public Scheduler {
 public:
  /// `knowledge` is the bound's (Instant: samples; otherwise steps); dt > 0 and finite
  /// (std::invalid_argument).
  FixedStepScheduler(std::unique_ptr<Bound> bound, Knowledge knowledge, std::unique_ptr<BroadPhase> broad,
                     double dt, PipelineOptions options = {}, const NarrowTable& table = narrow_table());

  void set_scenery(std::span<const StaticPolygon> polygons) override;
  bool run(const ScheduleInput& in, ScheduleResult& out) override;

  const StepPipeline& pipeline() const { return pipeline_; }

 private:
  StepPipeline pipeline_;
  Knowledge knowledge_;
  double dt_;
  StepResult step_;
  std::vector<BodyState> states_;
  std::vector<ScheduledContact> step_contacts_;
  std::vector<ScheduledStaticContact> step_static_contacts_;
};

}  // namespace ccd
