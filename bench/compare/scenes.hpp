// The scenes the metrics run. Where gaphys::scenes already has one it is
// converted from that world, so the comparison runs exactly the scene the
// gaphys tests and benchmarks run (same sizes, same jittered grid).
#pragma once

#include "scene.hpp"

namespace gaphys {
class world;
}  // namespace gaphys

namespace gaphys_compare {

// The bodies, planes and gravity of a gaphys world. Throws
// std::invalid_argument for what the neutral description cannot hold
// (a non-identity attitude, a non-diagonal inertia, a point shape).
// Friction is not taken over: M1-M6 compare frictionless contacts, whatever
// gaphys's scenes leave their shapes' friction at.
scene from_gaphys(const gaphys::world& world, const std::string& name);

// M1: principal inertia (1, 2, 3) kg m^2 spun at (1, 2, 3) rad/s, no gravity.
scene spinning_body();

// M2: 1 kg and 2 kg spheres (r 0.5, e 1) meeting at 3 and -1 m/s, their
// paths offset by `offset` (0: head-on), no gravity.
scene two_spheres(double offset);

// M2: five 1 kg spheres (r 0.5, e 1) on the x axis, the last four touching,
// the first 1 m away and moving at 1 m/s towards them, no gravity.
scene newtons_cradle();

// M3: a sphere (r 0.5, 1 kg) whose bottom is 2 m above a floor at z = 0,
// both with restitution e, under gravity.
scene bouncing_sphere(double e);

// M4: count spheres (r 0.5, e 0) stacked in a tube of four walls.
scene sphere_column(int count);

// M5: a sphere (r 0.1, 1 kg, e 0.5) 1 m above its target moving down at
// `speed`, no gravity; it is the scene's last body. The target is the floor plane z = 0 or, for
// `sphere_target`, a static sphere (r 0.1) centred at the origin.
scene projectile(double speed, bool sphere_target);

// M6: count spheres (r 0.1, e 0.3) falling into an open box of five planes.
scene falling_spheres(int count);

// F1, F2, F4: a solid sphere (r 0.5, 1 kg, e 0) resting on the floor plane
// z = 0, touching it, launched with `velocity` and `angular_velocity`
// (world frame, rad/s); sphere and floor have friction mu, under gravity.
scene sphere_on_floor(const std::string& name, const vec3& velocity, const vec3& angular_velocity,
                      double mu);

// F3: the same sphere at rest, touching a static plane through the origin
// tilted by `degrees` about the y axis (normal (-sin, 0, cos): the slope
// falls towards -x), both with friction mu, under gravity.
scene sphere_on_incline(double degrees, double mu);

// The direction down the slope of sphere_on_incline(degrees, ...).
vec3 down_the_incline(double degrees);

// s with friction mu on every plane and shape (F5: M6's scene with friction).
scene with_friction(scene s, double mu);

// The box scenes (B1-B5): solid boxes of 1 kg, e 0, friction mu on every
// box and plane, under gravity 9.81 along -z. A "unit box" has half extents 0.5.

// B1: a unit box at rest with a face flat on a static plane through the
// origin tilted by `degrees` about y (the plane of sphere_on_incline),
// touching it: the box is turned by the same angle.
scene box_on_incline(double degrees, double mu);

// B2: a unit box resting on the floor z = 0, turned by `yaw_degrees` about z,
// sliding at `speed` along x without spin.
scene sliding_box(double speed, double yaw_degrees, double mu);

// B3: count unit boxes stacked on the floor, exactly touching (centres at
// z = 0.5 + i), aligned with the axes.
scene box_tower(int count, double mu);

// B4: a pyramid of unit boxes in the x-z plane: rows of base, base - 1, ...,
// 1 boxes, neighbours in a row `gap` apart, each box centred over the gap
// between the two below it and touching them (no vertical gap).
scene box_pyramid(int base, double gap, double mu);

// B5: count boxes (half extents 0.25) falling into M6's open box of five
// planes, spawned as M6 spawns its spheres with the sphere's radius replaced
// by the box's circumradius (so no two start overlapping, whatever their
// attitudes): a jittered grid of pitch 3 r, at random attitudes.
scene falling_boxes(int count, double mu, unsigned seed = 1);

}  // namespace gaphys_compare
