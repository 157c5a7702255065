#pragma once
// The ground truth's solvers behind one table keyed by shape kinds, built like the
// narrow-phase table (ccd/narrow/narrow_table.hpp): an entry answers one candidate
// (ccd/truth/truth_candidates.hpp), a pair of bodies or a body and a static polygon over
// a run of time windows [u0, u1], and appends its events with their errors.
//
// The default table (truth_table):
//   sphere x sphere    -> exact (pair_contact_intervals, ccd/truth/pair_contact.hpp; errors 0)
//   every other pair   -> certified brackets (pair_bracket_events, ccd/truth/rigid_truth.hpp;
//                         the periodic search when the box wraps around)
//   sphere x polygon   -> exact (body_polygon_intervals, ccd/truth/static_truth.hpp)
//   other x polygon    -> certified brackets (body_polygon_bracket_events,
//                         ccd/truth/rigid_static_truth.hpp)
// bracket_truth_table() binds every entry to the brackets (the cross-path tests: on
// spheres the generic search must hold the exact events inside its brackets).
//
// Adding (A, B) registers (B, A) too: every solver here is symmetric in its two bodies
// (the events are written with a < b as given). A missing entry is a programming error
// (find throws std::logic_error naming the kinds).
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/scene/scenery.hpp>
#include <ccd/shape/shape_kind.hpp>
#include <ccd/truth/ground_truth.hpp>
#include <ccd/truth/static_truth.hpp>
#include <ccd/truth/truth_io.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace ccd {

/// What an entry may use.
struct TruthQuery {
  const RigidMotion& motion;
  std::span<const StaticPolygon> scenery;
  double time_tolerance = 0.0;      ///< seconds (> 0), for the bracket search
  std::size_t max_evaluations = 0;  ///< per call, for the bracket search
};

/// Where entries append: events with one error entry each (zero for exact solvers).
struct TruthEvents {
  std::vector<ContactEvent> events;
  std::vector<EventError> errors;
  std::vector<StaticEvent> static_events;
  std::vector<EventError> static_errors;
  std::size_t evaluations = 0;  ///< distance evaluations of the bracket search
};

/// Bodies a < b over [u0, u1].
using PairTruthFn = void (*)(const TruthQuery& q, std::uint32_t a, std::uint32_t b, double u0, double u1,
                             TruthEvents& out);
/// Body `body` against scenery[polygon] over [u0, u1].
using PolygonTruthFn = void (*)(const TruthQuery& q, std::uint32_t body, std::uint32_t polygon, double u0, double u1,
                                TruthEvents& out);

class TruthTable {
 public:
  /// Registers fn for (ka, kb) and (kb, ka); replaces an existing entry (an exact override).
  void add(ShapeKind ka, ShapeKind kb, PairTruthFn fn);
  /// Registers fn for a body of kind k against a static polygon (the polygon column).
  void add_polygon(ShapeKind k, PolygonTruthFn fn);
  /// The entries; throw std::logic_error when there is none.
  PairTruthFn find(ShapeKind ka, ShapeKind kb) const;
  PolygonTruthFn find_polygon(ShapeKind k) const;

 private:
  std::array<PairTruthFn, kShapeKinds * kShapeKinds> pairs_{};
  std::array<PolygonTruthFn, kShapeKinds> polygons_{};
};

/// The exact solvers for spheres, certified brackets for the rest (see the header).
const TruthTable& truth_table();
/// Certified brackets for every entry, spheres included.
const TruthTable& bracket_truth_table();

/// The entries themselves, for tables of one's own.
void exact_sphere_pair_truth(const TruthQuery& q, std::uint32_t a, std::uint32_t b, double u0, double u1,
                             TruthEvents& out);
void bracket_pair_truth(const TruthQuery& q, std::uint32_t a, std::uint32_t b, double u0, double u1,
                        TruthEvents& out);
void exact_sphere_polygon_truth(const TruthQuery& q, std::uint32_t body, std::uint32_t polygon, double u0, double u1,
                                TruthEvents& out);
void bracket_polygon_truth(const TruthQuery& q, std::uint32_t body, std::uint32_t polygon, double u0, double u1,
                           TruthEvents& out);

}  // namespace ccd
