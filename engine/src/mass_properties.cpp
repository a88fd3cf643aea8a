// Mass properties of uniform solids, in closed form. Each shape's are worked
// out at unit density in its own frame (volume, centroid, inertia about the
// centroid), then scaled by the density, turned and moved to its pose.
#include "gaphys/mass_properties.hpp"

#include <array>

#include "validate.hpp"

namespace gaphys {

namespace {

using matrix = std::array<real, 9>;  // row-major, about the x, y, z axes

using detail::pi;

// A solid of unit density: its volume, centroid and inertia about the centroid.
struct unit_solid {
  real volume;
  vector center;
  matrix inertia;
};

matrix diagonal(real x, real y, real z) { return {x, 0, 0, 0, y, 0, 0, 0, z}; }

unit_solid sphere(real r) {
  const real v = 4 * pi * r * r * r / 3;
  const real moment = real(0.4) * v * r * r;
  return {v, vector{}, diagonal(moment, moment, moment)};
}

unit_solid box(const vector& h) {
  const real a2 = h.e1() * h.e1(), b2 = h.e2() * h.e2(), c2 = h.e3() * h.e3();
  const real v = 8 * h.e1() * h.e2() * h.e3();
  return {v, vector{}, diagonal(v * (b2 + c2) / 3, v * (a2 + c2) / 3, v * (a2 + b2) / 3)};
}

// A cylinder of length 2h along z and a hemisphere on each end. A hemisphere
// has half a ball's moment about any axis through its flat face's centre,
// (2/5) m r^2, and its centroid is 3r/8 off that face. About a cross axis
// through the capsule's centre, h + 3r/8 away from that centroid:
//   (2/5) r^2 - (3r/8)^2 + (h + 3r/8)^2 = (2/5) r^2 + h^2 + (3/4) h r
// per unit of the hemisphere's mass.
unit_solid capsule(real h, real r) {
  const real cylinder = 2 * pi * r * r * h;
  const real hemisphere = 2 * pi * r * r * r / 3;
  const real about_axis = cylinder * r * r / 2 + 2 * hemisphere * real(0.4) * r * r;
  const real across = cylinder * (3 * r * r + 4 * h * h) / 12 +
                      2 * hemisphere * (real(0.4) * r * r + h * h + real(0.75) * h * r);
  return {cylinder + 2 * hemisphere, vector{}, diagonal(across, across, about_axis)};
}

// Sums over the tetrahedra that join a point p inside to each face's
// triangle fan. For a tetrahedron with corners 0, a, b, c (relative to p) of
// signed volume V = a . (b x c) / 6:
//   integral of x dV       = V (a + b + c) / 4
//   integral of x x^T dV   = V / 20 (a a^T + b b^T + c c^T + s s^T), s = a + b + c
// The second moment C about the centroid gives the inertia tr(C) 1 - C.
unit_solid polyhedron(const convex_polyhedron& p) {
  real px = 0, py = 0, pz = 0;
  for (const vector& v : p.vertices) px += v.e1(), py += v.e2(), pz += v.e3();
  const real count = static_cast<real>(p.vertices.size());
  px /= count, py /= count, pz /= count;

  real volume = 0;
  std::array<real, 3> first{};
  matrix second{};
  auto relative = [&](std::uint32_t i) {
    const vector& v = p.vertices[i];
    return std::array<real, 3>{v.e1() - px, v.e2() - py, v.e3() - pz};
  };
  for (const polyhedron_face& f : p.faces) {
    const auto a = relative(p.vertex_indices[f.first]);
    for (std::uint32_t k = 1; k + 1 < f.count; ++k) {
      const auto b = relative(p.vertex_indices[f.first + k]);
      const auto c = relative(p.vertex_indices[f.first + k + 1]);
      const real v = (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
                      a[2] * (b[0] * c[1] - b[1] * c[0])) /
                     6;
      const std::array<real, 3> s{a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2]};
      volume += v;
      for (int i = 0; i < 3; ++i) {
        first[i] += v * s[i] / 4;
        for (int j = 0; j < 3; ++j) {
          second[3 * i + j] += v / 20 * (a[i] * a[j] + b[i] * b[j] + c[i] * c[j] + s[i] * s[j]);
        }
      }
    }
  }
  const std::array<real, 3> centroid{first[0] / volume, first[1] / volume, first[2] / volume};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) second[3 * i + j] -= volume * centroid[i] * centroid[j];
  }
  const real trace = second[0] + second[4] + second[8];
  matrix inertia;
  for (int i = 0; i < 9; ++i) inertia[i] = (i % 4 == 0 ? trace : 0) - second[i];
  return {volume, vector{px + centroid[0], py + centroid[1], pz + centroid[2]}, inertia};
}

