// The standard scenes, written once and shared by the tests, the benchmarks,
// the profiling workload (profiling/train_workload.cpp) and the demo.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "gaphys/world.hpp"

namespace gaphys::scenes {

// The time step every scene is meant to run at: 1/240 s.
inline constexpr real time_step = real(1) / 240;

// count spheres (radius 0.1 m, 1 kg, e = 0.3) on a jittered grid above an
// open box of five static planes sized to hold them, falling under gravity.
// Friction and rolling resistance (every shape's) 0 by default: the
// thesis's frictionless world.
world falling_spheres_in_box(int count, std::uint64_t seed = 1, real friction = 0,
                             real rolling_resistance = 0);

// count cubes (half extent 0.25 m, 1 kg, e = 0) in falling_spheres_in_box's
// pattern, spaced by their circumradius and turned at random, falling into
// an open box: the comparison's B5 scene. Friction 0.5 by default.
world falling_boxes_in_box(int count, std::uint64_t seed = 1, real friction = real(0.5));

// count spheres (radius, 1 kg, e = 0) stacked in a square tube of static
// planes 2% wider than a sphere, each dropped from 1 cm above the one below.
world sphere_column(int count = 5, real radius = real(0.5), real friction = 0);

// Two smooth spheres (no friction) without gravity, e = 1: 1 kg at
// (-2, 0, 0) moving at 3 m/s along e1 and 2 kg at (2, offset, 0) moving at
// -1 m/s; offset 0 is head-on.
world elastic_collision(real offset = real(0.3));

// One body without shape or gravity, principal inertia (1, 2, 3) kg m^2,
// spun at (1, 2, 3) rad/s about its body axes x, y, z.
world spinning_body();

// A smooth sphere (radius 0.5, 1 kg) whose bottom is drop_height above a
// static floor at z = 0, both with the given restitution.
world bouncing_sphere(real restitution, real drop_height = 2);

// A solid sphere (radius 0.5, 1 kg) touching a static floor at z = 0, with
// the given velocity and angular velocity; floor and sphere both of material m.
world sphere_on_floor(const vector& velocity, const bivector& spin, const material& m);

// A solid sphere (radius 0.5, 1 kg, e = 0) at rest touching a static plane
// through the origin tilted by `angle` (rad) about e2, so that it slopes down
// towards -e1; sphere and plane with friction μ.
world sphere_on_incline(real angle, real friction);

// A ball (radius 0.5, μ = 0.5) at rest on a 20° ramp, 3 m up-slope from
// where the ramp meets a floor: it rolls down and on along the floor.
world rolling_ramp();

// `count` smooth balls (radius 0.5, 1 kg, e = 1) in a touching row along e1
// without gravity; the first `released` of them move at `speed` towards the
// rest, touching them.
world newtons_cradle(int released, int count = 5, real speed = 1);

// `count` smooth spheres (radius 0.1, 1 kg, e = 1) in a closed 4 m box without
// gravity, at `speed` m/s in random directions, bouncing at any speed
// (restitution threshold 0): a gas whose kinetic energy is constant.
world sphere_gas(int count = 300, std::uint64_t seed = 1, real speed = 2);

// `count` unit cubes (1 kg, e = 0) stacked on a static floor at z = 0, each
// resting on the one below; cubes and floor with friction μ.
world box_tower(int count = 10, real friction = real(0.5));

// A two-dimensional pyramid of unit cubes (1 kg, e = 0, μ = 0.5) on a floor:
// `base` cubes in the bottom row, 5 cm apart, and one fewer in each row above,
// each resting across two below; base (base + 1) / 2 cubes in all.
world box_pyramid(int base = 10);

// `count` dominoes (0.1 x 0.5 x 1 m boxes, 1 kg, e = 0, μ = 0.5) standing in a
// row along e1, 0.5 m apart, on a floor; the first is tipped 15° towards the
// second about its leading bottom edge, so that each knocks over the next.
world dominoes(int count = 20);

// A table (a 1.5 x 0.9 x 0.06 m top on four 0.7 m legs: one compound body of
// five boxes, 10 kg, e = 0, μ = 0.5), tilted 3° about e1 and dropped with its
// feet 0.2 m above a floor, and a 0.4 m cube (1 kg) dropped onto its top.
world compound_table();

// `count` bodies (1 kg, e = 0.2, μ = 0.5), in turn a box, a capsule, a
// convex hull of 10 random points and a sphere, of random sizes (about
// 0.1 to 0.25 m across) and attitudes, dropped in layers into an open box
// of five static planes, 3 m wide.
world shape_mix(int count = 24, std::uint64_t seed = 1);

// The scenes by name, with their default sizes, for programs that pick one.
struct entry {
  std::string name;
  std::string description;
  std::function<world()> build;
};
const std::vector<entry>& catalogue();

}  // namespace gaphys::scenes
