// A body's geometric description. Its pose comes from the body it is attached
// to; the shape only knows its body-frame parameters and its material.
#pragma once

#include "gaphys/algebra.hpp"

namespace gaphys {

enum class shape_kind { sphere, plane, point };

class shape {
 public:
  // A solid sphere of this radius (finite, > 0) centred on the body.
  static shape sphere(real radius);
  // The half-space {x : n . x <= offset} of the body frame, n = normal / |normal|
  // (normal finite and nonzero; offset is the signed distance of the boundary
  // plane from the body origin along n). Only static bodies may carry one.
  static shape plane(const vector& normal, real offset);
  // A point at the body's centre (a flat point in c3ga, thesis 4.2.1). Points
  // collide with spheres.
  static shape point();

  // Coefficient of restitution in [0, 1]; a contact uses the larger of its
  // two shapes' values.
  shape with_restitution(real restitution) const;

  shape_kind kind() const { return kind_; }
  real radius() const { return radius_; }
  const vector& normal() const { return normal_; }
  real offset() const { return offset_; }
  real restitution() const { return restitution_; }

 private:
  shape(shape_kind kind, real radius, const vector& normal, real offset)
      : kind_(kind), radius_(radius), normal_(normal), offset_(offset) {}

  shape_kind kind_;
  real radius_ = 0;
  vector normal_{};
  real offset_ = 0;
  real restitution_ = 0.5;
};

}  // namespace gaphys
