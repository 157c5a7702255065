// FCL 0.7's continuous collision side by side with ccdlab's conservative advancement on
// spinning rigid bodies (docs/peers.md, "Spinning bodies: FCL's continuous collision").
//
// The horizon is cut into `steps` equal steps. For every step and every pair of bodies
// whose enclosing spheres' swept boxes overlap in it (pairs of two spheres excepted: no
// rotation matters there), each method answers "first contact in [t0, t1]?":
//  - fcl_default:      fcl::continuousCollide(geometry, tf at t0, tf at t1, ...) with a
//                      default ContinuousCollisionRequestd: naive solver, translation-only
//                      motion (the start orientation is kept), 10 samples;
//  - fcl_naive_interp: naive solver, 10 samples of fcl::InterpMotion;
//  - fcl_ca:           FCL's conservative advancement (libccd GJK) on fcl::InterpMotion;
//  - ccdlab_ca:        ccdlab's narrow table (conservative advancement on the certified
//                      GJK distance), the entry the step pipeline calls.
// fcl::InterpMotion turns the body about a fixed world axis at a constant rate about its
// reference point while that point moves on a straight line at constant speed: with the
// reference point at the body's origin (its centre of rotation) this is ccdlab's motion
// (constant world-frame angular velocity, q(t) = exp((t - t0) omega / 2) q0) as long as the
// centre moves in a straight line at constant speed over the step and the step's turn is
// below pi (InterpMotion takes the shortest rotation between the two orientations).
// Pair-steps where that does not hold (a wall reflection, an acceleration or a spin change
// inside the step, a turn >= pi) are skipped and counted. The motion is built with the
// constructor that takes the reference point: the two-transform one leaves it unset in
// FCL 0.7. fcl::ScrewMotion is not used: a screw moves the centre along a helix unless the
// velocity is parallel to the spin axis.
//
// Truth per pair-step, from the certified rigid truth (`ccdlab truth`, read with --truth,
// or computed by the same function when --truth is absent): contact when an event that is
// not grazing has a certified overlap in the step ([enter + enter_error, exit - exit_error]
// meets [t0, t1]), none when no event's outer bracket [enter - enter_error, exit +
// exit_error] meets it, ambiguous otherwise (not counted). A miss: truth says contact, the
// method none. A false alarm: the converse. Late: a found contact reported after the
// first time in the step at which the overlap is certified.
//
// Time per query: the thread's CPU time for all the queries of one method, median of
// --repeats passes, divided by the query count. FCL gets its transforms at t0 and t1 made
// beforehand (as a caller of continuousCollide has them); ccdlab evaluates its own poses
// inside the query.
//
//   rigid_peers --scene SCENE.json [--truth TRUTH.json] [--steps=30] [--repeats=5]
// Exit 2 with one line on bad input; exit 1 when ccdlab_ca misses a contact.
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/narrow/narrow_table.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_digest.hpp>
#include <ccd/scene/scene_io.hpp>
#include <ccd/truth/truth.hpp>
#include <ccd/truth/truth_io.hpp>
#include <ccd/util/thread_cpu_time.hpp>

#include <CLI/CLI.hpp>

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/math/motion/interp_motion.h>
#include <fcl/narrowphase/continuous_collision.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

namespace {

struct Args {
  std::string scene;
  std::string truth;
  int steps = 30;
  int repeats = 5;
};

// One line on stderr and exit 2 (bad arguments or input).
[[noreturn]] void usage_error(const std::string& what) {
  std::cerr << "rigid_peers: " << what << " (rigid_peers --help lists the options)\n";
  std::exit(2);
}

Args parse(int argc, char** argv) {
  Args a;
  CLI::App app("FCL's continuous collision against ccdlab's conservative advancement on spinning bodies,\n"
               "misses counted against the certified truth.",
               "rigid_peers");
  app.add_option("--scene", a.scene, "the scene (ccdlab-scene JSON with shapes and spin)")->required();
  app.add_option("--truth", a.truth, "its truth from `ccdlab truth` (computed here when not given)");
  app.add_option("--steps", a.steps, "steps the horizon is cut into")->check(CLI::Range(1, 1000000));
  app.add_option("--repeats", a.repeats, "timed passes per method (the median is kept)")
      ->check(CLI::Range(1, 1000000));
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    std::exit(0);
  } catch (const CLI::ParseError& e) {
    usage_error(e.what());
  }
  return a;
}

