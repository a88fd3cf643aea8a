// Seams between static shapes laid flush (docs/engine.md, "Seams"): a body
// slides over a floor of boxes as over one floor, while walls, steps and
// the floor under a resting body still hold it. Truth: a frictionless body
// keeps its speed, a sliding box with friction μ stops after v² / (2 μ g),
// and a wall or a step stops what slides into it.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "engine_test_support.hpp"
#include "gaphys/detail/hidden_faces.hpp"

namespace gaphys::testing {
namespace {

constexpr real h = real(1) / 60;
constexpr real tile_half = real(0.5);  // tiles 1 m long, 0.5 m thick, 4 m wide

// A turn about the vertical by `angle`: the floor's tiles are laid along
// turn(e1), so that no test relies on the world's axes.
rotor about_vertical(real angle) { return rotor{std::cos(angle / 2), -std::sin(angle / 2), 0, 0}; }

struct tiled_floor {
  world w;
  rotor turn;
  vector along;  // the direction the tiles are laid in
  std::vector<body_id> tiles;
};

// `count` static boxes laid flush along `along`, their tops at height 0
// (each raised by rise[i], where given), with friction mu; as one static
// body of `count` shapes where `compound`.
tiled_floor lay_tiles(int count, real angle, real mu, bool compound = false,
                      const std::vector<real>& rise = {}) {
  tiled_floor f;
  f.turn = about_vertical(angle);
  f.along = e3ga::apply(f.turn, vector{1, 0, 0});
  const auto raised = [&](int i) { return i < static_cast<int>(rise.size()) ? rise[i] : real(0); };
  const shape tile =
      shape::box(vector{tile_half, 2, real(0.25)}).with_friction(mu).with_restitution(0);
  if (compound) {
    body_definition floor;
    floor.is_static = true;
    floor.attitude = f.turn;
    for (int i = 0; i < count; ++i) {
      floor.shapes.push_back(attached_shape{
          tile, vector{2 * tile_half * i, 0, raised(i) - real(0.25)}, rotor{1, 0, 0, 0}});
    }
    f.tiles.push_back(f.w.create_body(floor));
    return f;
  }
  body_definition t;
  t.is_static = true;
  t.attitude = f.turn;
  t.shape = tile;
  for (int i = 0; i < count; ++i) {
    t.position = (2 * tile_half * i) * f.along + vector{0, 0, raised(i) - real(0.25)};
    f.tiles.push_back(f.w.create_body(t));
  }
  return f;
}

struct slider {
  std::string name;
  shape form;
  rotor attitude;  // in the floor's frame
  real rest_height;
};

// Bodies that slide on a face or a side: a cube, a ball, a capsule lying
// along the tiles, a pyramid (a hull) on its base.
std::vector<slider> sliders() {
  const real r = std::sqrt(real(0.5));
  return {
      {"box", shape::box(vector{0.2, 0.2, 0.2}), rotor{1, 0, 0, 0}, real(0.2)},
      {"sphere", shape::sphere(0.2), rotor{1, 0, 0, 0}, real(0.2)},
      {"capsule", shape::capsule(0.2, 0.1), rotor{r, 0, r, 0}, real(0.1)},
      {"pyramid",
       shape::convex_hull({vector{-0.2, -0.2, -0.1}, vector{0.2, -0.2, -0.1},
                           vector{-0.2, 0.2, -0.1}, vector{0.2, 0.2, -0.1}, vector{0, 0, 0.3}}),
       rotor{1, 0, 0, 0}, real(0.1)},
  };
}

body_id add_slider(tiled_floor& f, const slider& s, real mu, real along, real speed) {
  body_definition d;
  d.shape = s.form.with_friction(mu).with_restitution(0);
  d.attitude = e3ga::gp(f.turn, s.attitude);
  d.position = along * f.along + vector{0, 0, s.rest_height};
  d.velocity = speed * f.along;
  d.angular_velocity = bivector{};
  return f.w.create_body(d);
}

// Frictionless, each body crosses five seams at 3 m/s: before seams were
// handled, a box kept 1.06 m/s after the first (thrown up and turning),
// a pyramid 0.43, a ball 2.77 and a capsule 2.83.
TEST(seam_test, frictionless_bodies_keep_their_speed_across_the_seams_of_a_floor_of_boxes) {
  for (const bool compound : {false, true}) {
    for (const real angle : {real(0), real(0.6)}) {
      for (const slider& s : sliders()) {
        SCOPED_TRACE(s.name + (compound ? ", one compound floor" : ", separate tiles") +
                     ", turned " + std::to_string(angle));
        tiled_floor f = lay_tiles(8, angle, 0, compound);
        // Every shape's centre of mass (the hull's is above its base's centre).
        const body_id id = add_slider(f, s, 0, 0, 3);
        const real start_height = f.w.at(id).position().e3();
        real highest_rise = 0, fastest_vertical = 0;
        for (int i = 0; i < 110; ++i) {  // 5.5 m: five seams
          f.w.step(h);
          const body& b = f.w.at(id);
          highest_rise = std::max(highest_rise, std::fabs(b.position().e3() - start_height));
          fastest_vertical = std::max(fastest_vertical, std::fabs(b.velocity().e3()));
        }
        const body& b = f.w.at(id);
        EXPECT_GT(dot(b.position(), f.along), real(5.4));
        EXPECT_NEAR(dot(b.velocity(), f.along), 3, tolerance(1e-6, 1e-4));
        EXPECT_LT(highest_rise, real(0.001));
        EXPECT_LT(fastest_vertical, tolerance(1e-3, 1e-2));
        EXPECT_LT(length(b.angular_velocity()), tolerance(1e-3, 1e-2));
      }
    }
  }
}

// A box with friction μ = 0.4 sliding from 4 m/s stops after v² / (2 μ g)
// = 2.04 m, over two seams: where it stops on one static box as long.
TEST(seam_test, a_box_with_friction_stops_where_it_would_on_one_floor) {
  for (const real angle : {real(0), real(1.1)}) {
    SCOPED_TRACE(angle);
    const auto stopped_at = [&](bool tiled) {
      tiled_floor f = lay_tiles(tiled ? 6 : 0, angle, real(0.4));
      if (!tiled) {
        body_definition one;
        one.is_static = true;
        one.attitude = f.turn;
        one.position = real(2.5) * f.along + vector{0, 0, -0.25};
        one.shape = shape::box(vector{3, 2, 0.25}).with_friction(real(0.4)).with_restitution(0);
        f.w.create_body(one);
      }
      const body_id id = add_slider(f, sliders()[0], real(0.4), real(0.2), 4);
      for (int i = 0; i < 120; ++i) f.w.step(h);
      EXPECT_LT(length(f.w.at(id).velocity()), tolerance(1e-6, 1e-4));
      return dot(f.w.at(id).position(), f.along) - real(0.2);
    };
    const real on_tiles = stopped_at(true), on_one = stopped_at(false);
    const real expected = 4 * 4 / (2 * real(0.4) * real(9.81));
    EXPECT_NEAR(on_tiles, expected, real(0.03) * expected);
    EXPECT_NEAR(on_tiles, on_one, real(0.001));
  }
}

// A ball at rest right above a seam (or just beside it), its weight on both
// boxes' edges, stays up: neither box's contact hides the other's.
TEST(seam_test, a_ball_resting_on_a_seam_stays_up) {
  for (const real angle : {real(0), real(0.6)}) {
    for (const real offset : {real(0), real(1e-4), real(-3e-3), real(0.02)}) {
      SCOPED_TRACE(std::to_string(angle) + ", " + std::to_string(offset));
      tiled_floor f = lay_tiles(3, angle, real(0.5));
      const body_id id = add_slider(f, sliders()[1], real(0.5), 3 * tile_half + offset, 0);
      for (int i = 0; i < 180; ++i) f.w.step(h);
      EXPECT_NEAR(f.w.at(id).position().e3(), 0.2, 0.001);
    }
  }
}

// The seams' pass on the contacts as the narrow phase lists them, met in
// shares on two threads: 320 frictionless boxes in 8 rows slide at 3 m/s
// over a floor of 50 tiles, crossing three seams each (enough pairs to be
// met in shares). Each keeps its speed, as one box does above (with the
// pass left out where the pairs are met in shares, the boxes were thrown
// up at the first seam), and the state is the same to the bit on one
// thread and on two.
TEST(seam_test, boxes_sliding_over_seams_keep_their_speed_on_any_number_of_threads) {
  std::vector<std::uint64_t> hashes;
  for (const int threads : {1, 2}) {
    SCOPED_TRACE(threads);
    tiled_floor f = lay_tiles(50, real(0.6), 0);
    f.w.set_threads(threads);
    const vector across = e3ga::apply(f.turn, vector{0, 1, 0});
    std::vector<body_id> boxes;
    for (int row = 0; row < 8; ++row) {
      for (int at = 0; at < 40; ++at) {
        const body_id id = add_slider(f, sliders()[0], 0, real(0.5) * at + real(0.3), 3);
        body& b = f.w.at(id);
        b.set_position(b.position() + (real(0.45) * row - real(1.6)) * across);
        boxes.push_back(id);
      }
    }
    for (int i = 0; i < 60; ++i) f.w.step(h);
    EXPECT_GE(f.w.last_step_timings().candidate_pairs, 512u);
    for (const body_id id : boxes) {
      const body& b = f.w.at(id);
      ASSERT_NEAR(dot(b.velocity(), f.along), 3, tolerance(1e-6, 1e-4));
      ASSERT_LT(std::fabs(b.velocity().e3()), tolerance(1e-3, 1e-2));
    }
    hashes.push_back(f.w.state_hash());
  }
  EXPECT_EQ(hashes[0], hashes[1]);
}

// Walls and steps are not seams. A wall standing on the floor of boxes
// stops what slides into it, even a pyramid that meets it with the edge of
// its base, at the floor (its contact points lie where the floor hides the
// wall's face below them); a step 5 or 20 mm up stops a box sliding at
// 1 m/s (too slow to tip over it).
TEST(seam_test, a_wall_on_a_floor_of_boxes_and_a_step_still_stop_a_sliding_body) {
  // How far along the tiles the body's front came, at most: its farthest
  // corner, or the far side of its ball or of a capsule's end ball.
  const auto farthest = [](tiled_floor& f, body_id id) {
    real most = 0;
    for (int i = 0; i < 120; ++i) {
      f.w.step(h);
      const body& b = f.w.at(id);
      const attached_shape& only = b.shapes()[0];
      const auto along = [&](const vector& in_body) { return dot(b.to_world(in_body), f.along); };
      if (const convex_polyhedron* hull = only.shape.polyhedron()) {
        for (const vector& corner : hull->vertices)
          most = std::max(most, along(only.offset + corner));
      } else {
        const real ends = only.shape.kind() == shape_kind::capsule ? only.shape.half_height() : 0;
        for (const real end : {-ends, ends}) {
          most = std::max(most, along(only.offset + vector{0, 0, end}) + only.shape.radius());
        }
      }
    }
    return most;
  };
  for (const slider& s : sliders()) {
    SCOPED_TRACE(s.name);
    tiled_floor f = lay_tiles(6, real(0.6), 0);
    // The wall: a static box 1 m high standing on tile 3, its face at 3.0 m.
    body_definition wall;
    wall.is_static = true;
    wall.attitude = f.turn;
    wall.position = real(3.25) * f.along + vector{0, 0, 0.5};
    wall.shape = shape::box(vector{0.25, 2, 0.5}).with_friction(0).with_restitution(0);
    f.w.create_body(wall);
    const body_id id = add_slider(f, s, 0, 0, 3);
    EXPECT_NEAR(farthest(f, id), 3, 0.005);
  }
  for (const real rise : {real(0.02), real(0.005)}) {
    SCOPED_TRACE(rise);
    tiled_floor f = lay_tiles(6, 0, 0, false, {0, 0, 0, rise});
    const body_id id = add_slider(f, sliders()[0], 0, 1, 1);
    // (Tipped back by the step's edge, its top corner may reach over the step.)
    real most = 0;
    for (int i = 0; i < 120; ++i) {
      f.w.step(h);
      most = std::max(most, dot(f.w.at(id).position(), f.along));
    }
    EXPECT_GT(most, real(2.29));
    EXPECT_LT(most, real(2.5) - real(0.18));
    EXPECT_LT(dot(f.w.at(id).velocity(), f.along), 0);  // sent back
  }
}

// The lowest point of a body with one box or hull shape.
real lowest_corner(const body& b) {
  const attached_shape& only = b.shapes()[0];
  real lowest = std::numeric_limits<real>::infinity();
  for (const vector& corner : only.shape.polyhedron()->vertices) {
    lowest = std::min(lowest, b.to_world(only.offset + corner).e3());
  }
  return lowest;
}

// The lowest any corner of the body came in `seconds` of steps.
real lowest_over(tiled_floor& f, body_id id, real seconds) {
  real lowest = 1;
  for (int i = 0; i * h < seconds; ++i) {
    f.w.step(h);
    lowest = std::min(lowest, lowest_corner(f.w.at(id)));
  }
  return lowest;
}

// Surfaces that are not flush hide nothing: a tile 1.5 or 2 mm higher than
// the one before is a step, whose lower tile's edge holds up the pyramid or
// wedge that slides against it; a plate 2 mm thick lying on a floor does not
// hide the floor from what pushes into its edge. (A first version hid
// both: hulls sank 2 to 37 cm, some through the floor.)
TEST(seam_test, surfaces_that_are_not_flush_hide_nothing) {
  const shape wedge = shape::convex_hull({vector{-0.2, -0.2, -0.1}, vector{0.2, -0.2, -0.1},
                                          vector{-0.2, 0.2, -0.1}, vector{0.2, 0.2, -0.1},
                                          vector{-0.2, -0.2, 0.2}, vector{-0.2, 0.2, 0.2}});
  const slider sliding_wedge{"wedge", wedge, rotor{1, 0, 0, 0}, real(0.1)};
  for (const slider& s : {sliders()[3], sliding_wedge}) {
    for (const real speed : {real(1), real(3), real(6)}) {
      for (const real rise : {real(0.0015), real(0.002)}) {
        SCOPED_TRACE(s.name + " at " + std::to_string(speed) + " m/s, step " +
                     std::to_string(rise));
        tiled_floor f = lay_tiles(8, 0, 0, false, {0, rise, 0, rise, 0, rise, 0, rise});
        const body_id id = add_slider(f, s, 0, 0, speed);
        EXPECT_GT(lowest_over(f, id, 6 / speed), real(-0.003));  // 6 m: still over the tiles
      }
      SCOPED_TRACE(s.name + " at " + std::to_string(speed) + " m/s, against a plate");
      tiled_floor f = lay_tiles(1, 0, 0);
      body_definition floor;
      floor.is_static = true;
      floor.position = vector{1, 0, -0.25};
      floor.shape = shape::box(vector{4, 2, 0.25}).with_friction(0).with_restitution(0);
      f.w.create_body(floor);
      body_definition plate = floor;
      plate.position = vector{1.5, 0, 0.001};
      plate.shape = shape::box(vector{0.5, 1, 0.001}).with_friction(0).with_restitution(0);
      f.w.create_body(plate);
      const body_id id = add_slider(f, s, 0, 0, speed);
      EXPECT_GT(lowest_over(f, id, 4 / speed), real(-0.003));  // 4 m: still over the floor
    }
  }
}

// The test itself, on shapes placed by hand: the second of two flush boxes
// hides its side from a point at the seam (resting up to the slop into the
// first), not its top; a wall on a floor keeps its face.
TEST(seam_test, hidden_by_tells_a_covered_face_from_a_wall) {
  const real slop = real(0.0005);
  // (A placed box points to its shape's polyhedron: the shapes outlive them.)
  const shape tile = shape::box(vector{0.5, 2, 0.25}), upright = shape::box(vector{0.25, 2, 0.5});
  const placed_shape first = place(tile, vector{0, 0, -0.25}, rotor{1, 0, 0, 0});
  const placed_shape second = place(tile, vector{1, 0, -0.25}, rotor{1, 0, 0, 0});
  for (const real depth : {real(0), real(0.0002), real(0.0005), real(-0.0004)}) {
    EXPECT_TRUE(detail::hidden_by(second, vector{0.5, 0, -depth}, vector{-1, 0, 0}, first, slop));
  }
  EXPECT_FALSE(detail::hidden_by(second, vector{0.5, 0, 0}, vector{0, 0, 1}, first, slop));
  EXPECT_FALSE(detail::hidden_by(second, vector{0.7, 0, 0}, vector{0, 0, 1}, first, slop));
  // A ball's contact at the second box's edge, its normal leaning over the first.
  const vector leaning{-std::sin(real(0.3)), 0, std::cos(real(0.3))};
  EXPECT_TRUE(detail::hidden_by(second, vector{0.5, 0, 0}, leaning, first, slop));
  // Leaning the other way, over the second box's own top: not hidden.
  const vector away{std::sin(real(0.3)), 0, std::cos(real(0.3))};
  EXPECT_FALSE(detail::hidden_by(second, vector{0.5, 0, 0}, away, first, slop));
  // The second box 1.5 mm higher is a step: neither its side above the
  // first box nor the first box's edge under a normal leaning over it is
  // hidden (a first version hid the edge, and hulls sank at such steps).
  const placed_shape raised =
      place(tile, vector{1, 0, real(-0.25) + real(0.0015)}, rotor{1, 0, 0, 0});
  EXPECT_FALSE(detail::hidden_by(raised, vector{0.5, 0, 0.0005}, vector{-1, 0, 0}, first, slop));
  const vector over_the_step{std::sin(real(0.3)), 0, std::cos(real(0.3))};
  EXPECT_FALSE(detail::hidden_by(first, vector{0.5, 0, 0}, over_the_step, raised, slop));
  // Raised by a tenth of the slop, it is still a seam.
  const placed_shape level =
      place(tile, vector{1, 0, real(-0.25) + real(0.00005)}, rotor{1, 0, 0, 0});
  EXPECT_TRUE(detail::hidden_by(level, vector{0.5, 0, 0}, vector{-1, 0, 0}, first, slop));
  // A wall 1 m high on the first box: its face at the floor is not hidden.
  const placed_shape wall = place(upright, vector{0.25, 0, 0.5}, rotor{1, 0, 0, 0});
  EXPECT_FALSE(detail::hidden_by(wall, vector{0, 0, 0}, vector{-1, 0, 0}, first, slop));
  // A plane floor hides no part of a face of a box standing on it.
  const shape plane = shape::plane(vector{0, 0, 1}, 0);
  const placed_shape floor = place(plane, vector{}, rotor{1, 0, 0, 0});
  EXPECT_FALSE(detail::hidden_by(wall, vector{0, 0, 0}, vector{-1, 0, 0}, floor, slop));
}

}  // namespace
}  // namespace gaphys::testing
