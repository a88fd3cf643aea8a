#include "gaphys/contact.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "convex_contact.hpp"

namespace gaphys {

namespace {

using c3ga::mv;

vector to_e3ga(const c3ga::euclidean_vector& v) { return {v.e1(), v.e2(), v.e3()}; }

// The largest value of x . direction over the shape's solid. A plane's solid
// is unbounded except along its own normal, the only direction a contact with
// a plane has.
real support_height(const placed_shape& s, const vector& direction) {
  switch (s.kind) {
    case shape_kind::sphere:
      return e3ga::scp(s.center, direction) + s.radius;
    case shape_kind::point:
      return e3ga::scp(s.center, direction);
    case shape_kind::plane:
      return s.offset;
    default:  // the convex narrow phase's shapes never reach the meet
      break;
  }
  return 0;
}

bool is_round(shape_kind kind) {
  return kind == shape_kind::sphere || kind == shape_kind::plane || kind == shape_kind::point;
}

// Two spheres with the same centre and radius: their duals are equal, the
// meet is zero and has no round to read. They overlap wholly; the normal is
// arbitrary (e3), so the solver separates them deterministically.
// `duals_product` is scp(A*, B*).
std::optional<contact_geometry> coincident_spheres(const placed_shape& a, const placed_shape& b,
                                                   real duals_product) {
  if (a.kind != shape_kind::sphere || b.kind != shape_kind::sphere) return std::nullopt;
  if (!(duals_product > 0)) return std::nullopt;
  const vector normal{0, 0, 1};
  const real depth = support_height(a, -normal) + support_height(b, normal);
  return contact_geometry{a.center, normal, depth, a.radius * a.radius};
}

}  // namespace

placed_shape place(const shape& s, const vector& position, const rotor& attitude) {
  placed_shape placed{mv{}, s.kind(), position, vector{}, s.radius(), 0};
  placed.attitude = attitude;
  const real half_square = real(0.5) * e3ga::scp(position, position);
  switch (s.kind()) {
    case shape_kind::sphere:  // σ = c - r^2/2 ni, c = no + x + x^2/2 ni
      placed.dual = c3ga::dual_sphere{1, position.e1(), position.e2(), position.e3(),
                                      half_square - real(0.5) * s.radius() * s.radius()};
      break;
    case shape_kind::plane: {  // -(n + d ni), n and d in the world frame
      placed.normal = e3ga::apply(attitude, s.normal());
      placed.offset = s.offset() + e3ga::scp(placed.normal, position);
      placed.dual = -c3ga::dual_plane{placed.normal.e1(), placed.normal.e2(), placed.normal.e3(),
                                      placed.offset};
      break;
    }
    case shape_kind::point: {  // the dual of the flat point x ^ ni
      const c3ga::normalized_point x{position.e1(), position.e2(), position.e3(), half_square};
      placed.dual = c3ga::dual(c3ga::op(x, c3ga::ni()));
      break;
    }
    case shape_kind::capsule:
      placed.half_height = s.half_height();
      placed.axis = e3ga::apply(attitude, vector{0, 0, 1});
      break;
    case shape_kind::box:
      placed.half_extents = s.half_extents();
      placed.polyhedron = s.polyhedron();
      break;
    case shape_kind::convex_hull:
      placed.polyhedron = s.polyhedron();
      break;
  }
  return placed;
}

namespace {

// The Euclidean part (e1, e2, e3) of a c3ga value, named type or mv.
template <class X>
vector euclidean_part(const X& x) {
  if constexpr (std::is_same_v<X, mv>) {
    return to_e3ga(c3ga::euclidean_vector(x));
  } else {
    return {x.e1(), x.e2(), x.e3()};
  }
}

// A sphere's and a plane's duals as their named c3ga types, the same numbers
// place() stores in placed_shape::dual: the meet's products then run the
// generated kernels of those types (straight-line code, no mv dispatch).
c3ga::dual_sphere dual_sphere_of(const placed_shape& s) {
  const real half_square = real(0.5) * e3ga::scp(s.center, s.center);
  return {1, s.center.e1(), s.center.e2(), s.center.e3(),
          half_square - real(0.5) * s.radius * s.radius};
}

c3ga::dual_plane dual_plane_of(const placed_shape& s) {
  return -c3ga::dual_plane{s.normal.e1(), s.normal.e2(), s.normal.e3(), s.offset};
}

// Thesis eq. 4.10: reflecting infinity in the round C gives its centre, C ni C.
template <class Round, class Weight>
mv centre_of(const Round& meet, const Weight&) {
  const mv ni = c3ga::ni();
  return c3ga::gp(c3ga::gp(meet, ni), meet);
}

// The same for a circle, by grades: C ni C is a vector, the grade-1 part of
// (C ⌊ ni) C + (C ∧ ni) C, that is (C ⌊ ni) ⌋ C + (C ∧ ni) ⌊ C. For a
// trivector C ⌊ ni = ni ⌋ C (the weight), and (C ∧ ni) ⌊ C = -C ⌋ (C ∧ ni)
// (reverse both sides: C~ = -C, (C ∧ ni)~ = C ∧ ni). Contractions of named
// types, where the geometric products would pass through an mv of grades 2
// and 4.
c3ga::dual_sphere centre_of(const c3ga::circle& meet, const c3ga::point_pair& weight) {
  return c3ga::lc(weight, meet) - c3ga::lc(meet, c3ga::op(meet, c3ga::ni()));
}

// The meet of two round shapes given their duals: named types where both are
// spheres or planes, mv where a point takes part (its dual, the flat point's,
// has no named type of its own).
template <class DualA, class DualB>
std::optional<contact_geometry> meet_rounds(const placed_shape& a, const DualA& dual_a,
                                            const placed_shape& b, const DualB& dual_b,
                                            real lookahead, const vector& velocity_a,
                                            const vector& velocity_b) {
  const auto ni = c3ga::ni();
  const auto no = c3ga::no();

  // Thesis eq. 4.8 on dual shapes: C = A ∩ B = (A* ∧ B*)^-*. Two spheres, or a
  // sphere and a plane, meet in a circle; a sphere and a flat point in a round
  // point (a dual sphere centred on the point).
  const auto meet = c3ga::undual(c3ga::op(dual_a, dual_b));

  // Thesis test t = C^2 (eq. 4.9), made independent of C's grade and weight:
  // the squared radius of a round is C Ĉ / (ni ⌋ C)^2 (Dorst et al. 2007,
  // table 14.1). > 0: interpenetrating, 0: touching, < 0: the surfaces do not
  // meet. A zero weight means no finite intersection (parallel planes, a
  // point and a plane) or no intersection to speak of (identical spheres).
  const auto weight = c3ga::lc(ni, meet);
  const real weight_square = c3ga::scp(weight, weight);
  const real duals_product = c3ga::scp(dual_a, dual_b);
  if (!(std::fabs(weight_square) > 0)) return coincident_spheres(a, b, duals_product);
  const real squared_radius = c3ga::scp(meet, c3ga::involute(meet)) / weight_square;
  // Surfaces that do not meet are apart, or one solid holds the other whole
  // (a sphere sunk below a plane, or inside a bigger sphere). The inner
  // product of the duals tells which: for spheres σA . σB = (rA^2 + rB^2 -
  // d^2) / 2, below -rA rB when apart and above rA rB when nested; for a
  // sphere and a plane it is the centre's depth below the plane. Apart
  // shapes go on only when they may close the gap within the lookahead.
  const bool apart = !(squared_radius >= 0) && !(duals_product > 0);
  if (apart && !(lookahead > 0)) return std::nullopt;

  // Thesis eq. 4.11: (-ni ⌋ C) ∧ ni = -weight ∧ ni is the direction of the
  // round's carrier, n ∧ ni; undualized and read out by no ⌋ it is a vector
  // along the normal, oriented from B to A. A round point has no carrier
  // direction: for a flat point the normal is the line of the two centres.
  const auto direction = c3ga::lc(no, c3ga::undual(c3ga::op(weight, ni)));
  vector normal = -euclidean_part(direction);
  real length = e3ga::norm(normal);
  if (!(length > 1e-9 * std::sqrt(std::fabs(weight_square)))) {
    if (a.kind == shape_kind::plane || b.kind == shape_kind::plane) return std::nullopt;
    normal = a.center - b.center;
    length = e3ga::norm(normal);
    if (!(length > 0)) normal = vector{0, 0, 1}, length = 1;  // coincident centres: any direction
  }
  normal = normal / length;

  // Depth: how far the solids overlap along the normal (minus the gap when
  // they are apart). A gap counts when the speeds of A and B towards each
  // other, -n . vA and n . vB where positive, cover it within the lookahead.
  const real depth = support_height(a, -normal) + support_height(b, normal);
  const real closing = std::max(-e3ga::scp(normal, velocity_a), real(0)) +
                       std::max(e3ga::scp(normal, velocity_b), real(0));
  if (apart && !(-depth <= lookahead * closing)) return std::nullopt;

  const auto centre = centre_of(meet, weight);
  const real centre_weight = -c3ga::scp(ni, centre);
  const vector point = euclidean_part(centre) / centre_weight;
  return contact_geometry{point, normal, depth, squared_radius};
}

}  // namespace

std::optional<contact_geometry> find_contact(const placed_shape& a, const placed_shape& b,
                                             real lookahead, const vector& velocity_a,
                                             const vector& velocity_b) {
  const auto with = [&](const auto& dual_a, const auto& dual_b) {
    return meet_rounds(a, dual_a, b, dual_b, lookahead, velocity_a, velocity_b);
  };
  const bool sphere_a = a.kind == shape_kind::sphere, sphere_b = b.kind == shape_kind::sphere;
  const bool plane_a = a.kind == shape_kind::plane, plane_b = b.kind == shape_kind::plane;
  if (sphere_a && sphere_b) return with(dual_sphere_of(a), dual_sphere_of(b));
  if (sphere_a && plane_b) return with(dual_sphere_of(a), dual_plane_of(b));
  if (plane_a && sphere_b) return with(dual_plane_of(a), dual_sphere_of(b));
  return with(a.dual, b.dual);
}

void find_contacts(const placed_shape& a, const placed_shape& b, real lookahead,
                   const vector& velocity_a, const vector& velocity_b, real margin,
                   contact_manifold& out) {
  out.count = 0;
  if (!is_round(a.kind) || !is_round(b.kind)) {
    detail::collide_convex(a, b, margin, out);
    return;
  }
  if (auto geometry = find_contact(a, b, lookahead, velocity_a, velocity_b)) {
    out.points[0] = contact_point{*geometry, 0};
    out.count = 1;
  }
}

bool touching(const placed_shape& a, const placed_shape& b, contact_manifold& scratch) {
  find_contacts(a, b, 0, vector{}, vector{}, 0, scratch);
  for (int k = 0; k < scratch.count; ++k) {
    if (scratch.points[k].geometry.depth >= 0) return true;
  }
  return false;
}

}  // namespace gaphys