// A query: one pair over one step, with what the truth says.
enum class Truth : std::uint8_t { Contact, None, Ambiguous };
struct Query {
  std::uint32_t a = 0, b = 0;
  double t0 = 0.0, t1 = 0.0;
  Truth truth = Truth::None;
  double first_certain = 0.0;  ///< Contact: the first time in the step with a certified overlap
  fcl::Transform3d a0, a1, b0, b1;  ///< FCL's poses at t0 and t1 (made before the timing)
};

struct Answer {
  bool found = false;
  double toi = 0.0;
};

struct Tally {
  std::size_t contact = 0, misses = 0, false_alarms = 0, late = 0;
  double us_per_query = 0.0;
};

// FCL's view of a body: its geometry in FCL's conventions and the fixed rotation from
// FCL's shape frame to ccdlab's body frame (FCL's capsule lies along z, ccdlab's along x).
struct FclBody {
  std::shared_ptr<fcl::CollisionGeometryd> geometry;
  fcl::Matrix3d to_body = fcl::Matrix3d::Identity();
};

FclBody fcl_body(const ccd::Scene& scene, std::size_t i) {
  FclBody f;
  const std::int32_t s = scene.rigid.empty() ? ccd::kNoShape : scene.rigid[i].shape;
  if (s == ccd::kNoShape) {
    f.geometry = std::make_shared<fcl::Sphered>(scene.bodies[i].radius);
    return f;
  }
  const ccd::Shape& shape = scene.shapes[static_cast<std::size_t>(s)];
  switch (shape.kind) {
    case ccd::ShapeKind::Sphere: f.geometry = std::make_shared<fcl::Sphered>(shape.radius); break;
    case ccd::ShapeKind::Capsule:
      f.geometry = std::make_shared<fcl::Capsuled>(shape.radius, 2.0 * shape.half_length);
      f.to_body << 0, 0, 1, 0, 1, 0, -1, 0, 0;  // FCL's z axis onto ccdlab's x axis
      break;
    case ccd::ShapeKind::Box:
      f.geometry = std::make_shared<fcl::Boxd>(2.0 * shape.half_extents.x(), 2.0 * shape.half_extents.y(),
                                               2.0 * shape.half_extents.z());
      break;
    case ccd::ShapeKind::Hull: break;  // not compared (FCL's Convex needs faces)
  }
  return f;
}

fcl::Transform3d fcl_pose(const ccd::RigidMotion& m, const FclBody& f, std::size_t i, double t) {
  const ccd::Pose p = m.pose(i, t);
  fcl::Transform3d tf = fcl::Transform3d::Identity();
  tf.linear() = p.rotation * f.to_body;
  tf.translation() = p.centre;
  return tf;
}

// Whether body i's motion over [t0, t1] is InterpMotion's: one trajectory piece without
// acceleration, one spin piece, a turn below pi.
bool interp_exact(const ccd::RigidMotion& m, std::size_t i, double t0, double t1) {
  const ccd::Piece& q = m.centres().piece_at(i, t0);
  if (q.t1 < t1 || !q.a.isZero(0.0)) return false;
  if (m.rotations().empty()) return true;
  const ccd::RotationPiece& r = m.rotations().piece_at(i, t0);
  return r.t1 >= t1 && r.omega.norm() * (t1 - t0) < 0.99 * std::numbers::pi;
}

// The certified truth: from `ccdlab truth` (--truth, checked against the scene's digest), or
// the same computation here. errors has one entry per event.
struct CertifiedTruth {
  std::vector<ccd::ContactEvent> events;
  std::vector<ccd::EventError> errors;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> by_pair;  ///< event indices
};

CertifiedTruth certified_truth(const Args& args, const ccd::Scene& scene, const ccd::RigidMotion& motion) {
  CertifiedTruth out;
  ccd::Truth t;
  if (!args.truth.empty()) {
    t = ccd::load_truth(args.truth);
    if (t.scene_sha256 != ccd::scene_digest(scene))
      throw ccd::InputError(args.truth, "scene_sha256", "is not the digest of " + args.scene);
  } else {
    t = ccd::compute_truth(motion, {});
  }
  out.events = std::move(t.events);
  out.errors = t.errors.empty() ? std::vector<ccd::EventError>(out.events.size()) : std::move(t.errors);
  for (std::size_t e = 0; e < out.events.size(); ++e)
    out.by_pair[{out.events[e].a, out.events[e].b}].push_back(e);
  return out;
}

