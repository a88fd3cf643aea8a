#include "scenes.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "gaphys/scenes.hpp"
#include "gaphys_conversions.hpp"
#include "number.hpp"

namespace gaphys_compare {

namespace {

body_description sphere(double radius, double mass, const vec3& position, const vec3& velocity,
                        double restitution) {
  const double moment = 0.4 * mass * radius * radius;  // solid sphere
  body_description b;
  b.mass = mass;
  b.radius = radius;
  b.inertia = {moment, moment, moment};
  b.position = position;
  b.velocity = velocity;
  b.restitution = restitution;
  return b;
}

// A solid box of uniform density: I_x = m (b_y^2 + b_z^2) / 3 for half
// extents b, and so on about y and z.
body_description solid_box(const vec3& half_extents, double mass, const vec3& position,
                           const quat& attitude, double friction) {
  const vec3 b2{half_extents.x * half_extents.x, half_extents.y * half_extents.y,
                half_extents.z * half_extents.z};
  body_description b;
  b.mass = mass;
  b.half_extents = half_extents;
  b.inertia = {mass * (b2.y + b2.z) / 3, mass * (b2.z + b2.x) / 3, mass * (b2.x + b2.y) / 3};
  b.position = position;
  b.attitude = attitude;
  b.friction = friction;
  return b;
}

// The friction scenes' ball (scenes.hpp, sphere_on_floor).
constexpr double ball_radius = 0.5, ball_mass = 1;
constexpr double pi = 3.14159265358979323846;

// The box scenes' boxes and gravity.
constexpr double box_mass = 1;
constexpr vec3 unit_box{0.5, 0.5, 0.5};
constexpr vec3 box_gravity{0, 0, -9.81};

scene floor_scene(const std::string& name, double mu) {
  scene s;
  s.name = name;
  s.gravity = box_gravity;
  s.planes.push_back({{0, 0, 1}, 0, 0, mu});
  return s;
}

// Uniform in [-1, 1), from 53 random bits (the same numbers on every
// platform, which std::uniform_real_distribution does not promise).
double symmetric_unit(std::mt19937_64& random) {
  return static_cast<double>(random() >> 11) * 0x1.0p-52 - 1;
}

// A rotation drawn uniformly from all rotations: the unit quaternion
// (sqrt(1-u) sin a, sqrt(1-u) cos a, sqrt(u) sin b, sqrt(u) cos b) with u
// uniform in [0, 1) and a, b uniform angles is uniform on the 3-sphere.
quat random_attitude(std::mt19937_64& random) {
  const double u = (symmetric_unit(random) + 1) / 2;
  const double a = pi * (symmetric_unit(random) + 1), b = pi * (symmetric_unit(random) + 1);
  const double p = std::sqrt(1 - u), q = std::sqrt(u);
  return {p * std::sin(a), p * std::cos(a), q * std::sin(b), q * std::cos(b)};
}

}  // namespace

scene from_gaphys(const gaphys::world& world, const std::string& name) {
  scene s;
  s.name = name;
  s.gravity = to_vec3(world.settings().gravity);
  for (const gaphys::body& b : world.bodies()) {
    const gaphys::rotor& r = b.attitude();
    if (r.c[0] != 1 || r.c[1] != 0 || r.c[2] != 0 || r.c[3] != 0) {
      throw std::invalid_argument(name + ": a body does not start at the identity attitude");
    }
    const auto& shape = b.shape();
    if (shape && shape->kind() == gaphys::shape_kind::plane) {
      const gaphys::placed_shape placed = gaphys::place(*shape, b.position(), r);
      s.planes.push_back({to_vec3(placed.normal), placed.offset, shape->restitution()});
      continue;
    }
    if (shape && shape->kind() != gaphys::shape_kind::sphere) {
      throw std::invalid_argument(name + ": only spheres and planes have a neutral description");
    }
    const auto& rows = b.body_inertia().rows();
    if (rows[1] != 0 || rows[2] != 0 || rows[3] != 0 || rows[5] != 0 || rows[6] != 0 ||
        rows[7] != 0) {
      throw std::invalid_argument(name + ": inertia is not diagonal in the body frame");
    }
    body_description d;
    d.is_static = b.is_static();
    d.mass = b.is_static() ? 0 : b.mass();
    d.radius = shape ? shape->radius() : 0;
    d.inertia = {rows[0], rows[4], rows[8]};
    d.position = to_vec3(b.position());
    d.velocity = to_vec3(b.velocity());
    d.angular_velocity = axis_of(b.angular_velocity());
    d.restitution = shape ? shape->restitution() : 0;
    s.bodies.push_back(d);
  }
  return s;
}

scene spinning_body() { return from_gaphys(gaphys::scenes::spinning_body(), "spinning body"); }

scene two_spheres(double offset) {
  return from_gaphys(gaphys::scenes::elastic_collision(offset),
                     offset == 0 ? "head-on" : "oblique " + number(offset));
}

scene newtons_cradle() {
  scene s;
  s.name = "cradle 5";
  s.bodies.push_back(sphere(0.5, 1, {-2, 0, 0}, {1, 0, 0}, 1));
  for (int i = 0; i < 4; ++i) s.bodies.push_back(sphere(0.5, 1, {double(i), 0, 0}, {}, 1));
  return s;
}

scene bouncing_sphere(double e) {
  return from_gaphys(gaphys::scenes::bouncing_sphere(e), "e " + number(e));
}

scene sphere_column(int count) {
  return from_gaphys(gaphys::scenes::sphere_column(count), "K " + number(count));
}

scene projectile(double speed, bool sphere_target) {
  constexpr double radius = 0.1, restitution = 0.5;
  scene s;
  s.name = sphere_target ? "sphere target" : "plane target";
  if (sphere_target) {
    body_description target = sphere(radius, 1, {}, {}, restitution);
    target.is_static = true;
    s.bodies.push_back(target);
  } else {
    s.planes.push_back({{0, 0, 1}, 0, restitution});
  }
  s.bodies.push_back(sphere(radius, 1, {0, 0, 1}, {0, 0, -speed}, restitution));
  return s;
}

scene falling_spheres(int count) {
  return from_gaphys(gaphys::scenes::falling_spheres_in_box(count), "N " + number(count));
}

scene sphere_on_floor(const std::string& name, const vec3& velocity, const vec3& angular_velocity,
                      double mu) {
  scene s;
  s.name = name;
  s.gravity = {0, 0, -9.81};
  s.planes.push_back({{0, 0, 1}, 0, 0, mu});
  body_description ball = sphere(ball_radius, ball_mass, {0, 0, ball_radius}, velocity, 0);
  ball.angular_velocity = angular_velocity;
  ball.friction = mu;
  s.bodies.push_back(ball);
  return s;
}

vec3 down_the_incline(double degrees) {
  const double angle = degrees * pi / 180;
  return {-std::cos(angle), 0, -std::sin(angle)};
}

scene sphere_on_incline(double degrees, double mu) {
  const double angle = degrees * pi / 180;
  const vec3 normal{-std::sin(angle), 0, std::cos(angle)};
  scene s;
  s.name = number(degrees) + " deg, mu " + number(mu);
  s.gravity = {0, 0, -9.81};
  s.planes.push_back({normal, 0, 0, mu});
  // Centre one radius out along the normal: touching, not overlapping.
  body_description ball = sphere(ball_radius, ball_mass, ball_radius * normal, {}, 0);
  ball.friction = mu;
  s.bodies.push_back(ball);
  return s;
}

scene with_friction(scene s, double mu) {
  for (plane_description& p : s.planes) p.friction = mu;
  for (body_description& b : s.bodies) {
    if (b.has_shape()) b.friction = mu;
  }
  return s;
}

scene box_on_incline(double degrees, double mu) {
  const double angle = degrees * pi / 180;
  const vec3 normal{-std::sin(angle), 0, std::cos(angle)};
  scene s;
  s.name = number(degrees) + " deg, mu " + number(mu);
  s.gravity = box_gravity;
  s.planes.push_back({normal, 0, 0, mu});
  // Turning by -angle about y takes z to the normal; the centre is half a
  // side out along it, so the bottom face lies on the plane.
  s.bodies.push_back(
      solid_box(unit_box, box_mass, unit_box.z * normal, about_axis({0, 1, 0}, -angle), mu));
  return s;
}

scene sliding_box(double speed, double yaw_degrees, double mu) {
  scene s = floor_scene("v0 " + number(speed) + ", yaw " + number(yaw_degrees) + " deg", mu);
  body_description box = solid_box(unit_box, box_mass, {0, 0, unit_box.z},
                                   about_axis({0, 0, 1}, yaw_degrees * pi / 180), mu);
  box.velocity = {speed, 0, 0};
  s.bodies.push_back(box);
  return s;
}

scene box_tower(int count, double mu) {
  scene s = floor_scene("tower of " + number(count), mu);
  for (int i = 0; i < count; ++i) {
    s.bodies.push_back(solid_box(unit_box, box_mass, {0, 0, unit_box.z * (2 * i + 1)}, {}, mu));
  }
  return s;
}

scene box_pyramid(int base, double gap, double mu) {
  scene s = floor_scene("pyramid of " + number(base) + ", gap " + number(1000 * gap) + " mm", mu);
  const double pitch = 2 * unit_box.x + gap;
  for (int row = 0; row < base; ++row) {
    const int count = base - row;
    for (int i = 0; i < count; ++i) {
      const double x = (i - (count - 1) / 2.0) * pitch;
      s.bodies.push_back(solid_box(unit_box, box_mass, {x, 0, unit_box.z * (2 * row + 1)}, {}, mu));
    }
  }
  return s;
}

scene falling_boxes(int count, double mu, unsigned seed) {
  // M6's pattern (gaphys::scenes::falling_spheres_in_box), r the circumradius.
  constexpr vec3 half{0.25, 0.25, 0.25};
  const double r = norm(half), spacing = 3 * r;
  const int side = std::max(1, static_cast<int>(std::ceil(std::sqrt(count / 4.0))));
  const double half_width = side * spacing / 2;
  scene s = floor_scene("N " + number(count), mu);
  s.planes.push_back({{1, 0, 0}, -half_width, 0, mu});
  s.planes.push_back({{-1, 0, 0}, -half_width, 0, mu});
  s.planes.push_back({{0, 1, 0}, -half_width, 0, mu});
  s.planes.push_back({{0, -1, 0}, -half_width, 0, mu});
  std::mt19937_64 random(seed);
  for (int i = 0; i < count; ++i) {
    const int layer = i / (side * side), row = (i / side) % side, column = i % side;
    const vec3 cell{-half_width + (column + 0.5) * spacing, -half_width + (row + 0.5) * spacing,
                    2 * r + layer * spacing};
    const vec3 shake{symmetric_unit(random), symmetric_unit(random), symmetric_unit(random)};
    body_description box =
        solid_box(half, box_mass, cell + (r / 4) * shake, random_attitude(random), mu);
    box.velocity = 0.5 * shake;
    s.bodies.push_back(box);
  }
  return s;
}

}  // namespace gaphys_compare
