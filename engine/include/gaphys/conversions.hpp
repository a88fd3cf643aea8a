// Conversions between the engine's geometric algebra and the forms most
// applications think in: unit quaternions, 3x3 rotation matrices and axial
// vectors (docs/engine.md, "Conversions", has the whole table).
//
// Conventions, each checked by tests/engine/test_conversions.cpp:
// - A rotor R turns vectors by x' = R x ~R. The rotor turning by +θ
//   (right-handed) about the unit axis a is R = exp(-θ/2 B) with B the plane
//   of a: B = a_x e23 + a_y e31 + a_z e12 = a_z e12 - a_y e13 + a_x e23.
// - A quaternion is Hamilton's (i j = k), w its scalar part, and turns vectors
//   by x' = q x q*. The same turn is q = cos(θ/2) + sin(θ/2) (a_x i + a_y j +
//   a_z k), so, reading R = cos(θ/2) - sin(θ/2) B term by term,
//     w = R.scalar,  x = -R.e23,  y = R.e13,  z = -R.e12,
//   that is i = -e23, j = -e31 = e13, k = -e12 (and indeed e23 e31 = -e12:
//   i j = k). The sign is kept both ways: q and -q, R and -R are the same turn.
// - A matrix M turns vectors by x' = M x; its columns are R e1 ~R, R e2 ~R,
//   R e3 ~R.
// - A bivector Ω (angular velocity, torque, angular momentum) and its axial
//   vector ω are each other's duals, Ω = ω I3 with I3 = e1 e2 e3:
//   ω = (Ω.e23, -Ω.e13, Ω.e12). Then the engine's r ⌋ Ω is ω × r, its
//   torque r ∧ f is the axial r × f, and Ω = to_bivector(ω) turns the body
//   about ω by |ω| rad/s, right-handed.
//
// Bad input throws invalid_input before anything is returned: non-finite
// numbers, a zero quaternion or rotor, a matrix that is not a rotation.
// Quaternions and rotors of any other length are normalized first.
#pragma once

#include <array>

#include "gaphys/algebra.hpp"

namespace gaphys {

// Hamilton's quaternion w + x i + y j + z k. Default: the identity turn.
struct quaternion {
  real w = 1, x = 0, y = 0, z = 0;
};

// A 3x3 matrix, row-major: element (row i, column j) is [3 i + j], the
// layout inertia::tensor takes.
using matrix3 = std::array<real, 9>;

// How far a matrix may be from a rotation and still be accepted: every entry
// of M Mᵀ - 1 within this (which puts det M within 1.5e-6 of ±1), and
// det M > 0, not a reflection. (1e-5 in a float engine, whose own matrices
// err by a few 1e-7.)
inline constexpr real rotation_matrix_tolerance = sizeof(real) == 8 ? real(1e-6) : real(1e-5);

// Rotations. The results are unit quaternions and rotors and orthonormal
// matrices, whatever the length of the quaternion or rotor given.
quaternion to_quaternion(const rotor& attitude);
rotor to_rotor(const quaternion& q);
matrix3 to_matrix(const rotor& attitude);
matrix3 to_matrix(const quaternion& q);
// From a rotation matrix (Shepperd's method: the quaternion's largest
// component first, so no division by a small one). Its sign makes that
// component positive.
rotor to_rotor(const matrix3& rotation);
quaternion to_quaternion(const matrix3& rotation);

// Angular quantities: the bivector's axial vector (its dual) and back.
vector to_axial(const bivector& plane);
bivector to_bivector(const vector& axial);

}  // namespace gaphys