// What the truth says of pair (a, b) over [t0, t1]: a certified contact (and the first
// certain time of it), none, or ambiguous (an event's error bracket meets the step).
void classify(const CertifiedTruth& truth, Query& q) {
  bool contact = false, near = false;
  double first = q.t1;
  if (const auto it = truth.by_pair.find({q.a, q.b}); it != truth.by_pair.end())
    for (const std::size_t e : it->second) {
      const ccd::ContactEvent& ev = truth.events[e];
      const ccd::EventError& er = truth.errors[e];
      const double lo = ev.enter + er.enter_error, hi = ev.exit - er.exit_error;
      if (!er.grazing && lo <= hi && std::max(lo, q.t0) <= std::min(hi, q.t1)) {
        contact = true;
        first = std::min(first, std::max(lo, q.t0));
      } else if (std::max(ev.enter - er.enter_error, q.t0) <= std::min(ev.exit + er.exit_error, q.t1)) {
        near = true;
      }
    }
  q.truth = contact ? Truth::Contact : near ? Truth::Ambiguous : Truth::None;
  q.first_certain = first;
}

struct Queries {
  std::vector<Query> list;
  std::size_t skipped_motion = 0, skipped_hull = 0, ambiguous = 0, contacts = 0;
};

// Every pair of bodies (not both spheres) whose swept boxes overlap in a step, with FCL's
// poses; pairs FCL cannot take (hulls, motion InterpMotion cannot follow) and pairs the
// truth leaves ambiguous are counted and left out.
Queries make_queries(const ccd::Scene& scene, const ccd::Trajectories& traj, const ccd::RigidMotion& motion,
                     const std::vector<FclBody>& fcl_bodies, const CertifiedTruth& truth, int steps) {
  Queries out;
  const std::size_t n = scene.bodies.size();
  const double dt = scene.horizon / steps;
  std::vector<ccd::Aabb> boxes(n);
  for (int k = 0; k < steps; ++k) {
    const double t0 = k * dt, t1 = k + 1 == steps ? scene.horizon : (k + 1) * dt;
    for (std::size_t i = 0; i < n; ++i) boxes[i] = traj.swept_bounds(i, t0, t1);
    for (std::uint32_t a = 0; a < n; ++a)
      for (std::uint32_t b = a + 1; b < n; ++b) {
        if (!boxes[a].overlaps(boxes[b])) continue;
        if (motion.kind(a) == ccd::ShapeKind::Sphere && motion.kind(b) == ccd::ShapeKind::Sphere) continue;
        if (!fcl_bodies[a].geometry || !fcl_bodies[b].geometry) {
          ++out.skipped_hull;
          continue;
        }
        if (!interp_exact(motion, a, t0, t1) || !interp_exact(motion, b, t0, t1)) {
          ++out.skipped_motion;
          continue;
        }
        Query q;
        q.a = a;
        q.b = b;
        q.t0 = t0;
        q.t1 = t1;
        classify(truth, q);
        if (q.truth == Truth::Ambiguous) {
          ++out.ambiguous;
          continue;
        }
        out.contacts += q.truth == Truth::Contact;
        q.a0 = fcl_pose(motion, fcl_bodies[a], a, t0);
        q.a1 = fcl_pose(motion, fcl_bodies[a], a, t1);
        q.b0 = fcl_pose(motion, fcl_bodies[b], b, t0);
        q.b1 = fcl_pose(motion, fcl_bodies[b], b, t1);
        out.list.push_back(q);
      }
  }
  return out;
}

struct Method {
  const char* name;
  std::function<Answer(const Query&)> run;
};

