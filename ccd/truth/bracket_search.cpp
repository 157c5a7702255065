#include <ccd/truth/bracket_search.hpp>

#include <algorithm>
#include <limits>
#include <utility>

namespace ccd {

BracketSearch::BracketSearch(Probe probe, double lipschitz, double time_tolerance, double band,
                             std::size_t max_evaluations)
    : probe_(std::move(probe)), L_(lipschitz), tol_(time_tolerance), max_(max_evaluations), band_(band) {}

void BracketSearch::run(double lo, double hi) { search(lo, hi); }

void BracketSearch::push(double lo, double hi, Label l) {
  if (!pieces_.empty() && pieces_.back().label == l && pieces_.back().hi >= lo)
    pieces_.back().hi = std::max(pieces_.back().hi, hi);
  else
    pieces_.push_back({lo, hi, l});
}

void BracketSearch::search(double lo, double hi) {
  if (evaluations_ >= max_) {
    push(lo, hi, Label::Unresolved);
    return;
  }
  const double mid = lo + 0.5 * (hi - lo);
  if (!(mid > lo && mid < hi)) {  // an interval of an ulp or two: nothing left to split
    push(lo, hi, Label::Unresolved);
    return;
  }
  ++evaluations_;
  const double L = local_ ? std::min(L_, local_(lo, hi)) : L_;
  DistanceOptions o;
  // Resolve the distance to a fraction of what the time tolerance moves the shapes.
  o.tolerance = std::max(0.25 * L * tol_, 1e-15);
  const BracketProbe p = probe_(mid, o);
  const ConvexDistance& d = p.distance;
  const double inf = std::numeric_limits<double>::infinity();
  // The exact poses' distance is within `slack` of the evaluated one.
  const double slack = p.slack;
  Label sure = Label::Unresolved;
  double reach = 0.0;
  if (d.status == ConvexDistance::Status::Separated && (slack == 0.0 || d.lower - slack > 0.0)) {
    sure = d.lower - slack > band_ ? Label::Separated : Label::Near;
    reach = L > 0.0 ? (d.lower - slack) / L : inf;
  } else if (d.status == ConvexDistance::Status::Overlapping && (slack == 0.0 || d.upper + slack < 0.0)) {
    sure = Label::Overlapping;
    reach = L > 0.0 ? -(d.upper + slack) / L : inf;
  } else if (d.status == ConvexDistance::Status::Uncertain && d.upper + slack <= 0.0) {
    sure = Label::Overlapping;  // touching, certified: contact at mid (throughout when L is 0)
    reach = L > 0.0 ? 0.0 : inf;
  }
  if (sure == Label::Unresolved) {
    if (hi - lo <= tol_ || (local_ && L * (hi - lo) <= 0.5 * (d.upper - d.lower) + slack)) {
      push(lo, hi, Label::Unresolved);
      return;
    }
    search(lo, mid);
    search(mid, hi);
    return;
  }
  // Certified on the open interval (mid - reach, mid + reach); its ends belong to the
  // neighbouring closed sub-searches.
  const double x0 = mid - reach, x1 = mid + reach;
  if (x0 > lo) search(lo, x0);
  push(std::max(lo, x0), std::min(hi, x1), sure);
  if (x1 < hi) search(x1, hi);
}

void BracketSearch::events(double horizon, std::vector<BracketEvent>& out) {
  auto& ps = pieces_;
  const double tol = tol_;
  // A certified gap narrower than the time tolerance between two uncertified runs does not
  // split an event (the search resolves crossings to about an ulp, leaving slivers).
  for (std::size_t i = 1; i + 1 < ps.size(); ++i)
    if (ps[i].label == Label::Separated && ps[i].hi - ps[i].lo <= tol && ps[i - 1].label != Label::Separated &&
        ps[i + 1].label != Label::Separated)
      ps[i].label = Label::Unresolved;
  for (std::size_t i = 0; i < ps.size();) {
    if (ps[i].label == Label::Separated) {
      ++i;
      continue;
    }
    std::size_t k = i;
    const LabelledPiece* first_o = nullptr;
    const LabelledPiece* last_o = nullptr;
    for (; k < ps.size() && ps[k].label != Label::Separated; ++k)
      if (ps[k].label == Label::Overlapping) {
        if (!first_o) first_o = &ps[k];
        last_o = &ps[k];
      }
    const double r0 = ps[i].lo, r1 = ps[k - 1].hi;
    BracketEvent ev;
    EventError& err = ev.error;
    if (first_o) {
      // enter in [r0, first_o->lo]; exit in [last_o->hi, r1].
      if (ps[i].label == Label::Overlapping && r0 == 0.0) {
        ev.enter = 0.0;
      } else {
        ev.enter = r0 + 0.5 * (first_o->lo - r0);
        err.enter_error = std::max(ev.enter - r0, first_o->lo - ev.enter);
      }
      if (ps[k - 1].label == Label::Overlapping && r1 == horizon) {
        ev.exit = horizon;
      } else {
        ev.exit = last_o->hi + 0.5 * (r1 - last_o->hi);
        err.exit_error = std::max(ev.exit - last_o->hi, r1 - ev.exit);
      }
    } else {
      ev.enter = ev.exit = r0 + 0.5 * (r1 - r0);
      err.enter_error = err.exit_error = std::max(ev.enter - r0, r1 - ev.enter);
      err.grazing = true;
      err.undecided = true;
    }
    out.push_back(ev);
    i = k;
  }
}

}  // namespace ccd
