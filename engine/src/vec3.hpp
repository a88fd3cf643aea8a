// Vector arithmetic written out, for the convex narrow phase's inner loops.
//
// The algebra's own calls go through the generic multivector in the
// reference variant and are counted one by one in the instrumented one; a
// separating-axis test makes hundreds of dot products per pair of boxes, so
// its loops use this plain triple and convert at their edges. Every variant
// then computes the same floating-point operations, in the same order.
#pragma once

#include <cmath>

#include "gaphys/algebra.hpp"

namespace gaphys::detail {

struct vec3 {
  real x = 0, y = 0, z = 0;
};

inline vec3 to_vec3(const vector& v) { return {v.c[0], v.c[1], v.c[2]}; }
inline vector to_vector(const vec3& v) { return {v.x, v.y, v.z}; }

inline vec3 operator+(const vec3& a, const vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline vec3 operator-(const vec3& a, const vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline vec3 operator-(const vec3& a) { return {-a.x, -a.y, -a.z}; }
inline vec3 operator*(real s, const vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline real dot(const vec3& a, const vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
// a × b, the dual of a ∧ b (I3 = e1 e2 e3): a ∧ b = (a × b) I3.
inline vec3 cross(const vec3& a, const vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline real length(const vec3& a) { return std::sqrt(dot(a, a)); }

// A rigid frame as a rotation matrix and an origin: x_world = origin + M x.
// M's columns are R e_i ~R, written out from the rotor's coefficients.
struct rigid_frame {
  vec3 column[3];
  vec3 origin;

  vec3 rotate(const vec3& v) const { return v.x * column[0] + v.y * column[1] + v.z * column[2]; }
  // Mᵀ v: M is orthogonal, so this undoes rotate().
  vec3 unrotate(const vec3& v) const {
    return {dot(column[0], v), dot(column[1], v), dot(column[2], v)};
  }
  vec3 to_world(const vec3& v) const { return origin + rotate(v); }
  vec3 to_local(const vec3& v) const { return unrotate(v - origin); }
};

// The frame of x -> origin + R x ~R. With R = s + b12 e12 + b13 e13 + b23
// e23 (s² + b12² + b13² + b23² = 1), R e1 ~R, R e2 ~R and R e3 ~R expand to
// the columns below (the sandwich of a vector by a rotor, term by term).
inline rigid_frame frame_of(const rotor& r, const vector& origin) {
  const real s = r.c[0], a = r.c[1], b = r.c[2], c = r.c[3];  // a = b12, b = b13, c = b23
  rigid_frame f;
  f.column[0] = {s * s - a * a - b * b + c * c, -2 * (s * a + b * c), 2 * (a * c - s * b)};
  f.column[1] = {2 * (s * a - b * c), s * s - a * a + b * b - c * c, -2 * (s * c + a * b)};
  f.column[2] = {2 * (s * b + a * c), 2 * (s * c - a * b), s * s + a * a - b * b - c * c};
  f.origin = to_vec3(origin);
  return f;
}

}  // namespace gaphys::detail
