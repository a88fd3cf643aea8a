#include "gaphys/scenes.hpp"

#include <algorithm>
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

shape with_material(const shape& s, const material& m) {
  return s.with_restitution(m.restitution)
      .with_friction(m.friction)
      .with_rolling_resistance(m.rolling_resistance)
      .with_spinning_friction(m.spinning_friction);
}

void add_static_plane(world& w, const vector& normal, real offset, const material& m) {
  body_definition floor;
  floor.is_static = true;
  floor.shape = with_material(shape::plane(normal, offset), m);
  w.create_body(floor);
}

// A floor at z = 0 and walls at x, y = ±half_width; each plane's solid side is
// outside the box.
void add_open_box(world& w, real half_width, const material& m) {
  add_static_plane(w, vector{0, 0, 1}, 0, m);
  add_static_plane(w, vector{1, 0, 0}, -half_width, m);
  add_static_plane(w, vector{-1, 0, 0}, -half_width, m);
  add_static_plane(w, vector{0, 1, 0}, -half_width, m);
  add_static_plane(w, vector{0, -1, 0}, -half_width, m);
}

body_id add_sphere(world& w, const vector& position, real radius, const material& m,
                   const vector& velocity = vector{}, const bivector& spin = bivector{}) {
  body_definition ball;
  ball.mass = 1;
  ball.position = position;
  ball.velocity = velocity;
  ball.angular_velocity = spin;
  ball.shape = with_material(shape::sphere(radius), m);
  return w.create_body(ball);
}

// Restitution e and friction μ, no rolling or spinning resistance.
material surface(real restitution, real friction) { return {restitution, friction, 0, 0}; }

// A dynamic body of one shape at rest, 1 kg unless told.
body_id add_solid(world& w, const shape& s, const vector& position, const material& m,
                  const rotor& attitude = rotor{1, 0, 0, 0}, real mass = 1) {
  body_definition solid;
  solid.mass = mass;
  solid.position = position;
  solid.attitude = attitude;
  solid.shape = with_material(s, m);
  return w.create_body(solid);
}

// The turn by `angle` (rad) that takes e3 towards e1 (about +e2): with
// B = e31 = -e13, R = cos(angle/2) - B sin(angle/2).
rotor turn_e3_towards_e1(real angle) {
  return rotor{std::cos(angle / 2), 0, std::sin(angle / 2), 0};
}

constexpr real degree = real(3.14159265358979323846) / 180;

}  // namespace

world falling_spheres_in_box(int count, std::uint64_t seed, real friction,
                             real rolling_resistance) {
  constexpr real radius = real(0.1), spacing = 3 * radius;
  material m = surface(real(0.3), friction);
  m.rolling_resistance = rolling_resistance;
  const int side = std::max(1, static_cast<int>(std::ceil(std::sqrt(real(count) / 4))));
  const real half_width = side * spacing / 2;
  world w;
  add_open_box(w, half_width, m);
  jitter random(seed);
  for (int i = 0; i < count; ++i) {
    const int layer = i / (side * side), row = (i / side) % side, column = i % side;
    const vector cell{-half_width + (column + real(0.5)) * spacing,
                      -half_width + (row + real(0.5)) * spacing, 2 * radius + layer * spacing};
    const vector shake{random.next(), random.next(), random.next()};
    add_sphere(w, cell + (radius / 4) * shake, radius, m, real(0.5) * shake);
  }
  return w;
}

world falling_boxes_in_box(int count, std::uint64_t seed, real friction) {
  const vector half{real(0.25), real(0.25), real(0.25)};
  const real radius = e3ga::norm(half), spacing = 3 * radius;
  const material m = surface(0, friction);
  const int side = std::max(1, static_cast<int>(std::ceil(std::sqrt(real(count) / 4))));
  const real half_width = side * spacing / 2;
  world w;
  add_open_box(w, half_width, m);
  jitter random(seed);
  const shape cube = shape::box(half);
  for (int i = 0; i < count; ++i) {
    const int layer = i / (side * side), row = (i / side) % side, column = i % side;
    const vector cell{-half_width + (column + real(0.5)) * spacing,
                      -half_width + (row + real(0.5)) * spacing, 2 * radius + layer * spacing};
    const vector shake{random.next(), random.next(), random.next()};
    // An attitude from four jitters: a rotor normalized (not uniform over
    // the turns, which the scene does not need).
    rotor turn{random.next(), random.next(), random.next(), random.next()};
    turn = turn / e3ga::norm(turn);
    const body_id box = add_solid(w, cube, cell + (radius / 4) * shake, m, turn);
    w.at(box).set_velocity(real(0.5) * shake);
  }
  return w;
}

