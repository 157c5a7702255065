#include <pipeline/image_pairs.hpp>
#include <pipeline/periodic_images.hpp>

#include <algorithm>
#include <tuple>
#include <utility>

namespace ccd {

void ImagePairs::group(std::span<const BodyPair> local, std::span<const std::uint32_t> owner,
                       std::span<const ImageShift> shift, std::vector<BodyPair>& bodies) {
  pairs_.clear();
  for (const BodyPair& p : local) {
    std::uint32_t x = p.a, y = p.b;
    std::uint32_t a = owner[x], b = owner[y];
    if (a == b) continue;
    if (a > b) {
      std::swap(a, b);
      std::swap(x, y);
    }
    pairs_.push_back({a, b, shift_difference(shift[y], shift[x]), x, y});
  }
  auto key = [](const ImagePair& q) { return std::tie(q.a, q.b, q.shift); };
  std::sort(pairs_.begin(), pairs_.end(),
            [&](const ImagePair& p, const ImagePair& q) { return key(p) < key(q); });
  pairs_.erase(std::unique(pairs_.begin(), pairs_.end(),
                           [&](const ImagePair& p, const ImagePair& q) { return key(p) == key(q); }),
               pairs_.end());
  tests_.clear();
  bodies.clear();
  for (const ImagePair& q : pairs_) {
    tests_.push_back({std::min(q.x, q.y), std::max(q.x, q.y)});
    if (bodies.empty() || bodies.back() != BodyPair{q.a, q.b}) bodies.push_back({q.a, q.b});
  }
}

void ImagePairs::reduce_tests(std::span<const BodyPair> passed, std::span<const double> earliest,
                              std::vector<BodyPair>& body_passed, std::vector<double>& body_earliest) {
  solve_.clear();
  solve_earliest_.clear();
  solve_group_.clear();
  passed_bodies_.clear();
  std::size_t j = 0;  // next passed local pair: the passed ones are a subsequence of tests_
  for (std::size_t i = 0; i < pairs_.size() && j < passed.size(); ++i) {
    if (tests_[i] != passed[j]) continue;
    const ImagePair& q = pairs_[i];
    const BodyPair body{q.a, q.b};
    if (passed_bodies_.empty() || passed_bodies_.back() != body) {
      passed_bodies_.push_back(body);
      body_passed.push_back(body);
      body_earliest.push_back(earliest[j]);
    } else {
      body_earliest.back() = std::min(body_earliest.back(), earliest[j]);
    }
    solve_.push_back({q.x, q.y});
    solve_earliest_.push_back(earliest[j]);
    solve_group_.push_back(static_cast<std::uint32_t>(passed_bodies_.size() - 1));
    ++j;
  }
  best_.assign(passed_bodies_.size(), ContactResult{});
  has_best_.assign(passed_bodies_.size(), 0);
}

void ImagePairs::keep(std::size_t i, const ContactResult& c) {
  const std::uint32_t k = solve_group_[i];
  if (!has_best_[k] || c.toi < best_[k].toi) {
    best_[k] = c;
    has_best_[k] = 1;
  }
}

}  // namespace ccd
