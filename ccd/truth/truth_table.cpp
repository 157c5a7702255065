#include <ccd/truth/truth_table.hpp>

#include <ccd/truth/pair_contact.hpp>
#include <ccd/truth/rigid_static_truth.hpp>
#include <ccd/truth/rigid_truth.hpp>

#include <stdexcept>
#include <string>

namespace ccd {

void TruthTable::add(ShapeKind ka, ShapeKind kb, PairTruthFn fn) {
  const auto ia = static_cast<std::size_t>(ka), ib = static_cast<std::size_t>(kb);
  pairs_[ia * kShapeKinds + ib] = fn;
  pairs_[ib * kShapeKinds + ia] = fn;
}

void TruthTable::add_polygon(ShapeKind k, PolygonTruthFn fn) { polygons_[static_cast<std::size_t>(k)] = fn; }

PairTruthFn TruthTable::find(ShapeKind ka, ShapeKind kb) const {
  const PairTruthFn fn = pairs_[static_cast<std::size_t>(ka) * kShapeKinds + static_cast<std::size_t>(kb)];
  if (!fn) throw std::logic_error("no truth solver for " + std::string(to_string(ka)) + " x " + std::string(to_string(kb)));
  return fn;
}

PolygonTruthFn TruthTable::find_polygon(ShapeKind k) const {
  const PolygonTruthFn fn = polygons_[static_cast<std::size_t>(k)];
  if (!fn) throw std::logic_error("no truth solver for " + std::string(to_string(k)) + " x polygon");
  return fn;
}

void exact_sphere_pair_truth(const TruthQuery& q, std::uint32_t a, std::uint32_t b, double u0, double u1,
                             TruthEvents& out) {
  std::vector<ContactInterval> iv;
  pair_contact_intervals(q.motion.centres(), a, b, u0, u1, iv);
  for (const ContactInterval& x : iv) {
    out.events.push_back({a, b, x.enter, x.exit});
    out.errors.push_back({});
  }
}

void bracket_pair_truth(const TruthQuery& q, std::uint32_t a, std::uint32_t b, double u0, double u1,
                        TruthEvents& out) {
  out.evaluations += q.motion.centres().periodic()
                         ? periodic_pair_bracket_events(q.motion, a, b, u0, u1, q.time_tolerance, q.max_evaluations,
                                                        out.events, out.errors)
                         : pair_bracket_events(q.motion, a, b, u0, u1, q.time_tolerance, q.max_evaluations,
                                               out.events, out.errors);
}

void exact_sphere_polygon_truth(const TruthQuery& q, std::uint32_t body, std::uint32_t polygon, double u0, double u1,
                                TruthEvents& out) {
  std::vector<ContactInterval> iv;
  body_polygon_intervals(q.motion.centres(), body, q.scenery[polygon], u0, u1, iv);
  for (const ContactInterval& x : iv) {
    out.static_events.push_back({body, polygon, x.enter, x.exit});
    out.static_errors.push_back({});
  }
}

void bracket_polygon_truth(const TruthQuery& q, std::uint32_t body, std::uint32_t polygon, double u0, double u1,
                           TruthEvents& out) {
  out.evaluations += body_polygon_bracket_events(q.motion, body, q.scenery[polygon], polygon, u0, u1,
                                                 q.time_tolerance, q.max_evaluations, out.static_events,
                                                 out.static_errors);
}

namespace {

TruthTable brackets_everywhere() {
  TruthTable t;
  for (std::size_t i = 0; i < kShapeKinds; ++i) {
    for (std::size_t k = i; k < kShapeKinds; ++k)
      t.add(static_cast<ShapeKind>(i), static_cast<ShapeKind>(k), &bracket_pair_truth);
    t.add_polygon(static_cast<ShapeKind>(i), &bracket_polygon_truth);
  }
  return t;
}

}  // namespace

const TruthTable& truth_table() {
  static const TruthTable table = [] {
    TruthTable t = brackets_everywhere();
    t.add(ShapeKind::Sphere, ShapeKind::Sphere, &exact_sphere_pair_truth);
    t.add_polygon(ShapeKind::Sphere, &exact_sphere_polygon_truth);
    return t;
  }();
  return table;
}

const TruthTable& bracket_truth_table() {
  static const TruthTable table = brackets_everywhere();
  return table;
}

}  // namespace ccd
