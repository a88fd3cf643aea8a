#include "gaphys/conversions.hpp"

#include <algorithm>
#include <cmath>

#include "validate.hpp"

namespace gaphys {

namespace {

// The quaternion of the same turn as R, by the mapping derived in
// conversions.hpp: w = R.scalar, x = -R.e23, y = R.e13, z = -R.e12.
quaternion quaternion_of(const rotor& r) { return {r.c[0], -r.c[3], r.c[2], -r.c[1]}; }

// The unit quaternion along q. Dividing by the largest component first keeps
// the squares from overflowing or underflowing: any finite nonzero q has a
// direction.
quaternion unit(const quaternion& q, const char* what) {
  const real parts[] = {q.w, q.x, q.y, q.z};
  for (real p : parts) {
    if (!std::isfinite(p)) {
      detail::reject(what, " must be finite (got w ", q.w, ", x ", q.x, ", y ", q.y, ", z ", q.z,
                     ")");
    }
  }
  real largest = 0;
  for (real p : parts) largest = std::max(largest, std::abs(p));
  if (!(largest > 0)) detail::reject(what, " must be nonzero");
  const quaternion s{q.w / largest, q.x / largest, q.y / largest, q.z / largest};
  const real length = std::sqrt(s.w * s.w + s.x * s.x + s.y * s.y + s.z * s.z);
  return {s.w / length, s.x / length, s.y / length, s.z / length};
}

quaternion unit_quaternion_of(const rotor& r) {
  detail::require_finite(r, "rotor");
  return unit(quaternion_of(r), "rotor");
}

// The rotation matrix of a unit quaternion: column j is q e_j q*, expanded
// with w² + x² + y² + z² = 1 on the diagonal.
matrix3 matrix_of(const quaternion& q) {
  const real w = q.w, x = q.x, y = q.y, z = q.z;
  // One row of the matrix per line.
  // clang-format off
  return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
          2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
          2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
  // clang-format on
}

// Orthonormal rows within the tolerance, and no reflection. Orthonormal rows
// put the determinant within about 1.5 tolerances of ±1, so its sign is what
// is left to check.
void require_rotation(const matrix3& m) {
  for (int k = 0; k < 9; ++k) {
    if (!std::isfinite(m[k])) {
      detail::reject("rotation matrix must be finite (got ", m[k], " at row ", k / 3, ", column ",
                     k % 3, ")");
    }
  }
  real worst = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const real dot =
          m[3 * i] * m[3 * j] + m[3 * i + 1] * m[3 * j + 1] + m[3 * i + 2] * m[3 * j + 2];
      worst = std::max(worst, std::abs(dot - (i == j ? 1 : 0)));
    }
  }
  if (!(worst <= rotation_matrix_tolerance)) {
    detail::reject("rotation matrix is not orthonormal: M M^T - 1 has an entry of ", worst,
                   " (tolerance ", rotation_matrix_tolerance, ")");
  }
  const real det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
                   m[2] * (m[3] * m[7] - m[4] * m[6]);
  if (!(det > 0)) {
    detail::reject("rotation matrix has determinant ", det, ", not +1: it is a reflection");
  }
}

// Shepperd's method. With the matrix of q (matrix_of above), the diagonal and
// trace give the four squares
//   4 w² = 1 + m00 + m11 + m22,   4 x² = 1 + m00 - m11 - m22,
//   4 y² = 1 - m00 + m11 - m22,   4 z² = 1 - m00 - m11 + m22,
// and the off-diagonal pairs the six products
//   4 w x = m21 - m12,  4 w y = m02 - m20,  4 w z = m10 - m01,
//   4 x y = m01 + m10,  4 x z = m02 + m20,  4 y z = m12 + m21.
// The largest square is at least 1/4 (the four sum to 4), so taking its root
// and dividing the three products that hold it never divides by a small number.
quaternion quaternion_of(const matrix3& m) {
  require_rotation(m);
  const real squares[] = {1 + m[0] + m[4] + m[8], 1 + m[0] - m[4] - m[8], 1 - m[0] + m[4] - m[8],
                          1 - m[0] - m[4] + m[8]};
  const int largest = static_cast<int>(std::max_element(squares, squares + 4) - squares);
  const real twice = std::sqrt(squares[largest]);  // twice the component, >= 1
  const real f = 1 / (2 * twice);                  // turns a product into the other factor
  quaternion q;
  switch (largest) {
    case 0:
      q = {twice / 2, (m[7] - m[5]) * f, (m[2] - m[6]) * f, (m[3] - m[1]) * f};
      break;
    case 1:
      q = {(m[7] - m[5]) * f, twice / 2, (m[1] + m[3]) * f, (m[2] + m[6]) * f};
      break;
    case 2:
      q = {(m[2] - m[6]) * f, (m[1] + m[3]) * f, twice / 2, (m[5] + m[7]) * f};
      break;
    default:
      q = {(m[3] - m[1]) * f, (m[2] + m[6]) * f, (m[5] + m[7]) * f, twice / 2};
      break;
  }
  // A matrix off a rotation by up to the tolerance gives a q off unit length.
  return unit(q, "rotation matrix");
}

}  // namespace

quaternion to_quaternion(const rotor& attitude) { return unit_quaternion_of(attitude); }

rotor to_rotor(const quaternion& q) {
  const quaternion u = unit(q, "quaternion");
  return rotor{u.w, -u.z, u.y, -u.x};
}

matrix3 to_matrix(const rotor& attitude) { return matrix_of(unit_quaternion_of(attitude)); }

matrix3 to_matrix(const quaternion& q) { return matrix_of(unit(q, "quaternion")); }

rotor to_rotor(const matrix3& rotation) {
  const quaternion q = quaternion_of(rotation);
  return rotor{q.w, -q.z, q.y, -q.x};
}

quaternion to_quaternion(const matrix3& rotation) { return quaternion_of(rotation); }

vector to_axial(const bivector& plane) {
  detail::require_finite(plane, "bivector");
  return vector{plane.c[2], -plane.c[1], plane.c[0]};
}

bivector to_bivector(const vector& axial) {
  detail::require_finite(axial, "axial vector");
  return bivector{axial.c[2], -axial.c[1], axial.c[0]};
}

}  // namespace gaphys
