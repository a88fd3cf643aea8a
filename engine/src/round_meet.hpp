// The conformal meet of two round shapes (spheres, planes, points), in two
// halves: the algebra (terms_of: products of the shapes' duals, the same for
// one pair or, on batches, for W pairs at once) and the contact it tells of
// (contact_from: the branches, per pair).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>

#include "gaphys/contact.hpp"
#include "gaphys/ga/compiler.hpp"
#include "precision.hpp"

namespace gaphys::detail {

// What the meet C = (A* ∧ B*)^-* of two duals says, as numbers (T a scalar,
// or a pack of lanes on batches).
template <class T>
struct round_terms {
  T weight_square;             // (ni ⌋ C)^2, the round's squared weight
  T duals_product;             // A* . B*
  T meet_square;               // C Ĉ: over weight_square, the round's squared radius
  std::array<T, 3> direction;  // Euclidean part of no ⌋ ((ni ⌋ C) ∧ ni)^-*: along the normal
  std::array<T, 3> centre;     // Euclidean part of C ni C, the round's centre, weighted
  T centre_weight;             // -ni . (C ni C)
};

// Where a pair's meet is computed: at the centre of its first shape that is
// not a plane (a sphere's or a point's), else at the world's origin. A
// translation T commutes with the meet, T(A ∩ B)T~ = TAT~ ∩ TBT~, but the
// meet's terms are products of duals that carry |x|^2 / 2 of each centre x:
// in the world frame they lost precision with the square of the pair's
// distance from the origin, and two spheres 10 km out (double), or 100 m out
// (float), that overlapped by 1 mm met nothing. At the pair, the terms are of
// the size of the shapes wherever the pair is.
inline const vector& meet_origin(const placed_shape& a, const placed_shape& b) {
  static const vector world_origin{};
  if (a.kind != shape_kind::plane) return a.center;
  if (b.kind != shape_kind::plane) return b.center;
  return world_origin;
}

// A sphere's and a plane's duals, in the frame whose origin is `origin` (the
// world's: place() stores them in placed_shape::dual, widened to mv), as
// their named c3ga types: the meet's products then run the generated kernels
// of those types (straight-line code, no mv dispatch).
conformal::dual_sphere dual_sphere_of(const placed_shape& s, const vector& origin);
conformal::dual_plane dual_plane_of(const placed_shape& s, const vector& origin);
// Any round shape's dual (a point's has no named type), in that frame.
conformal::mv dual_of(const placed_shape& s, const vector& origin);

// The Euclidean part (e1, e2, e3) of a c3ga value, named type or mv.
template <class X>
auto euclidean_part(const X& x) {
  if constexpr (std::is_same_v<X, conformal::mv>) {
    const conformal::euclidean_vector v(x);
    return std::array<real, 3>{v.e1(), v.e2(), v.e3()};
  } else {
    return std::array<typename X::scalar_type, 3>{x.e1(), x.e2(), x.e3()};
  }
}

// Thesis eq. 4.10: reflecting infinity in the round C gives its centre, C ni C.
template <class Round, class Weight>
conformal::mv centre_of(const Round& meet, const Weight&) {
  const conformal::mv ni = c3ga::ni<real>();
  return c3ga::gp(c3ga::gp(meet, ni), meet);
}

// The same for a circle, by grades: C ni C is a vector, the grade-1 part of
// (C ⌊ ni) C + (C ∧ ni) C, that is (C ⌊ ni) ⌋ C + (C ∧ ni) ⌊ C. For a
// trivector C ⌊ ni = ni ⌋ C (the weight), and (C ∧ ni) ⌊ C = -C ⌋ (C ∧ ni)
// (reverse both sides: C~ = -C, (C ∧ ni)~ = C ∧ ni). Contractions of named
// types, where the geometric products would pass through an mv of grades 2
// and 4.
template <class T>
GAPHYS_ALWAYS_INLINE c3ga::basic_dual_sphere<T> centre_of(const c3ga::basic_circle<T>& meet,
                                                          const c3ga::basic_point_pair<T>& weight) {
  return c3ga::sub(c3ga::lc(weight, meet), c3ga::lc(meet, c3ga::op(meet, c3ga::ni<T>())));
}

// The terms of the meet of two duals: dual_sphere and dual_plane (or their
// batches), or mv where a point takes part (its dual, the flat point's, has
// no named type of its own). (Forced inline, with read_terms and centre_of:
// called on batches, GCC passed their packs through memory at each call,
// a tenth of the meet's time in a pile of spheres.)
template <class DualA, class DualB>
GAPHYS_ALWAYS_INLINE auto terms_of(const DualA& dual_a, const DualB& dual_b) {
  using scalar =
      std::conditional_t<std::is_same_v<DualA, conformal::mv>, real, typename DualA::scalar_type>;
  const auto ni = c3ga::ni<scalar>();
  const auto no = c3ga::no<scalar>();
  // Thesis eq. 4.8 on dual shapes: C = A ∩ B = (A* ∧ B*)^-*. Two spheres, or a
  // sphere and a plane, meet in a circle; a sphere and a flat point in a round
  // point (a dual sphere centred on the point).
  const auto meet = c3ga::undual(c3ga::op(dual_a, dual_b));
  // Thesis test t = C^2 (eq. 4.9), made independent of C's grade and weight
  // (contact_from divides by the weight).
  const auto weight = c3ga::lc(ni, meet);
  // Thesis eq. 4.11: (-ni ⌋ C) ∧ ni = -weight ∧ ni is the direction of the
  // round's carrier, n ∧ ni; undualized and read out by no ⌋ it is a vector
  // along the normal, oriented from B to A.
  const auto direction = c3ga::lc(no, c3ga::undual(c3ga::op(weight, ni)));
  const auto centre = centre_of(meet, weight);
  return round_terms<scalar>{c3ga::scp(weight, weight),
                             c3ga::scp(dual_a, dual_b),
                             c3ga::scp(meet, c3ga::involute(meet)),
                             euclidean_part(direction),
                             euclidean_part(centre),
                             -c3ga::scp(ni, centre)};
}

// What contact_from reads of a meet's terms: their quotients and square
// roots, taken on batches of pairs with the terms (on one pair at a time,
// their latencies, one after the other, were most of contact_from's time).
template <class T>
struct round_reading {
  T weight_square;               // round_terms::weight_square; 0: no finite round
  T weight;                      // sqrt(|weight_square|)
  T duals_product;               // A* . B*
  T squared_radius;              // meet_square / weight_square
  T length;                      // |direction|
  e3ga::basic_vector<T> normal;  // -direction / length: from B to A
  e3ga::basic_vector<T> centre;  // centre / centre_weight: the round's centre, from the origin
};

// A square root, of a number or of a pack's lanes (correctly rounded either
// way: the same bits). A pack of 64 bytes (AVX-512) lane by lane: there GCC
// 12 inlines std::experimental::sqrt from its own header with a register
// left undefined on purpose (_mm512_undefined_pd), and warns of it. A
// narrower one whole: lane by lane, each lane taken out and put back, a
// pack of two doubles (SSE2) spent a tenth of the meet's time there.
template <class T>
T square_root(const T& x) {
  if constexpr (std::is_floating_point_v<T>) {
    return std::sqrt(x);
  } else if constexpr (sizeof(T) < 64) {
    using std::sqrt;
    return sqrt(x);  // (std::experimental's, found by the pack's type)
  } else {
    return T([&](auto lane) { return std::sqrt(x[lane]); });
  }
}

template <class T>
GAPHYS_ALWAYS_INLINE round_reading<T> read_terms(const round_terms<T>& t) {
  using std::abs;
  using vector_of = e3ga::basic_vector<T>;
  // (A round point has no carrier direction: its normal and length are NaN
  // or 0, and contact_from takes the line of centres instead.)
  const vector_of direction = -vector_of(t.direction[0], t.direction[1], t.direction[2]);
  const T length = square_root(abs(e3ga::norm2(direction)));
  return round_reading<T>{t.weight_square,
                          square_root(abs(t.weight_square)),
                          t.duals_product,
                          t.meet_square / t.weight_square,
                          length,
                          direction / length,
                          vector_of(t.centre[0], t.centre[1], t.centre[2]) / t.centre_weight};
}

// The largest value of x . direction over the shape's solid, x from
// `origin`. A plane's solid is unbounded except along its own normal, the
// only direction a contact with a plane has. (Forced inline: out of line,
// its calls were a fifth of contact_from's instructions.)
GAPHYS_ALWAYS_INLINE real support_height(const placed_shape& s, const vector& direction,
                                         const vector& origin) {
  switch (s.kind) {
    case shape_kind::sphere:
      return e3ga::scp(s.center - origin, direction) + s.radius;
    case shape_kind::point:
      return e3ga::scp(s.center - origin, direction);
    case shape_kind::plane:
      return s.offset - e3ga::scp(s.normal, origin);
    default:  // the convex narrow phase's shapes never reach the meet
      break;
  }
  return 0;
}

// Two spheres with the same centre and radius (contact_from, where the meet
// is zero): `duals_product` is scp(A*, B*).
std::optional<contact_geometry> coincident_spheres(const placed_shape& a, const placed_shape& b,
                                                   real duals_product, const vector& origin);

// The contact of two round shapes whose meet, computed in the frame at
// `origin` (meet_origin), reads r (find_contact's rules: contact.hpp).
// (Inline: out of line, its call and its result's copy were a fifth of the
// narrow phase's time in a pile of spheres.)
GAPHYS_ALWAYS_INLINE std::optional<contact_geometry> contact_from(
    const placed_shape& a, const placed_shape& b, const round_reading<real>& r,
    const vector& origin, real lookahead, const vector& velocity_a, const vector& velocity_b) {
  // A zero weight means no finite intersection (parallel planes, a point and
  // a plane) or no intersection to speak of (identical spheres).
  if (!(std::fabs(r.weight_square) > 0)) return coincident_spheres(a, b, r.duals_product, origin);
  // The squared radius of a round is C Ĉ / (ni ⌋ C)^2 (Dorst et al. 2007,
  // table 14.1). > 0: interpenetrating, 0: touching, < 0: the surfaces do not
  // meet.
  const real squared_radius = r.squared_radius;
  // Surfaces that do not meet are apart, or one solid holds the other whole
  // (a sphere sunk below a plane, or inside a bigger sphere). The inner
  // product of the duals tells which: for spheres σA . σB = (rA^2 + rB^2 -
  // d^2) / 2, below -rA rB when apart and above rA rB when nested; for a
  // sphere and a plane it is the centre's depth below the plane. Apart
  // shapes go on only when they may close the gap within the lookahead.
  const bool apart = !(squared_radius >= 0) && !(r.duals_product > 0);
  if (apart && !(lookahead > 0)) return std::nullopt;

  // The normal, from B to A. A round point has no carrier direction: for a
  // flat point the normal is the line of the two centres.
  vector normal = r.normal;
  if (!(r.length > by_precision(1e-9, 1e-4) * r.weight)) {
    if (a.kind == shape_kind::plane || b.kind == shape_kind::plane) return std::nullopt;
    normal = a.center - b.center;
    real length = e3ga::norm(normal);
    if (!(length > 0)) normal = vector{0, 0, 1}, length = 1;  // coincident centres: any direction
    normal = normal / length;
  }

  // Depth: how far the solids overlap along the normal (minus the gap when
  // they are apart). A gap counts when the speeds of A and B towards each
  // other, -n . vA and n . vB where positive, cover it within the lookahead.
  const real depth = support_height(a, -normal, origin) + support_height(b, normal, origin);
  const real closing = std::max(-e3ga::scp(normal, velocity_a), real(0)) +
                       std::max(e3ga::scp(normal, velocity_b), real(0));
  if (apart && !(-depth <= lookahead * closing)) return std::nullopt;

  const vector point = origin + r.centre;
  return contact_geometry{point, normal, depth, squared_radius};
}

// The shapes the conformal meet takes whole (find_contact): spheres, planes
// and points; the others go to the convex narrow phase.
inline bool is_round(shape_kind kind) {
  return kind == shape_kind::sphere || kind == shape_kind::plane || kind == shape_kind::point;
}

// Two round shapes that terms_of meets on batches: a sphere and a sphere,
// or a sphere and a plane, in either order.
bool meets_on_batches(shape_kind a, shape_kind b);

// readings[k] = what the terms of pairs[k], in the frame at their
// meet_origin, read (read_terms), for pairs of shapes that
// meets_on_batches: W pairs of one kind of pair at a time.
void batched_readings(const std::pair<const placed_shape*, const placed_shape*>* pairs,
                      std::size_t count, round_reading<real>* readings);

}  // namespace gaphys::detail
