// The harness's own small vector and quaternion, in double. Every engine's
// state is read into these types, so one piece of code measures all engines.
#pragma once

#include <cmath>

namespace gaphys_compare {

struct vec3 {
  double x = 0, y = 0, z = 0;
};

inline vec3 operator+(const vec3& a, const vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline vec3 operator-(const vec3& a, const vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline vec3 operator*(double s, const vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(const vec3& a, const vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double norm(const vec3& a) { return std::sqrt(dot(a, a)); }
inline vec3 cross(const vec3& a, const vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Attitude as a quaternion w + x i + y j + z k, mapping body to world.
// Adapters hand it over as the engine keeps it, so its norm shows how well
// the engine keeps it normalized.
struct quat {
  double w = 1, x = 0, y = 0, z = 0;
};

inline double norm(const quat& q) {
  return std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
}

// v rotated by q / |q|: v + 2 w (u × v) + 2 u × (u × v), u = (x, y, z), on
// the normalized q, so a drift of |q| does not leak into what is measured
// from the rotation.
inline vec3 rotate(const quat& q, const vec3& v) {
  const double n = norm(q);
  const vec3 u{q.x / n, q.y / n, q.z / n};
  const double w = q.w / n;
  const vec3 t = 2 * cross(u, v);
  return v + w * t + cross(u, t);
}

inline quat conjugate(const quat& q) { return {q.w, -q.x, -q.y, -q.z}; }

// The rotation by angle (rad) about the unit axis: cos(angle/2) + sin(angle/2) axis.
inline quat about_axis(const vec3& axis, double angle) {
  const double s = std::sin(angle / 2);
  return {std::cos(angle / 2), s * axis.x, s * axis.y, s * axis.z};
}

// a b: b's rotation first, then a's.
inline quat operator*(const quat& a, const quat& b) {
  return {
      a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
      a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

// The angle (rad, in [0, pi]) between two nonzero vectors, accurate near 0
// where acos of the cosine is not.
inline double angle_between(const vec3& a, const vec3& b) {
  return std::atan2(norm(cross(a, b)), dot(a, b));
}

}  // namespace gaphys_compare
