// gaphys's vectors, rotors and bivectors to and from the harness's neutral
// vec3 and quat (vec3.hpp), for the gaphys adapter and the scenes taken
// from gaphys's own (scenes.cpp).
#pragma once

#include "gaphys/algebra.hpp"
#include "vec3.hpp"

namespace gaphys_compare {

// (The scenes are double; a float engine takes the nearest floats.)
inline gaphys::vector to_gaphys(const vec3& v) {
  using gaphys::real;
  return {real(v.x), real(v.y), real(v.z)};
}
inline vec3 to_vec3(const gaphys::vector& v) { return {v.c[0], v.c[1], v.c[2]}; }

// Rotation by θ about the unit axis n: R = cos(θ/2) - sin(θ/2) n I, where
// n I = nx e23 + ny e31 + nz e12 (docs/engine.md's pairing of planes and
// axes). The quaternion is cos(θ/2) + sin(θ/2) n, so with R's coordinates
// (1, e12, e13, e23) and e31 = -e13: x = -e23, y = e13, z = -e12. |q| is
// then sqrt(R ~R), the rotor's norm.
inline quat to_quat(const gaphys::rotor& r) { return {r.c[0], -r.c[3], r.c[2], -r.c[1]}; }

// The inverse of to_quat: (w, x, y, z) -> (w, e12 = -z, e13 = y, e23 = -x).
inline gaphys::rotor to_rotor(const quat& q) {
  using gaphys::real;
  return {real(q.w), real(-q.z), real(q.y), real(-q.x)};
}

// gaphys keeps angular velocity as a bivector Ω = ωx e23 + ωy e31 + ωz e12
// (docs/engine.md); its coordinates are (e12, e13, e23) and e31 = -e13.
inline gaphys::bivector to_bivector(const vec3& w) {
  using gaphys::real;
  return {real(w.z), real(-w.y), real(w.x)};
}
inline vec3 axis_of(const gaphys::bivector& b) { return {b.c[2], -b.c[1], b.c[0]}; }

}  // namespace gaphys_compare
