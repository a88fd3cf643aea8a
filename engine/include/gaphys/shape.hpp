// A body's geometric description. Its pose comes from the body it is attached
// to; the shape only knows its body-frame parameters and its material.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "gaphys/algebra.hpp"
#include "gaphys/convex_polyhedron.hpp"
#include "gaphys/material.hpp"

namespace gaphys {

namespace detail {
struct snapshot_access;  // snapshot.cpp: reads and writes every field
}

enum class shape_kind { sphere, plane, point, box, capsule, convex_hull };

// Which shapes meet, by category and mask bits (as Box2D's): two shapes make
// contacts, or a sensor reports the other, only when each one's category
// shares a bit with the other's mask. By default every shape is in category
// 1 and meets every category.
struct collision_filter {
  std::uint32_t category = 1;
  std::uint32_t mask = 0xffffffff;

  bool meets(const collision_filter& other) const {
    return (category & other.mask) != 0 && (other.category & mask) != 0;
  }
};

class shape {
 public:
  // A solid sphere of this radius (finite, > 0) centred on the shape's frame
  // (the body's origin, or its attached_shape pose).
  static shape sphere(real radius);
  // The half-space {x : n . x <= offset} of the body frame, n = normal / |normal|
  // (normal finite and nonzero; offset is the signed distance of the boundary
  // plane from the body origin along n). Only static bodies may carry one.
  static shape plane(const vector& normal, real offset);
  // A point at the shape frame's origin (a flat point in c3ga, thesis
  // 4.2.1). Points collide with spheres, boxes, capsules and hulls.
  static shape point();
  // A box centred on the shape's frame, its edges along the frame's axes, with
  // these half extents (each finite and > 0).
  static shape box(const vector& half_extents);
  // The points within `radius` of the segment from -half_height e3 to
  // +half_height e3 of the body frame (radius finite and > 0, half_height
  // finite and >= 0; 0 is a sphere).
  static shape capsule(real half_height, real radius);
  // The convex hull of the points (body frame; convex_polyhedron::hull says
  // how). Throws invalid_input for a non-finite point, fewer than 4 points,
  // or points all (nearly) in one plane.
  static shape convex_hull(const std::vector<vector>& points);

  // The surface's material (material.hpp says what each value does and how
  // a contact combines its two shapes' values). Each returns a copy with the
  // one value changed; a value out of range throws invalid_input naming it.
  shape with_restitution(real restitution) const;  // in [0, 1]; default 0.5
  shape with_friction(real mu) const;              // finite, >= 0; default 0.5
  shape with_rolling_resistance(real c) const;     // finite, >= 0; default 0
  shape with_spinning_friction(real c) const;      // finite, >= 0; default 0
  // A copy in these categories, meeting shapes of these (collision_filter).
  shape with_filter(std::uint32_t category, std::uint32_t mask) const;
  // A copy that is a sensor: it reports the shapes it overlaps
  // (world::sensor_overlaps) and never pushes them, adds no mass to its
  // body, and ray casts and overlap queries pass through it. A plane or a
  // point cannot be one (invalid_input): a sensor needs a volume.
  shape as_sensor() const;

  shape_kind kind() const { return kind_; }
  real radius() const { return radius_; }                       // sphere, capsule
  const vector& half_extents() const { return half_extents_; }  // box
  real half_height() const { return half_height_; }             // capsule
  // The faces, edges and corners of a box or a convex hull; nullptr otherwise.
  const convex_polyhedron* polyhedron() const { return polyhedron_.get(); }
  // The largest distance of the shape's solid from its frame's origin
  // (infinite for a plane).
  real bounding_radius() const;
  const vector& normal() const { return normal_; }
  real offset() const { return offset_; }
  const collision_filter& filter() const { return filter_; }
  bool is_sensor() const { return sensor_; }
  const gaphys::material& material() const { return material_; }
  real restitution() const { return material_.restitution; }
  real friction() const { return material_.friction; }
  real rolling_resistance() const { return material_.rolling_resistance; }
  real spinning_friction() const { return material_.spinning_friction; }

 private:
  friend struct detail::snapshot_access;
  explicit shape(shape_kind kind) : kind_(kind) {}
  // A copy with one material value changed (already validated).
  shape with(real gaphys::material::*field, real value) const;

  shape_kind kind_;
  real radius_ = 0;
  vector normal_{};
  real offset_ = 0;
  vector half_extents_{};
  real half_height_ = 0;
  std::shared_ptr<const convex_polyhedron> polyhedron_;  // immutable, shared by copies
  gaphys::material material_;
  collision_filter filter_;
  bool sensor_ = false;
};

}  // namespace gaphys
