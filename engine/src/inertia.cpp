#include "gaphys/inertia.hpp"

#include <cmath>

#include "precision.hpp"
#include "validate.hpp"

namespace gaphys {

namespace {

using matrix = std::array<real, 9>;

real determinant(const matrix& m) {
  return m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
         m[2] * (m[3] * m[7] - m[4] * m[6]);
}

// The inverse of a symmetric positive definite 3x3 matrix, by its adjugate.
matrix inverse_of(const matrix& m) {
  const real inv_det = 1 / determinant(m);
  return {(m[4] * m[8] - m[5] * m[7]) * inv_det, (m[2] * m[7] - m[1] * m[8]) * inv_det,
          (m[1] * m[5] - m[2] * m[4]) * inv_det, (m[5] * m[6] - m[3] * m[8]) * inv_det,
          (m[0] * m[8] - m[2] * m[6]) * inv_det, (m[2] * m[3] - m[0] * m[5]) * inv_det,
          (m[3] * m[7] - m[4] * m[6]) * inv_det, (m[1] * m[6] - m[0] * m[7]) * inv_det,
          (m[0] * m[4] - m[1] * m[3]) * inv_det};
}

}  // namespace

inertia::inertia(const matrix& rows, const matrix& inverse)
    : tensor_(rows),
      inverse_(inverse),
      isotropic_(rows[1] == 0 && rows[2] == 0 && rows[3] == 0 && rows[5] == 0 && rows[6] == 0 &&
                 rows[7] == 0 && rows[0] == rows[4] && rows[0] == rows[8]) {}

inertia inertia::tensor(const matrix& m) {
  for (real x : m) detail::require_finite(x, "inertia tensor entry");
  const real scale = std::fabs(m[0]) + std::fabs(m[4]) + std::fabs(m[8]);
  const real tolerance = detail::by_precision(1e-12, 1e-5) * scale;
  if (std::fabs(m[1] - m[3]) > tolerance || std::fabs(m[2] - m[6]) > tolerance ||
      std::fabs(m[5] - m[7]) > tolerance) {
    detail::reject("inertia tensor must be symmetric");
  }
  // Sylvester's criterion (all leading principal minors positive) and the
  // inverse, on the tensor scaled by a power of two near 1 / its trace: the
  // moments of a 1 mm cube of 1 g, 2e-10 kg m^2, have a determinant of 5e-30,
  // and at the unit density the shapes' moments are first computed at, 5e-48,
  // below a float's least number. (A power of two scales exactly: where
  // nothing underflows the inverse has the same bits as unscaled.)
  int exponent = 0;
  std::frexp(scale, &exponent);
  matrix unit;
  for (int i = 0; i < 9; ++i) unit[i] = std::ldexp(m[i], -exponent);
  if (!(unit[0] > 0) || !(unit[0] * unit[4] - unit[1] * unit[3] > 0) || !(determinant(unit) > 0)) {
    detail::reject("inertia tensor must be positive definite");
  }
  matrix inverse = inverse_of(unit);
  for (real& x : inverse) x = std::ldexp(x, -exponent);
  for (real x : inverse) {
    if (!std::isfinite(x)) {
      detail::reject(
          "inertia tensor of trace ", scale,
          " kg m^2 is too small or too large to invert in real numbers; rescale the scene");
    }
  }
  return inertia(m, inverse);
}

inertia inertia::principal(real about_x, real about_y, real about_z) {
  detail::require_positive(about_x, "inertia about x");
  detail::require_positive(about_y, "inertia about y");
  detail::require_positive(about_z, "inertia about z");
  return tensor({about_x, 0, 0, 0, about_y, 0, 0, 0, about_z});
}

inertia inertia::solid_sphere(real mass, real radius) {
  detail::require_positive(mass, "mass");
  detail::require_positive(radius, "radius");
  const real moment = real(0.4) * mass * radius * radius;
  return principal(moment, moment, moment);
}

inertia inertia::solid_box(real mass, real half_x, real half_y, real half_z) {
  detail::require_positive(mass, "mass");
  detail::require_positive(half_x, "box half extent x");
  detail::require_positive(half_y, "box half extent y");
  detail::require_positive(half_z, "box half extent z");
  const real x2 = half_x * half_x, y2 = half_y * half_y, z2 = half_z * half_z;
  return principal(mass * (y2 + z2) / 3, mass * (x2 + z2) / 3, mass * (x2 + y2) / 3);
}

// The rotation in plane e23 is about x, in e31 = -e13 about y, in e12 about z.
bivector inertia::apply(const matrix& m, const bivector& b) {
  const real x = b.e23(), y = -b.e13(), z = b.e12();
  const real lx = m[0] * x + m[1] * y + m[2] * z;
  const real ly = m[3] * x + m[4] * y + m[5] * z;
  const real lz = m[6] * x + m[7] * y + m[8] * z;
  return bivector{lz, -ly, lx};
}

}  // namespace gaphys
