// A fixture for the narrow-phase tests: shapes placed in the world. A
// placed box or hull points into its shape's polyhedron, so the fixture
// keeps every shape it places for the length of the test.
#pragma once

#include <deque>

#include "convex_contact.hpp"
#include "engine_test_support.hpp"

namespace gaphys::testing {

class placed_shape_test : public engine_test {
 protected:
  placed_shape keep_placed(const shape& s, const vector& centre, const rotor& attitude) {
    shapes_.push_back(s);
    return place(shapes_.back(), centre, attitude);
  }
  placed_shape box(const vector& centre, const vector& half_extents,
                   const rotor& attitude = rotor{1, 0, 0, 0}) {
    return keep_placed(shape::box(half_extents), centre, attitude);
  }
  placed_shape hull(const std::vector<vector>& points, const vector& centre,
                    const rotor& attitude = rotor{1, 0, 0, 0}) {
    return keep_placed(shape::convex_hull(points), centre, attitude);
  }
  // The plane z = height.
  static placed_shape floor(real height = 0) {
    return place(shape::plane(vector{0, 0, 1}, height), vector{}, rotor{1, 0, 0, 0});
  }
  static placed_shape sphere(const vector& centre, real radius) {
    return place(shape::sphere(radius), centre, rotor{1, 0, 0, 0});
  }

 private:
  std::deque<shape> shapes_;
};

}  // namespace gaphys::testing