world sphere_column(int count, real radius, real friction) {
  world w;
  const material m = surface(0, friction);
  add_open_box(w, real(1.02) * radius, m);
  for (int i = 0; i < count; ++i) {
    add_sphere(w, vector{0, 0, radius + i * (2 * radius + real(0.01))}, radius, m);
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
  light.shape = shape::sphere(real(0.5)).with_restitution(1).with_friction(0);
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
  add_static_plane(w, vector{0, 0, 1}, 0, surface(restitution, 0));
  add_sphere(w, vector{0, 0, real(0.5) + drop_height}, real(0.5), surface(restitution, 0));
  return w;
}

world sphere_on_floor(const vector& velocity, const bivector& spin, const material& m) {
  world w;
  add_static_plane(w, vector{0, 0, 1}, 0, m);
  add_sphere(w, vector{0, 0, real(0.5)}, real(0.5), m, velocity, spin);
  return w;
}

world sphere_on_incline(real angle, real friction) {
  world w;
  const material m = surface(0, friction);
  const vector normal{-std::sin(angle), 0, std::cos(angle)};
  add_static_plane(w, normal, 0, m);
  add_sphere(w, real(0.5) * normal, real(0.5), m);
  return w;
}

world rolling_ramp() {
  world w;
  const real angle = real(3.14159265358979323846) / 9;  // 20°
  const material m = surface(0, real(0.5));
  const vector normal{std::sin(angle), 0, std::cos(angle)};
  add_static_plane(w, normal, 0, m);         // the ramp, falling towards +x to the floor
  add_static_plane(w, vector{0, 0, 1}, 0, m);  // the floor, from x = 0 on
  const real start = -3;                     // x of the contact point on the ramp
  add_sphere(w, vector{start, 0, -std::tan(angle) * start} + real(0.5) * normal, real(0.5), m);
  return w;
}

world newtons_cradle(int released, int count, real speed) {
  world_settings settings;
  settings.gravity = vector{};
  world w(settings);
  const material m = surface(1, 0);
  for (int i = 0; i < count; ++i) {
    add_sphere(w, vector{real(i) - count + 1, 0, 0}, real(0.5), m,
               i < released ? vector{speed, 0, 0} : vector{});
  }
  // The released balls start touching the row: a gap of 1e-9 m, closed in the
  // first step.
  for (int i = 0; i < released; ++i) {
    body& ball = w.at(static_cast<body_id>(i));
    ball.set_position(ball.position() - vector{real(1e-9), 0, 0});
  }
  return w;
}

world sphere_gas(int count, std::uint64_t seed, real speed) {
  world_settings settings;
  settings.gravity = vector{};
  settings.restitution_threshold = 0;
  world w(settings);
  constexpr real half_width = 2, radius = real(0.1);
  const material m = surface(1, 0);
  add_open_box(w, half_width, m);
  add_static_plane(w, vector{0, 0, -1}, -2 * half_width, m);  // the lid, 4 m up
  // On a grid 0.4 m apart inside the box, each ball shaken by up to 0.1 m and
  // sent in a random direction.
  const int side = static_cast<int>(std::ceil(std::cbrt(real(count))));
  const real spacing = 2 * half_width / side;
  jitter random(seed);
  for (int i = 0; i < count; ++i) {
    const int layer = i / (side * side), row = (i / side) % side, column = i % side;
    const vector cell{-half_width + (column + real(0.5)) * spacing,
                      -half_width + (row + real(0.5)) * spacing, (layer + real(0.5)) * spacing};
    const vector shake{random.next(), random.next(), random.next()};
    vector direction{random.next(), random.next(), random.next()};
    direction = direction / e3ga::norm(direction);
    add_sphere(w, cell + (spacing / 2 - radius) * real(0.5) * shake, radius, m, speed * direction);
  }
  return w;
}

world box_tower(int count, real friction) {
  world w;
  const material m = surface(0, friction);
  add_static_plane(w, vector{0, 0, 1}, 0, m);
  const shape cube = shape::box(vector{real(0.5), real(0.5), real(0.5)});
  for (int i = 0; i < count; ++i) add_solid(w, cube, vector{0, 0, real(0.5) + i}, m);
  return w;
}

world box_pyramid(int base) {
  world w;
  const material m = surface(0, real(0.5));
  add_static_plane(w, vector{0, 0, 1}, 0, m);
  const shape cube = shape::box(vector{real(0.5), real(0.5), real(0.5)});
  constexpr real spacing = real(1.05);  // centre to centre along a row: 5 cm gaps
  for (int row = 0; row < base; ++row) {
    const int in_row = base - row;
    for (int i = 0; i < in_row; ++i) {
      const real x = (i - real(in_row - 1) / 2) * spacing;
      add_solid(w, cube, vector{x, 0, real(0.5) + row}, m);
    }
  }
  return w;
}

world dominoes(int count) {
  world w;
  const material m = surface(0, real(0.5));
  add_static_plane(w, vector{0, 0, 1}, 0, m);
  const vector half{real(0.05), real(0.25), real(0.5)};
  const shape domino = shape::box(half);
  constexpr real spacing = real(0.5);
  // The first turns about its bottom edge on the +e1 side, which stays on the
  // floor: its centre is that edge plus the turned (-half.e1, 0, half.e3).
  // Past atan(0.05 / 0.5) = 5.7° its weight carries it on over.
  const real tip = 15 * degree;
  const vector edge{half.e1(), 0, 0};
  const vector to_centre{-half.e1() * std::cos(tip) + half.e3() * std::sin(tip), 0,
                         half.e1() * std::sin(tip) + half.e3() * std::cos(tip)};
  add_solid(w, domino, edge + to_centre, m, turn_e3_towards_e1(tip));
  for (int i = 1; i < count; ++i) add_solid(w, domino, vector{i * spacing, 0, half.e3()}, m);
  return w;
}

world compound_table() {
  world w;
  const material m = surface(0, real(0.5));
  add_static_plane(w, vector{0, 0, 1}, 0, m);
  // The table's frame has its origin at the centre of the top; the body's
  // origin then moves to the centre of mass, a little below.
  const vector top_half{real(0.75), real(0.45), real(0.03)};
  const vector leg_half{real(0.03), real(0.03), real(0.35)};
  body_definition table;
  table.mass = 10;
  table.shapes.push_back({with_material(shape::box(top_half), m), vector{}, rotor{1, 0, 0, 0}});
  const shape leg = with_material(shape::box(leg_half), m);
  const real leg_z = -(top_half.e3() + leg_half.e3());
  for (const real x : {real(-0.68), real(0.68)}) {
    for (const real y : {real(-0.38), real(0.38)}) {
      table.shapes.push_back({leg, vector{x, y, leg_z}, rotor{1, 0, 0, 0}});
    }
  }
  // Tilted by 3° in the e23 plane (about e1, the +e2 side up), so that the
  // feet on the -e2 side land first; the lowest foot starts 0.18 m up.
  const real tilt = 3 * degree;
  table.attitude = rotor{std::cos(tilt / 2), 0, 0, -std::sin(tilt / 2)};
  const real feet = top_half.e3() + 2 * leg_half.e3();  // below the top's centre
  table.position = vector{0, 0, feet + real(0.2)};
  w.create_body(table);
  // The cube's bottom 0.3 m above the top, off its centre.
  const real top_surface = table.position.e3() + top_half.e3();
  add_solid(w, shape::box(vector{real(0.2), real(0.2), real(0.2)}),
            vector{real(0.3), real(0.1), top_surface + real(0.3) + real(0.2)}, m);
  return w;
}

world shape_mix(int count, std::uint64_t seed) {
  world w;
  const material m = surface(real(0.2), real(0.5));
  constexpr real half_width = real(1.5), cell = real(0.75), layer_height = real(0.6);
  add_open_box(w, half_width, m);
  jitter random(seed);
  // Uniform in [low, high).
  const auto between = [&random](real low, real high) {
    return low + (high - low) * (random.next() + 1) / 2;
  };
  const int side = 3;  // cells a row: 3 x 3 a layer, well inside the walls
  for (int i = 0; i < count; ++i) {
    const int layer = i / (side * side), row = (i / side) % side, column = i % side;
    const vector position{(column - 1) * cell + between(real(-0.05), real(0.05)),
                          (row - 1) * cell + between(real(-0.05), real(0.05)),
                          real(0.5) + layer * layer_height};
    // A random rotor, made unit by the body.
    const rotor attitude{random.next(), random.next(), random.next(), random.next()};
    shape s = shape::sphere(between(real(0.1), real(0.2)));
    switch (i % 4) {
      case 0:
        s = shape::box(vector{between(real(0.08), real(0.22)), between(real(0.08), real(0.22)),
                              between(real(0.08), real(0.22))});
        break;
      case 1:
        s = shape::capsule(between(real(0.08), real(0.2)), between(real(0.07), real(0.12)));
        break;
      case 2: {
        // Points on an ellipsoid of random radii: a rounded, irregular stone.
        const vector radii{between(real(0.12), real(0.22)), between(real(0.12), real(0.22)),
                           between(real(0.1), real(0.18))};
        std::vector<vector> points;
        for (int k = 0; k < 10; ++k) {
          vector direction{random.next(), random.next(), random.next()};
          direction = direction / std::max(e3ga::norm(direction), real(1e-3));
          points.push_back(vector{radii.e1() * direction.e1(), radii.e2() * direction.e2(),
                                  radii.e3() * direction.e3()});
        }
        s = shape::convex_hull(points);
        break;
      }
      default:
        break;  // the sphere
    }
    add_solid(w, s, position, m, attitude);
  }
  return w;
}

const std::vector<entry>& catalogue() {
  static const std::vector<entry> scenes = {
      {"falling_spheres", "100 spheres falling into a box",
       [] { return falling_spheres_in_box(100); }},
      {"sphere_column", "5 spheres stacked in a tube", [] { return sphere_column(); }},
      {"elastic_collision", "two spheres, oblique elastic impact",
       [] { return elastic_collision(); }},
      {"spinning_body", "torque-free asymmetric body", [] { return spinning_body(); }},
      {"bouncing_sphere", "a sphere dropped 2 m, e = 0.8",
       [] { return bouncing_sphere(real(0.8)); }},
      {"rolling_ramp", "a ball rolls down a 20° ramp onto the floor",
       [] { return rolling_ramp(); }},
      {"cue_ball_backspin", "a ball struck low: slides, then rolls back",
       // Backspin: Ω = 20 e13 moves the ball's bottom forward at 10 m/s
       // (r ⌋ Ω with r = -0.5 e3) besides the ball's 3 m/s; as 2 r ω0 = 20
       // exceeds 5 v0 = 15, friction brings it back at (5 v0 - 2 r ω0) / 7.
       [] {
         return sphere_on_floor(vector{3, 0, 0}, bivector{0, 20, 0}, material{0, real(0.3), 0, 0});
       }},
      {"newtons_cradle", "two balls strike a row of three", [] { return newtons_cradle(2); }},
      {"friction_pile", "100 spheres falling into a box, friction 0.5",
       [] { return falling_spheres_in_box(100, 1, real(0.5)); }},
      {"box_tower", "10 unit cubes stacked on a floor, friction 0.5", [] { return box_tower(); }},
      {"box_pyramid", "55 unit cubes in a pyramid, 10 at the base", [] { return box_pyramid(); }},
      {"dominoes", "20 dominoes in a row, the first tipped over", [] { return dominoes(); }},
      {"compound_table", "a table of five boxes (one body) dropped, a cube onto it",
       [] { return compound_table(); }},
      {"shape_mix", "boxes, capsules, convex hulls and spheres dropped into a box",
       [] { return shape_mix(); }},
  };
  return scenes;
}

}  // namespace gaphys::scenes
