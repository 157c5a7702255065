#include <ccd/motion/state_cursor.hpp>

namespace ccd {

void StateCursor::evaluate(double t, std::vector<BodyState>& out) {
  out.resize(motion_.size());
  for (std::size_t i = 0; i < motion_.size(); ++i) {
    const auto ps = motion_.pieces(i);
    std::size_t& c = cursor_[i];
    while (c + 1 < ps.size() && t >= ps[c].t1) ++c;
    out[i] = {ps[c].position(t), ps[c].velocity(t), motion_.radius(i)};
  }
}

}  // namespace ccd
