// The earliest scheduler's slots in a scene that wraps around: a home slot is its body
// exactly, an image slot is the same path moved by whole periods (exactly: dyadic), paths
// are unwrapped over a window that crosses the seam, images follow the home box, slots are
// reused through the pool, and parked boxes never meet an active one.
#include <pipeline/scheduler_images.hpp>

#include <tests/ccd/scene/periodic_scenes.hpp>

#include <catch2/catch.hpp>

#include <algorithm>

namespace pipeline_scheduler_images_test {

using ccd::Vec3;

namespace {

// Box of a sphere of radius r whose centre moves from p to q.
ccd::Aabb swept(const Vec3& p, const Vec3& q, double r) {
  return {p.cwiseMin(q).array() - r, p.cwiseMax(q).array() + r};
}

}  // namespace

TEST_CASE("scheduler slots: homes, unwrapped paths and exact images", "[pipeline][periodic]") {
  // Box [0, 8]^3 wrapping on every axis; body 0 crosses the face x = 0 at t = 1/2 (moving
  // -2 from x = 1), body 1 rests at (4, 4, 4).
  ccd::Scene s = ccd::test::wrapped_box(2.0);
  s.bodies = {ccd::test::body(0.5, {1, 4, 4}, {-2, 0, 0}), ccd::test::body(0.5, {4, 4, 4})};
  const ccd::Trajectories motion(s);
  REQUIRE(motion.pieces(0).size() == 2);  // the wrap at t = 1/2
  ccd::SchedulerImages im;
  im.begin(motion);
  REQUIRE(im.size() == 2);
  CHECK(im.owner(0) == 0);
  CHECK(im.owner(1) == 1);

  SECTION("a home is its body at the window start, and unwrapped over the window") {
    im.set_home(0, 0.25);
    const ccd::BodyState st = im.state(0, 0.25);
    CHECK(st.position == Vec3(0.5, 4, 4));
    CHECK(st.velocity == Vec3(-2, 0, 0));
    // Past the wrap the home's path goes on below x = 0 (the body itself is at 8 - 0.5).
    CHECK(im.state(0, 0.75).position == Vec3(-0.5, 4, 4));
    CHECK(motion.position(0, 0.75) == Vec3(7.5, 4, 4));
    // A window starting after the wrap: the home is the body where it is now.
    im.set_home(0, 1.0);
    CHECK(im.state(0, 1.0).position == Vec3(7, 4, 4));
    CHECK(im.state(0, 0.25).position == Vec3(8.5, 4, 4));  // and unwrapped backwards
    // The view holds the listed slot's pieces over the window (both sides of the wrap),
    // moved onto one continuous path.
    im.set_home(0, 0.25);
    const std::uint32_t listed[] = {0};
    const ccd::Trajectories& v = im.view(listed, 0.25, 0.75);
    REQUIRE(v.size() == 2);
    CHECK(v.pieces(0).size() == 2);
    CHECK(v.pieces(1).empty());
    CHECK(v.periodic() == nullptr);
    CHECK(v.position(0, 0.75) == Vec3(-0.5, 4, 4));
    CHECK(v.position(0, 0.5) == Vec3(0, 4, 4));
  }

  SECTION("images of the home box that meets the face, exact shifts, pooled slots") {
    im.set_home(0, 0.25);
    std::vector<ccd::Aabb> boxes = {swept(Vec3(0.5, 4, 4), Vec3(-0.5, 4, 4), 0.5),
                                    swept(Vec3(4, 4, 4), Vec3(4, 4, 4), 0.5)};
    std::vector<std::uint32_t> images, freed;
    im.set_images(0, boxes[0], boxes, images, freed);
    REQUIRE(images.size() == 1);  // one image, at +8 on x
    CHECK(freed.empty());
    const std::uint32_t x = images[0];
    CHECK(x >= 2);
    CHECK(im.size() == boxes.size());  // the pool grew with parked boxes
    CHECK(im.owner(x) == 0);
    const ccd::ImageShift plus_x{1, 0, 0};
    CHECK(im.relative(0, x) == plus_x);
    CHECK(im.state(x, 0.25).position == Vec3(8.5, 4, 4));
    CHECK(im.state(x, 0.75).position == Vec3(7.5, 4, 4));  // the body itself, after its wrap
    // The pair view: slot x as body 0, body 1's home as body 1.
    im.set_home(1, 0.25);
    const ccd::Trajectories& pv = im.pair_view(x, 1, 0.25, 0.75);
    REQUIRE(pv.size() == 2);
    CHECK(pv.position(0, 0.5) == Vec3(8, 4, 4));
    CHECK(pv.position(1, 0.5) == Vec3(4, 4, 4));
    // Every pooled slot is parked: its point box meets no active box.
    for (std::uint32_t s = 0; s < im.size(); ++s)
      if (im.owner(s) == ccd::SchedulerImages::kFree)
        for (const std::uint32_t a : {0u, 1u, x}) CHECK_FALSE(boxes[s].overlaps(boxes[a]));
    // The home moves inside: its image is given back to the pool and parked.
    images.clear();
    const ccd::Aabb inside = swept(Vec3(4, 4, 4), Vec3(3, 4, 4), 0.5);
    boxes[0] = inside;
    im.set_images(0, inside, boxes, images, freed);
    CHECK(images.empty());
    REQUIRE(freed.size() == 1);
    CHECK(freed[0] == x);
    CHECK(im.owner(x) == ccd::SchedulerImages::kFree);
    CHECK_FALSE(boxes[x].overlaps(inside));
    // A corner: images on x, y and both; the freed slot is reused first.
    freed.clear();
    const ccd::Aabb corner = swept(Vec3(0.25, 7.75, 4), Vec3(0.25, 7.75, 4), 0.5);
    boxes[0] = corner;
    im.set_images(0, corner, boxes, images, freed);
    CHECK(images.size() == 3);
    CHECK(std::find(images.begin(), images.end(), x) != images.end());
    std::vector<ccd::ImageShift> shifts;
    for (const std::uint32_t s : images) shifts.push_back(im.relative(0, s));
    std::sort(shifts.begin(), shifts.end());
    const std::vector<ccd::ImageShift> expected = {{0, -1, 0}, {1, -1, 0}, {1, 0, 0}};
    CHECK(shifts == expected);
  }

  SECTION("a box that reaches the parking area moves the pool out") {
    std::vector<ccd::Aabb> boxes = {swept(Vec3(0.5, 4, 4), Vec3(-0.5, 4, 4), 0.5),
                                    swept(Vec3(4, 4, 4), Vec3(4, 4, 4), 0.5)};
    std::vector<std::uint32_t> images, freed, moved;
    im.set_home(0, 0.25);
    im.set_images(0, boxes[0], boxes, images, freed);
    // A very fast body's box spanning far below the box: every pooled slot moves out.
    const ccd::Aabb wide{Vec3(-100, 0, 0), Vec3(1, 8, 8)};
    im.keep_clear(wide, boxes, moved);
    CHECK(!moved.empty());
    for (const std::uint32_t s : moved) {
      CHECK(im.owner(s) == ccd::SchedulerImages::kFree);
      CHECK_FALSE(boxes[s].overlaps(wide));
    }
    moved.clear();
    im.keep_clear(boxes[1], boxes, moved);  // inside: nothing to do
    CHECK(moved.empty());
  }
}

}  // namespace pipeline_scheduler_images_test
