#pragma once
// The certified bracket search behind the rigid ground truth (docs/truth.md, "Rigid
// bodies"), for any two convex shapes whose signed distance f(t) is Lipschitz in time with
// a known constant L and can be bracketed at any instant (ccd/queries/convex_distance.hpp):
// two moving rigid bodies (ccd/truth/rigid_truth.hpp) or a moving rigid body and a static
// polygon (ccd/truth/rigid_static_truth.hpp).
//
// The search labels [u0, u1]: at the midpoint m of a sub-interval, f(m) >= lower > 0
// certifies separation on (m - lower/L, m + lower/L), f(m) <= upper < 0 certifies overlap
// on (m - |upper|/L, m + |upper|/L); what is left is searched the same way, until pieces
// narrower than the time tolerance that neither side can claim, which stay unresolved. A
// separation certified only up to the distance `band` does not count as separated (a
// sliding touch stays one event). The probe's `slack` (a pose's evaluation error, metres)
// is taken off both bounds before they certify anything. An upper bound <= 0 that is not
// below 0 (a touch certified exactly, ccd/queries/sphere_box_distance.hpp) certifies
// contact at m alone (on all of the sub-interval when L is 0 there).
// With a local Lipschitz bound (set_local_lipschitz: a bound valid on the sub-interval
// searched, used when smaller than L), a sub-interval whose distance cannot move by more
// than the probe's own uncertainty (L_local x width <= half the bracket width plus the
// slack) is left unresolved at once: splitting it would certify nothing new.
// Events (a maximal run of pieces not certified separated):
//  - with a certified overlap inside: enter lies between the run's start and the first
//    certified overlap, exit between the last certified overlap and the run's end; each
//    is the middle of its bracket with its half-width as the error (0 at time 0 and at the
//    horizon when the overlap is certified there);
//  - with none: `grazing` and `undecided` (the event may or may not exist), enter = exit
//    = the run's middle, errors its half-width.
// A certified separation narrower than the time tolerance between two such runs does not
// split them.
#include <ccd/queries/convex_distance.hpp>
#include <ccd/truth/truth_io.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace ccd {

/// One distance evaluation: the certified distance of the posed shapes at a time, and a
/// bound on how far the evaluated poses may be from the exact ones (metres, >= 0).
struct BracketProbe {
  ConvexDistance distance;
  double slack = 0.0;
};

/// One event of a search: times in seconds and their certified errors.
struct BracketEvent {
  double enter = 0.0;
  double exit = 0.0;
  EventError error;
};

class BracketSearch {
 public:
  /// probe(t, options): the distance at t, resolved to options.tolerance.
  using Probe = std::function<BracketProbe(double, const DistanceOptions&)>;
  /// lipschitz(lo, hi): m/s, a bound on |f'| over [lo, hi].
  using LocalLipschitz = std::function<double(double, double)>;

  /// lipschitz: m/s, the bound on |f'|; time_tolerance: seconds (> 0); band: metres;
  /// max_evaluations: past it the rest of the interval is left unresolved.
  BracketSearch(Probe probe, double lipschitz, double time_tolerance, double band, std::size_t max_evaluations);

  /// Uses min(L, local(lo, hi)) on each sub-interval [lo, hi] searched (see the header).
  void set_local_lipschitz(LocalLipschitz local) { local_ = std::move(local); }
  /// Labels [lo, hi] (closed; may be called again for a later interval).
  void run(double lo, double hi);
  std::size_t evaluations() const { return evaluations_; }
  /// Appends the events of what was searched (see the header comment); `horizon` is the
  /// scene's (an overlap certified there gives an exact exit).
  void events(double horizon, std::vector<BracketEvent>& out);

 private:
  enum class Label : std::uint8_t { Separated, Near, Overlapping, Unresolved };
  struct LabelledPiece {
    double lo, hi;
    Label label;
  };
  void push(double lo, double hi, Label l);
  void search(double lo, double hi);

  Probe probe_;
  LocalLipschitz local_;
  double L_, tol_;
  std::size_t max_;
  double band_;
  std::size_t evaluations_ = 0;
  std::vector<LabelledPiece> pieces_;
};

}  // namespace ccd
