#include "round_meet.hpp"

#include <algorithm>
#include <c3ga/batch.hpp>
#include <cmath>
#include <vector>

#include "gaphys/ga/compiler.hpp"
#include "precision.hpp"

namespace gaphys::detail {

namespace {

// The lanes of one batch: a pack of doubles as wide as the target's vector
// registers (2 with SSE2, 4 with AVX2).
constexpr int lanes = c3ga::native_lanes;

// read_terms(terms_of) on the pairs at[0 .. count) (count <= lanes; the
// rest of the batch repeats the last pair), their duals made by dual_a and
// dual_b in the frame at each pair's meet_origin.
template <class DualOfA, class DualOfB>
void readings_of_batch(const std::pair<const placed_shape*, const placed_shape*>* pairs,
                       const std::size_t* at, int count, round_reading<real>* readings,
                       DualOfA dual_a, DualOfB dual_b) {
  const auto pair = [&](int i) { return pairs[at[std::min(i, count - 1)]]; };
  const auto origin = [&](int i) -> const vector& {
    return meet_origin(*pair(i).first, *pair(i).second);
  };
  const auto duals_a =
      c3ga::gather<lanes>([&](int i) { return dual_a(*pair(i).first, origin(i)); });
  const auto duals_b =
      c3ga::gather<lanes>([&](int i) { return dual_b(*pair(i).second, origin(i)); });
  const auto r = read_terms(terms_of(duals_a, duals_b));
  for (int i = 0; i < count; ++i) {
    round_reading<real>& out = readings[at[i]];
    out.weight_square = r.weight_square[i];
    out.weight = r.weight[i];
    out.duals_product = r.duals_product[i];
    out.squared_radius = r.squared_radius[i];
    out.length = r.length[i];
    out.normal = {r.normal.e1()[i], r.normal.e2()[i], r.normal.e3()[i]};
    out.centre = {r.centre.e1()[i], r.centre.e2()[i], r.centre.e3()[i]};
  }
}

}  // namespace

// Two spheres with the same centre and radius: their duals are equal, the
// meet is zero and has no round to read. They overlap wholly; the normal is
// arbitrary (e3), so the solver separates them deterministically.
// `duals_product` is scp(A*, B*).
std::optional<contact_geometry> coincident_spheres(const placed_shape& a, const placed_shape& b,
                                                   real duals_product, const vector& origin) {
  if (a.kind != shape_kind::sphere || b.kind != shape_kind::sphere) return std::nullopt;
  if (!(duals_product > 0)) return std::nullopt;
  const vector normal{0, 0, 1};
  const real depth = support_height(a, -normal, origin) + support_height(b, normal, origin);
  return contact_geometry{a.center, normal, depth, a.radius * a.radius};
}

conformal::dual_sphere dual_sphere_of(const placed_shape& s, const vector& origin) {
  const vector c = s.center - origin;
  const real half_square = real(0.5) * e3ga::scp(c, c);
  return {1, c.e1(), c.e2(), c.e3(), half_square - real(0.5) * s.radius * s.radius};
}

conformal::dual_plane dual_plane_of(const placed_shape& s, const vector& origin) {
  const real offset = s.offset - e3ga::scp(s.normal, origin);
  return -conformal::dual_plane{s.normal.e1(), s.normal.e2(), s.normal.e3(), offset};
}

conformal::mv dual_of(const placed_shape& s, const vector& origin) {
  switch (s.kind) {
    case shape_kind::sphere:
      return conformal::mv(dual_sphere_of(s, origin));
    case shape_kind::plane:
      return conformal::mv(dual_plane_of(s, origin));
    case shape_kind::point: {  // the dual of the flat point x ^ ni
      const vector x = s.center - origin;
      const conformal::normalized_point p{x.e1(), x.e2(), x.e3(), real(0.5) * e3ga::scp(x, x)};
      return c3ga::dual(c3ga::op(p, c3ga::ni<real>()));
    }
    default:  // the convex narrow phase's shapes have no dual
      return conformal::mv{};
  }
}

bool meets_on_batches(shape_kind a, shape_kind b) {
  return (a == shape_kind::sphere && (b == shape_kind::sphere || b == shape_kind::plane)) ||
         (a == shape_kind::plane && b == shape_kind::sphere);
}

void batched_readings(const std::pair<const placed_shape*, const placed_shape*>* pairs,
                      std::size_t count, round_reading<real>* readings) {
  // The pairs of each kind, batch by batch: sphere-sphere, sphere-plane,
  // plane-sphere.
  // (Each thread's, kept from call to call.)
  static thread_local std::array<std::vector<std::size_t>, 3> of_kind;
  for (std::vector<std::size_t>& list : of_kind) list.clear();
  for (std::size_t k = 0; k < count; ++k) {
    const bool plane_a = pairs[k].first->kind == shape_kind::plane;
    const bool plane_b = pairs[k].second->kind == shape_kind::plane;
    of_kind[plane_a ? 2 : plane_b ? 1 : 0].push_back(k);
  }
  const auto sphere = [](const placed_shape& s, const vector& o) { return dual_sphere_of(s, o); };
  const auto plane = [](const placed_shape& s, const vector& o) { return dual_plane_of(s, o); };
  for (int kind = 0; kind < 3; ++kind) {
    const std::vector<std::size_t>& at = of_kind[kind];
    for (std::size_t first = 0; first < at.size(); first += lanes) {
      const int n = static_cast<int>(std::min<std::size_t>(lanes, at.size() - first));
      if (kind == 0) readings_of_batch(pairs, &at[first], n, readings, sphere, sphere);
      if (kind == 1) readings_of_batch(pairs, &at[first], n, readings, sphere, plane);
      if (kind == 2) readings_of_batch(pairs, &at[first], n, readings, plane, sphere);
    }
  }
}

}  // namespace gaphys::detail
