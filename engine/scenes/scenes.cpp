#include "gaphys/scenes.hpp"

#include <cmath>

namespace gaphys::scenes {

namespace {

// splitmix64: a small deterministic generator, identical on every platform.
class jitter {
 public:
  explicit jitter(std::uint64_t seed) : state_(seed) {}
  // Uniform in [-1, 1).
  real next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return real(z >> 11) * 0x1.0p-52 - 1;
  }

 private:
  std::uint64_t state_;
};

void add_static_plane(world& w, const vector& normal, real offset, real restitution) {
  body_definition floor;
  floor.is_static = true;
  floor.shape = shape::plane(normal, offset).with_restitution(restitution);
  w.create_body(floor);
}

// A floor at z = 0 and walls at x, y = ±half_width; each plane's solid side is
// outside the box.
void add_box(world& w, real half_width, real restitution) {
  add_static_plane(w, vector{0, 0, 1}, 0, restitution);
  add_static_plane(w, vector{1, 0, 0}, -half_width, restitution);
  add_static_plane(w, vector{-1, 0, 0}, -half_width, restitution);
  add_static_plane(w, vector{0, 1, 0}, -half_width, restitution);
  add_static_plane(w, vector{0, -1, 0}, -half_width, restitution);
}

body_id add_sphere(world& w, const vector& position, real radius, real restitution,
                   const vector& velocity = vector{}) {
  body_definition ball;
  ball.mass = 1;
  ball.position = position;
  ball.velocity = velocity;
  ball.shape = shape::sphere(radius).with_restitution(restitution);
  return w.create_body(ball);
}

}  // namespace

world falling_spheres_in_box(int count, std::uint64_t seed) {
  constexpr real radius = real(0.1), restitution = real(0.3), spacing = 3 * radius;
  const int side = std::max(1, static_cast<int>(std::ceil(std::sqrt(real(count) / 4))));
  const real half_width = side * spacing / 2;
  world w;
  add_box(w, half_width, restitution);
  jitter random(seed);
  for (int i = 0; i < count; ++i) {
    const int layer = i / (side * side), row = (i / side) % side, column = i % side;
    const vector cell{-half_width + (column + real(0.5)) * spacing,
                      -half_width + (row + real(0.5)) * spacing, 2 * radius + layer * spacing};
    const vector shake{random.next(), random.next(), random.next()};
    add_sphere(w, cell + (radius / 4) * shake, radius, restitution, real(0.5) * shake);
  }
  return w;
}

world sphere_column(int count, real radius) {
  world w;
  add_box(w, real(1.02) * radius, 0);
  for (int i = 0; i < count; ++i) {
    add_sphere(w, vector{0, 0, radius + i * (2 * radius + real(0.01))}, radius, 0);
  }
  return w;
}

world elastic_collision(real offset) {
  world_settings settings;
  settings.gravity = vector{};
  world w(settings);
  body_definition light;
  light.mass = 1;
  light.position = vector{-2, 0, 0};
  light.velocity = vector{3, 0, 0};
  light.shape = shape::sphere(real(0.5)).with_restitution(1);
  w.create_body(light);
  body_definition heavy = light;
  heavy.mass = 2;
  heavy.position = vector{2, offset, 0};
  heavy.velocity = vector{-1, 0, 0};
  w.create_body(heavy);
  return w;
}

world spinning_body() {
  world_settings settings;
  settings.gravity = vector{};
  world w(settings);
  body_definition spinner;
  spinner.mass = 1;
  spinner.inertia = inertia::principal(1, 2, 3);
  // About x is the e23 plane, about y e31 = -e13, about z e12.
  spinner.angular_velocity = bivector{3, -2, 1};
  w.create_body(spinner);
  return w;
}

world bouncing_sphere(real restitution, real drop_height) {
  world w;
  add_static_plane(w, vector{0, 0, 1}, 0, restitution);
  add_sphere(w, vector{0, 0, real(0.5) + drop_height}, real(0.5), restitution);
  return w;
}

const std::vector<entry>& catalogue() {
  static const std::vector<entry> scenes = {
      {"falling_spheres", "100 spheres falling into a box", [] { return falling_spheres_in_box(100); }},
      {"sphere_column", "5 spheres stacked in a tube", [] { return sphere_column(); }},
      {"elastic_collision", "two spheres, oblique elastic impact", [] { return elastic_collision(); }},
      {"spinning_body", "torque-free asymmetric body", [] { return spinning_body(); }},
      {"bouncing_sphere", "a sphere dropped 2 m, e = 0.8", [] { return bouncing_sphere(real(0.8)); }},
  };
  return scenes;
}

}  // namespace gaphys::scenes
