#include "shape_json.hpp"

#include <stdexcept>

#include "trajectory_writer.hpp"

namespace demo {

std::string json_vector(const gaphys::vector& v) {
  return "[" + json_number(v.e1()) + ", " + json_number(v.e2()) + ", " + json_number(v.e3()) + "]";
}

std::string json_rotor(const gaphys::rotor& r) {
  return "[" + json_number(r.scalar()) + ", " + json_number(r.e12()) + ", " + json_number(r.e13()) +
         ", " + json_number(r.e23()) + "]";
}

namespace {

// The hull's corners and its faces as lists of corner indices: a reader
// fan-triangulates each face (they are convex) or draws its outline.
std::string polyhedron_members(const gaphys::convex_polyhedron& p) {
  std::string text = "\"vertices\": [";
  for (std::size_t i = 0; i < p.vertices.size(); ++i) {
    text += (i == 0 ? "" : ", ") + json_vector(p.vertices[i]);
  }
  text += "], \"faces\": [";
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    const gaphys::polyhedron_face& face = p.faces[f];
    text += f == 0 ? "[" : ", [";
    for (std::uint32_t k = 0; k < face.count; ++k) {
      text += (k == 0 ? "" : ", ") + std::to_string(p.vertex_indices[face.first + k]);
    }
    text += "]";
  }
  return text + "]";
}

// The shape's members without the braces, so that a pose can follow them.
std::string shape_members(const gaphys::shape& s) {
  switch (s.kind()) {
    case gaphys::shape_kind::sphere:
      return "\"kind\": \"sphere\", \"radius\": " + json_number(s.radius());
    case gaphys::shape_kind::plane:
      return "\"kind\": \"plane\", \"normal\": " + json_vector(s.normal()) +
             ", \"offset\": " + json_number(s.offset());
    case gaphys::shape_kind::point:
      return "\"kind\": \"point\"";
    case gaphys::shape_kind::box:
      return "\"kind\": \"box\", \"half_extents\": " + json_vector(s.half_extents());
    case gaphys::shape_kind::capsule:
      return "\"kind\": \"capsule\", \"half_height\": " + json_number(s.half_height()) +
             ", \"radius\": " + json_number(s.radius());
    case gaphys::shape_kind::convex_hull:
      return "\"kind\": \"convex_hull\", " + polyhedron_members(*s.polyhedron());
  }
  throw std::logic_error("unknown shape kind");
}

}  // namespace

std::string json_shape(const gaphys::shape& s) { return "{" + shape_members(s) + "}"; }

std::string json_body(const gaphys::body& b, gaphys::body_id id) {
  std::string shapes;
  for (const gaphys::attached_shape& a : b.shapes()) {
    shapes += (shapes.empty() ? "{" : ", {") + shape_members(a.shape) +
              ", \"position\": " + json_vector(a.offset) +
              ", \"attitude\": " + json_rotor(a.attitude) + "}";
  }
  return "{\"id\": " + std::to_string(id) + ", \"static\": " + (b.is_static() ? "true" : "false") +
         ", \"shape\": " + (b.shape() ? json_shape(*b.shape()) : "null") + ", \"shapes\": [" +
         shapes + "], \"position\": " + json_vector(b.position()) +
         ", \"attitude\": " + json_rotor(b.attitude()) + "}";
}

}  // namespace demo
