// A body's geometric description. Its pose comes from the body it is attached
// to; the shape only knows its body-frame parameters and its material.
#pragma once

#include "gaphys/algebra.hpp"
#include "gaphys/material.hpp"

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

  // The surface's material (material.hpp says what each value does and how
  // a contact combines its two shapes' values). Each returns a copy with the
  // one value changed; a value out of range throws invalid_input naming it.
  shape with_restitution(real restitution) const;  // in [0, 1]; default 0.5
  shape with_friction(real mu) const;              // finite, >= 0; default 0.5
  shape with_rolling_resistance(real c) const;     // finite, >= 0; default 0
  shape with_spinning_friction(real c) const;      // finite, >= 0; default 0

  shape_kind kind() const { return kind_; }
  real radius() const { return radius_; }
  const vector& normal() const { return normal_; }
  real offset() const { return offset_; }
  const gaphys::material& material() const { return material_; }
  real restitution() const { return material_.restitution; }
  real friction() const { return material_.friction; }
  real rolling_resistance() const { return material_.rolling_resistance; }
  real spinning_friction() const { return material_.spinning_friction; }

 private:
  shape(shape_kind kind, real radius, const vector& normal, real offset)
      : kind_(kind), radius_(radius), normal_(normal), offset_(offset) {}
  // A copy with one material value changed (already validated).
  shape with(real gaphys::material::*field, real value) const;

  shape_kind kind_;
  real radius_ = 0;
  vector normal_{};
  real offset_ = 0;
  gaphys::material material_;
};

}  // namespace gaphys