unit_solid unit_solid_of(const shape& s) {
  switch (s.kind()) {
    case shape_kind::sphere:
      return sphere(s.radius());
    case shape_kind::box:
      return box(s.half_extents());
    case shape_kind::capsule:
      return capsule(s.half_height(), s.radius());
    case shape_kind::convex_hull:
      return polyhedron(*s.polyhedron());
    case shape_kind::plane:
    case shape_kind::point:
      break;
  }
  detail::reject("a plane or a point has no volume, so no solid mass properties");
}

// The unit solid of a shape whose mass properties real numbers can hold:
// a box of half extent 1e100 m has a volume of 8e300 m^3 but moments of
// 1e500, and one of 1e-160 m a volume of 0; either is rejected here, by
// name, rather than as a NaN or singular inertia tensor further on.
unit_solid solid_of(const shape& s) {
  const unit_solid unit = unit_solid_of(s);
  bool representable = std::isfinite(unit.volume) && unit.volume > 0;
  for (real x : unit.inertia) representable = representable && std::isfinite(x);
  for (int i = 0; i < 3; ++i) representable = representable && unit.inertia[4 * i] > 0;
  if (!representable) {
    detail::reject("a shape of bounding radius ", s.bounding_radius(),
                   " m is too large or too small for its volume and inertia to be real numbers "
                   "(volume ",
                   unit.volume, " m^3); rescale the scene or give the body an inertia");
  }
  return unit;
}

// The tensor as an inertia: symmetric to the last bit (rounding in M J M^T
// leaves it only nearly so).
gaphys::inertia inertia_of(const matrix& m) {
  matrix symmetric = m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < i; ++j) {
      symmetric[3 * i + j] = symmetric[3 * j + i] = (m[3 * i + j] + m[3 * j + i]) / 2;
    }
  }
  return inertia::tensor(symmetric);
}

}  // namespace

bool is_solid(const shape& s) {
  return s.kind() != shape_kind::plane && s.kind() != shape_kind::point;
}

real volume(const shape& s) { return is_solid(s) ? unit_solid_of(s).volume : 0; }

mass_properties solid_mass_properties(const shape& s, real density) {
  detail::require_positive(density, "density");
  const unit_solid unit = solid_of(s);
  matrix rows = unit.inertia;
  for (real& x : rows) x *= density;
  return {density * unit.volume, unit.center, inertia_of(rows)};
}

// Each part's tensor turns with its attitude, J' = M J M^T (the columns of M
// are R e_i ~R), and moves to the common centre c by the parallel-axis
// theorem, J_c = J' + m (|d|^2 1 - d d^T) with d the part's centre minus c.
mass_properties solid_mass_properties(const std::vector<attached_shape>& shapes, real density) {
  detail::require_positive(density, "density");
  struct part {
    real mass;
    vector center;
    matrix inertia;
  };
  std::vector<part> parts;
  real mass = 0;
  vector weighted{};
  for (const attached_shape& s : shapes) {
    detail::require_offset(s.offset, "shape offset");
    const rotor r = detail::unit_rotor(s.attitude, "shape attitude");
    if (!is_solid(s.shape) || s.shape.is_sensor()) continue;  // sensors add no mass
    const unit_solid unit = solid_of(s.shape);
    const vector columns[3] = {e3ga::apply(r, vector{1, 0, 0}), e3ga::apply(r, vector{0, 1, 0}),
                               e3ga::apply(r, vector{0, 0, 1})};
    matrix m;
    for (int j = 0; j < 3; ++j) {
      m[j] = columns[j].e1(), m[3 + j] = columns[j].e2(), m[6 + j] = columns[j].e3();
    }
    matrix turned{};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        for (int k = 0; k < 3; ++k) {
          for (int l = 0; l < 3; ++l) {
            turned[3 * i + j] += m[3 * i + k] * unit.inertia[3 * k + l] * m[3 * j + l];
          }
        }
      }
    }
    const real part_mass = density * unit.volume;
    for (real& x : turned) x *= density;
    const vector center = s.offset + e3ga::apply(r, unit.center);
    parts.push_back({part_mass, center, turned});
    mass += part_mass;
    weighted = weighted + part_mass * center;
  }
  if (parts.empty()) {
    detail::reject(
        "solid mass properties need a solid shape (planes and points have no volume, sensors no mass)");
  }
  // (A density of 1e-310 gave a NaN centre, reported as a NaN inertia tensor entry.)
  if (!(mass > 0) || !std::isfinite(mass) || !std::isfinite(1 / mass)) {
    detail::reject("density ", density, " kg/m^3 gives these shapes a mass of ", mass,
                   " kg, too small or too large to invert in real numbers");
  }
  const vector center = weighted / mass;
  matrix total{};
  for (const part& p : parts) {
    const vector d = p.center - center;
    const real dd[3] = {d.e1(), d.e2(), d.e3()};
    const real d2 = e3ga::scp(d, d);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        total[3 * i + j] += p.inertia[3 * i + j] + p.mass * ((i == j ? d2 : 0) - dd[i] * dd[j]);
      }
    }
  }
  return {mass, center, inertia_of(total)};
}

}  // namespace gaphys