// FCL's continuous collision three ways, and ccdlab's narrow table entry of the pair.
std::vector<Method> methods(const std::vector<FclBody>& fcl_bodies, const ccd::RigidMotion& motion) {
  fcl::ContinuousCollisionRequestd naive_interp;
  naive_interp.ccd_motion_type = fcl::CCDM_LINEAR;
  fcl::ContinuousCollisionRequestd fcl_ca;
  fcl_ca.ccd_motion_type = fcl::CCDM_LINEAR;
  fcl_ca.ccd_solver_type = fcl::CCDC_CONSERVATIVE_ADVANCEMENT;
  auto run_fcl = [&fcl_bodies](const fcl::ContinuousCollisionRequestd& request, bool interp) {
    return [&fcl_bodies, request, interp](const Query& q) {
      const FclBody &fa = fcl_bodies[q.a], &fb = fcl_bodies[q.b];
      const fcl::Transform3d &a0 = q.a0, &a1 = q.a1, &b0 = q.b0, &b1 = q.b1;
      fcl::ContinuousCollisionResultd result;
      if (interp) {
        const fcl::Vector3d origin = fcl::Vector3d::Zero();
        const fcl::InterpMotion<double> ma(a0.linear(), a0.translation(), a1.linear(), a1.translation(),
                                           origin);
        const fcl::InterpMotion<double> mb(b0.linear(), b0.translation(), b1.linear(), b1.translation(),
                                           origin);
        fcl::continuousCollide(fa.geometry.get(), &ma, fb.geometry.get(), &mb, request, result);
      } else {
        fcl::continuousCollide(fa.geometry.get(), a0, a1, fb.geometry.get(), b0, b1, request, result);
      }
      return Answer{result.is_collide, q.t0 + result.time_of_contact * (q.t1 - q.t0)};
    };
  };
  auto run_ccdlab = [&motion](const Query& q) {
    ccd::NarrowInput in;
    in.motion = &motion;
    in.t0 = q.t0;
    in.t1 = q.t1;
    const ccd::ContactResult r = ccd::narrow_table().find(motion.kind(q.a), motion.kind(q.b))(in, q.a, q.b);
    return Answer{r.found(), r.toi};
  };
  return {{"fcl_default", run_fcl(fcl::ContinuousCollisionRequestd{}, false)},
          {"fcl_naive_interp", run_fcl(naive_interp, true)},
          {"fcl_ca", run_fcl(fcl_ca, true)},
          {"ccdlab_ca", run_ccdlab}};
}

// One method over every query, timed over `repeats` passes (median), answers counted
// against the truth.
Tally tally(const Method& m, const std::vector<Query>& queries, int repeats) {
  std::vector<Answer> answers(queries.size());
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r) {
    const double c0 = ccd::thread_cpu_seconds();
    for (std::size_t i = 0; i < queries.size(); ++i) answers[i] = m.run(queries[i]);
    times.push_back(ccd::thread_cpu_seconds() - c0);
  }
  std::nth_element(times.begin(), times.begin() + static_cast<std::ptrdiff_t>(times.size() / 2), times.end());
  Tally t;
  t.us_per_query =
      queries.empty() ? 0.0 : 1e6 * times[times.size() / 2] / static_cast<double>(queries.size());
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const Query& q = queries[i];
    if (q.truth == Truth::Contact) {
      ++t.contact;
      if (!answers[i].found)
        ++t.misses;
      else if (answers[i].toi > q.first_certain + 1e-12 * (q.t1 - q.t0))
        ++t.late;
    } else if (answers[i].found) {
      ++t.false_alarms;
    }
  }
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse(argc, argv);
  try {
    const ccd::Scene scene = ccd::load_scene(args.scene);
    const ccd::Trajectories traj(scene);
    const ccd::RigidMotion motion(scene, traj);
    const std::size_t n = scene.bodies.size();
    const CertifiedTruth truth = certified_truth(args, scene, motion);
    std::vector<FclBody> fcl_bodies;
    for (std::size_t i = 0; i < n; ++i) fcl_bodies.push_back(fcl_body(scene, i));
    const Queries queries = make_queries(scene, traj, motion, fcl_bodies, truth, args.steps);

    std::printf("scene %s: %zu bodies, horizon %g s, %d steps of %g s\n", args.scene.c_str(), n,
                scene.horizon, args.steps, scene.horizon / args.steps);
    std::printf(
        "pair-steps: %zu compared (%zu with a certified contact), %zu ambiguous in the truth, %zu skipped "
        "(motion not InterpMotion's), %zu skipped (hulls)\n\n",
        queries.list.size(), queries.contacts, queries.ambiguous, queries.skipped_motion,
        queries.skipped_hull);
    std::printf("| method | contacts | misses | miss %% | false alarms | late | us/query |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    std::size_t ccdlab_misses = 0;
    for (const Method& m : methods(fcl_bodies, motion)) {
      const Tally t = tally(m, queries.list, args.repeats);
      if (std::string(m.name) == "ccdlab_ca") ccdlab_misses = t.misses;
      std::printf("| %s | %zu | %zu | %.1f | %zu | %zu | %.2f |\n", m.name, t.contact, t.misses,
                  t.contact ? 100.0 * static_cast<double>(t.misses) / static_cast<double>(t.contact) : 0.0,
                  t.false_alarms, t.late, t.us_per_query);
    }
    return ccdlab_misses == 0 ? 0 : 1;
  } catch (const ccd::InputError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
}
