#pragma once
// Whether two bodies of a scene touch at a given time: the sample test of discrete
// methods and the runner's shortcut, with the same definition of touching as the ground
// truth (ccd/queries/pair_motion.hpp: f <= its certified error bound).
#include <ccd/motion/trajectory.hpp>
#include <ccd/queries/pair_motion.hpp>

#include <cstdint>

namespace ccd {

enum class ContactCertainty : std::uint8_t { Apart, Contact, Unsure };

/// The double-precision verdict of in_contact: Apart or Contact when |f| exceeds the
/// double band 64 eps (|d| + R)(|d| + R + P), Unsure otherwise. Contact here implies a
/// truth interval that contains t in its interior.
ContactCertainty certain_contact(const Trajectories& traj, std::uint32_t a, std::size_t ia, std::uint32_t b,
                                 std::size_t ib, double t);

/// Whether bodies a and b are in contact at time t (f(t) <= its error bound): the sample
/// test of discrete methods. A double-precision evaluation decides when it is certain
/// (|f| beyond 64 eps (|d| + R)(|d| + R + P)); otherwise the double-double one does.
bool in_contact(const Trajectories& traj, std::uint32_t a, std::uint32_t b, double t);
/// The same, with the pieces that contain t already known (indices into pieces(a), pieces(b)).
bool in_contact(const Trajectories& traj, std::uint32_t a, std::size_t ia, std::uint32_t b, std::size_t ib, double t);

}  // namespace ccd
