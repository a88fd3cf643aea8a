// turning_approach (turning_reach.hpp) against the shape turned for real:
// the pose at many angles through the step, from the algebra's rotor
// exponential, and the support read by GJK's own support functions; the
// largest growth found that way is what turning_approach must give.
#include <algorithm>
#include <cmath>
#include <vector>

#include "gjk.hpp"
#include "placed_shape_test.hpp"
#include "turning_reach.hpp"

namespace gaphys::testing {
namespace {

using detail::turning_approach;

class turning_reach_test : public placed_shape_test {
 protected:
  static constexpr real step = real(1) / 60;  // s: a game's step, turns of radians

  // The shape turned by `angle` in the unit plane `plane` about `centre`:
  // x -> centre + R (x - centre) ~R with R = exp(-angle/2 plane), which
  // moves x at first along (x - centre) ⌋ plane, as the engine's ω does.
  static placed_shape turned(const placed_shape& s, const vector& centre, const bivector& plane,
                             real angle) {
    const rotor r = e3ga::exp((-angle / 2) * plane);
    placed_shape t = s;
    t.center = centre + e3ga::apply(r, s.center - centre);
    t.attitude = e3ga::unit(e3ga::gp(r, s.attitude));
    t.axis = e3ga::apply(r, s.axis);
    return t;
  }
  // The support along d: the farthest point's d . x (a capsule's segment
  // and a sphere's centre, whose radius adds the same at every angle).
  static real support(const placed_shape& s, const vector& d) {
    if (s.kind == shape_kind::box || s.kind == shape_kind::convex_hull) {
      return dot(d, detail::polyhedron_support(s)(d));
    }
    if (s.kind == shape_kind::capsule) {
      const detail::segment core{s.center - s.half_height * s.axis,
                                 s.center + s.half_height * s.axis};
      return dot(d, detail::segment_support(core)(d));
    }
    return dot(d, s.center);
  }
  // The most the support grows over `samples` + 1 angles from 0 to `angle`.
  static real sampled_approach(const placed_shape& s, const vector& centre, const bivector& plane,
                               real angle, const vector& d, int samples) {
    const real before = support(s, d);
    real most = 0;
    for (int k = 0; k <= samples; ++k) {
      most = std::max(most, support(turned(s, centre, plane, angle * k / samples), d) - before);
    }
    return most;
  }
  // The farthest point of the shape's corners (as turning_approach takes
  // them) from `centre`.
  static real farthest_corner(const placed_shape& s, const vector& centre) {
    real most = 0;
    const auto corner = [&](const vector& x) { most = std::max(most, length(x - centre)); };
    if (s.polyhedron) {
      for (const vector& v : s.polyhedron->vertices) corner(s.center + e3ga::apply(s.attitude, v));
    } else if (s.kind == shape_kind::capsule) {
      corner(s.center + s.half_height * s.axis);
      corner(s.center - s.half_height * s.axis);
    } else {
      corner(s.center);
    }
    return most;
  }
  rotor random_attitude() {
    return e3ga::exp(uniform(-3.2, 3.2) * e3ga::dual(random_unit_vector()));
  }
  vector random_point(real extent) {
    return vector{uniform(-extent, extent), uniform(-extent, extent), uniform(-extent, extent)};
  }
  // A random box, hull, capsule or sphere near the origin.
  placed_shape random_shape(int kind) {
    const vector at = random_point(0.5);
    switch (kind % 4) {
      case 0:
        return box(at, vector{uniform(0.05, 1), uniform(0.05, 1), uniform(0.05, 1)},
                   random_attitude());
      case 1: {
        std::vector<vector> points;
        for (int i = 0; i < 12; ++i) points.push_back(random_point(0.6));
        return hull(points, at, random_attitude());
      }
      case 2:
        return place(shape::capsule(uniform(0.05, 0.8), uniform(0.02, 0.3)), at, random_attitude());
      default:
        return sphere(at, uniform(0.05, 0.5));
    }
  }
};

// Turns of less than half a revolution are followed exactly: the growth is
// the largest the turned poses reach (sampling may only miss a little of it).
TEST_F(turning_reach_test, a_turn_of_under_half_a_revolution_is_followed_exactly) {
  for (int trial = 0; trial < 400; ++trial) {
    const placed_shape s = random_shape(trial);
    const vector centre =
        random_point(0.3);  // the body's centre of mass (compounds: off the shape)
    const bivector plane = e3ga::dual(random_unit_vector());
    const real rate = uniform(0.5, 180);  // rad/s: up to 3 rad in a step of 1/60 s
    const vector d = random_unit_vector();
    const real exact = turning_approach(s, centre, rate * plane, step, d);
    const real sampled = sampled_approach(s, centre, plane, rate * step, d, 4000);
    const real size = farthest_corner(s, centre);
    // (4,000 samples of up to 3 rad miss the peak by at most size (3/4000)^2 / 8.)
    ASSERT_GE(exact, sampled - tolerance(1e-12, 2e-6) * size) << "trial " << trial;
    ASSERT_LE(exact, sampled + tolerance(1e-7, 2e-6) * size) << "trial " << trial;
    // The growth is at most the chord each corner sweeps, at most h |ω| r.
    ASSERT_LE(exact, rate * step * size * (1 + tolerance(1e-12, 1e-6))) << "trial " << trial;
  }
}

// From half a revolution on, turning_approach may overestimate (the whole
// turn's reach, as a bound) but never underestimates, and never exceeds the
// shape's diameter about the centre.
TEST_F(turning_reach_test, a_longer_turn_is_bounded_from_above) {
  for (int trial = 0; trial < 200; ++trial) {
    const placed_shape s = random_shape(trial);
    const vector centre = random_point(0.3);
    const bivector plane = e3ga::dual(random_unit_vector());
    const real rate = uniform(190, 600);  // 3.2 to 10 rad in a step
    const vector d = random_unit_vector();
    const real bound = turning_approach(s, centre, rate * plane, step, d);
    const real sampled = sampled_approach(s, centre, plane, rate * step, d, 8000);
    const real size = farthest_corner(s, centre);
    ASSERT_GE(bound, sampled - tolerance(1e-12, 2e-6) * size) << "trial " << trial;
    ASSERT_LE(bound, 2 * size * (1 + tolerance(1e-12, 1e-6))) << "trial " << trial;
  }
}

// A cube spinning about a face's axis sweeps its corners round a circle of
// radius sqrt(2)/2 in that plane: towards a floor below, its support grows
// from 1/2 to at most sqrt(2)/2, whatever the speed; about the vertical it
// does not grow; a body at rest or a plane does not turn.
TEST_F(turning_reach_test, a_spinning_cube_reaches_no_farther_than_its_corners_circle) {
  const placed_shape cube = box(vector{0, 0, 1}, vector{0.5, 0.5, 0.5});
  const vector centre{0, 0, 1}, down{0, 0, -1};
  const bivector about_y{0, 1, 0}, about_z{1, 0, 0};
  const real circle = std::sqrt(real(0.5));
  for (const real rate : {real(50), real(100), real(300), real(1000)}) {
    EXPECT_NEAR(turning_approach(cube, centre, rate * about_y, step, down), circle - real(0.5),
                tolerance(1e-12, 1e-6));
    EXPECT_NEAR(turning_approach(cube, centre, rate * about_z, step, down), 0,
                tolerance(1e-12, 1e-6));
  }
  // A small turn: the leading corner's drop, sin(θ + π/4) sqrt(1/2) - 1/2 (not the tangent's θ/2).
  const real angle = real(0.3);
  EXPECT_NEAR(turning_approach(cube, centre, (angle / step) * about_y, step, down),
              std::sin(angle + real(0.7853981633974483)) * circle - real(0.5),
              tolerance(1e-12, 1e-6));
  EXPECT_EQ(turning_approach(cube, centre, bivector{}, step, down), 0);
  EXPECT_EQ(turning_approach(floor(), vector{}, bivector{0, 0, 5}, step, vector{0, 0, 1}), 0);
}

}  // namespace
}  // namespace gaphys::testing
