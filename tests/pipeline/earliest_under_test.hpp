#pragma once
// The earliest scheduler's tests call it as (motion, horizon, A, walls) -> contacts and read
// the last run's stats and static contacts: this wraps the Scheduler interface's run
// (pipeline/scheduler.hpp) into that form.
#include <pipeline/earliest_scheduler.hpp>

#include <memory>
#include <optional>
#include <vector>

namespace ccd::test {

class EarliestUnderTest {
 public:
  /// `rigid`: the scene's motion with its shapes and spin; null: every run's `motion` as
  /// plain spheres.
  explicit EarliestUnderTest(std::unique_ptr<EarliestScheduler> scheduler, const RigidMotion* rigid = nullptr)
      : scheduler_(std::move(scheduler)), rigid_(rigid) {}

  /// One run over [0, horizon] of `motion` (the centres of `rigid` when given); `contacts`
  /// gets the run's contacts; stage times are taken and added to `*times` when given.
  bool run(const Trajectories& motion, double horizon, double acceleration_bound, const std::optional<WallBox>& walls,
           std::vector<ScheduledContact>& contacts, StepTimes* times = nullptr) {
    ScheduleInput in;
    if (!rigid_) spheres_.assign_spheres(motion);
    in.motion = rigid_ ? rigid_ : &spheres_;
    in.horizon = horizon;
    in.acceleration_bound = acceleration_bound;
    in.walls = walls;
    in.timed = times != nullptr;
    const bool finished = scheduler_->run(in, last_);
    contacts = last_.contacts;
    if (times) {
      times->bound += last_.times.bound;
      times->broad += last_.times.broad;
      times->narrow += last_.times.narrow;
    }
    return finished;
  }
  void set_scenery(std::span<const StaticPolygon> polygons) { scheduler_->set_scenery(polygons); }
  const ScheduleStats& stats() const { return last_.stats; }
  const std::vector<ScheduledStaticContact>& static_contacts() const { return last_.static_contacts; }
  const Bound& bound() const { return scheduler_->bound(); }

 private:
  std::unique_ptr<EarliestScheduler> scheduler_;
  const RigidMotion* rigid_;
  RigidMotion spheres_;
  ScheduleResult last_;
};

}  // namespace ccd::test
