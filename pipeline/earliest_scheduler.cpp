#include <pipeline/earliest_scheduler.hpp>

#include <pipeline/earliest_run.hpp>

#include <cmath>
#include <stdexcept>

namespace ccd {

EarliestScheduler::EarliestScheduler(std::unique_ptr<Bound> bound, std::unique_ptr<Bound> scratch,
                                     Knowledge knowledge, std::unique_ptr<BroadPhase> broad,
                                     ScheduleOptions options, const NarrowTable& table)
    : bound_(std::move(bound)),
      scratch_(std::move(scratch)),
      knowledge_(knowledge),
      broad_(std::move(broad)),
      options_(options),
      narrow_(table.find(ShapeKind::Sphere, ShapeKind::Sphere)),
      table_(&table) {
  if (knowledge == Knowledge::Instant)
    throw std::invalid_argument("the earliest scheduler needs a space-time bound (an instant bound has no window)");
  if (!bound_ || !scratch_) throw std::invalid_argument("the earliest scheduler needs two bound instances");
  if (!(options.window > 0.0)) throw std::invalid_argument("the earliest scheduler needs a window dt > 0");
  if (!(options.stale > 0.0 && options.stale <= 1.0))
    throw std::invalid_argument("the earliest scheduler needs stale in (0, 1]");
  if (!(options.reach >= 0.0 && std::isfinite(options.reach)))
    throw std::invalid_argument("the earliest scheduler needs a finite reach >= 0");
  if (!(options.chunk >= 0.0 && std::isfinite(options.chunk)))
    throw std::invalid_argument("the earliest scheduler needs a finite chunk >= 0");
}

void EarliestScheduler::set_scenery(std::span<const StaticPolygon> polygons) {
  if (polygons.size() >= earliest::kStaticBit) throw std::invalid_argument("the earliest scheduler takes fewer than 2^31 polygons");
  scenery_ = polygons;
  static_index_ = StaticIndex::from_polygons(polygons);
}

bool EarliestScheduler::run(const ScheduleInput& in, ScheduleResult& out) {
  out = {};
  const earliest::Setup setup{*bound_, *scratch_, knowledge_, *broad_, options_, narrow_, *table_, scenery_,
                              static_index_};
  out.finished = earliest::EarliestRun(setup, in, out).run();
  if (in.sink) {
    in.sink->found(out.contacts, out.static_contacts);
    out.contacts.clear();
    out.static_contacts.clear();
  }
  return out.finished;
}

}  // namespace ccd
