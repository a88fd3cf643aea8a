// Inertia as a linear function on bivectors (thesis eq. 4.3), in the body frame.
//
// A bivector B = b12 e12 + b13 e13 + b23 e23 is the plane of a rotation. The
// map L = I(B) is symmetric and positive definite. It is stored as the usual
// 3x3 inertia tensor J about the body axes x, y, z, acting on the dual axis
// coordinates (b23, -b13, b12): the rotation in the e23 plane is the one about
// x, in e31 = -e13 about y, in e12 about z. So I(e12) = J_zz e12 for a
// diagonal tensor, and a solid box with half extents (a, b, c) has
// I(e12) = m (a^2 + b^2) / 3 e12.
#pragma once

#include <array>

#include "gaphys/algebra.hpp"

namespace gaphys {

namespace detail {
struct snapshot_access;  // snapshot.cpp: reads and writes every field
}

class inertia {
 public:
  // The unit tensor, 1 kg m^2 about every axis: a valid value for a holder
  // such as mass_properties{} until it is given a real one.
  inertia()
      : tensor_{1, 0, 0, 0, 1, 0, 0, 0, 1}, inverse_{1, 0, 0, 0, 1, 0, 0, 0, 1}, isotropic_(true) {}

  // Principal moments about the body's x, y and z axes (kg m^2): the planes
  // e23, e31 and e12. Each must be finite and positive.
  static inertia principal(real about_x, real about_y, real about_z);
  static inertia solid_sphere(real mass, real radius);
  static inertia solid_box(real mass, real half_x, real half_y, real half_z);

  // A general symmetric tensor, row-major about x, y, z; it must be symmetric
  // (to 1e-12 relative) and positive definite.
  static inertia tensor(const std::array<real, 9>& rows);

  bivector operator()(const bivector& b) const { return apply(tensor_, b); }
  bivector inverse(const bivector& l) const { return apply(inverse_, l); }
  const std::array<real, 9>& rows() const { return tensor_; }

  // The same moment about every axis (a sphere's): I(B) = k B in any frame,
  // so a body need not turn B into its own frame, and Ω = L / k is fixed
  // while L is.
  bool is_isotropic() const { return isotropic_; }
  real isotropic_moment() const { return tensor_[0]; }

 private:
  friend struct detail::snapshot_access;
  inertia(const std::array<real, 9>& rows, const std::array<real, 9>& inverse);
  static bivector apply(const std::array<real, 9>& m, const bivector& b);

  std::array<real, 9> tensor_;
  std::array<real, 9> inverse_;
  bool isotropic_;
};

}  // namespace gaphys
