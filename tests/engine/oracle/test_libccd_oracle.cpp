// The convex narrow phase against libccd (GJK, EPA): 10,000 random
// configurations each of hull–hull, box–box and capsule–box, separated,
// touching and overlapping, through detail::convex_separation.
//
// libccd sees the shapes only through support functions written here from
// their corners, points and segments (nothing of gaphys's SAT or GJK):
//  - overlapping: ccdGJKPenetration (EPA) gives the penetration depth and
//    direction;
//  - apart: libccd has no distance query, so the distance is found by
//    bisection on r of ccdGJKIntersect(A inflated by a ball of radius r, B):
//    the smallest r at which they meet is the distance.
// libccd's GJK calls the origin reached when it is within sqrt(DBL_EPSILON)
// (1.5e-8, absolute) of the simplex, which would blur the bisection at that
// level; for the intersection tests every support point is therefore scaled
// by 2^14 (exact in floating point). EPA is run unscaled: its other absolute
// thresholds are tuned to shapes of unit size, and scaled it returns wrong
// depths.
#include <ccd/ccd.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "convex_contact.hpp"
#include "gaphys/gaphys.hpp"

namespace gaphys::testing {
namespace {

constexpr real intersect_scale = 16384;  // 2^14

// ---- Shapes as libccd sees them ---------------------------------------------

struct ccd_shape {
  std::vector<vector> points;  // world; a capsule's two segment ends
  real radius = 0;             // a capsule's radius
  real inflation = 0;          // the bisection's ball
  mutable real scale = 1;      // libccd sees the points times this
};

void ccd_support(const void* object, const ccd_vec3_t* direction, ccd_vec3_t* out) {
  const ccd_shape& s = *static_cast<const ccd_shape*>(object);
  const real dx = direction->v[0], dy = direction->v[1], dz = direction->v[2];
  const vector* best = &s.points.front();
  real best_height = -INFINITY;
  for (const vector& p : s.points) {
    const real height = p.e1() * dx + p.e2() * dy + p.e3() * dz;
    if (height > best_height) best_height = height, best = &p;
  }
  const real length = std::sqrt(dx * dx + dy * dy + dz * dz);
  const real round = length > 0 ? (s.radius + s.inflation) / length : 0;
  out->v[0] = s.scale * (best->e1() + round * dx);
  out->v[1] = s.scale * (best->e2() + round * dy);
  out->v[2] = s.scale * (best->e3() + round * dz);
}

ccd_t make_ccd() {
  ccd_t ccd;
  CCD_INIT(&ccd);
  ccd.support1 = ccd_support;
  ccd.support2 = ccd_support;
  ccd.max_iterations = 1000;
  ccd.epa_tolerance = 1e-12;
  return ccd;
}

bool ccd_intersect(const ccd_shape& a, const ccd_shape& b) {
  a.scale = b.scale = intersect_scale;
  const ccd_t ccd = make_ccd();
  const bool meet = ccdGJKIntersect(&a, &b, &ccd) != 0;
  a.scale = b.scale = 1;
  return meet;
}

// The distance by bisection: [low, high] always holds the smallest
// inflation of A that meets B.
real ccd_distance(ccd_shape a, const ccd_shape& b) {
  real low = 0, high = 1;
  a.inflation = high;
  while (!ccd_intersect(a, b)) high *= 2, a.inflation = high;
  for (int i = 0; i < 64 && high - low > 1e-15 * high; ++i) {
    a.inflation = real(0.5) * (low + high);
    (ccd_intersect(a, b) ? high : low) = a.inflation;
  }
  return real(0.5) * (low + high);
}

// How far A and B overlap along unit n (n from B towards A): the extent of
// B beyond A's lowest point along n, from the support points alone.
real overlap_along(const ccd_shape& a, const ccd_shape& b, const vector& n) {
  ccd_vec3_t up{{n.e1(), n.e2(), n.e3()}}, down{{-n.e1(), -n.e2(), -n.e3()}}, pa, pb;
  ccd_support(&a, &down, &pa);
  ccd_support(&b, &up, &pb);
  return (pb.v[0] - pa.v[0]) * n.e1() + (pb.v[1] - pa.v[1]) * n.e2() + (pb.v[2] - pa.v[2]) * n.e3();
}

// ---- Random configurations ---------------------------------------------------

struct placed_pair {
  shape shape_a, shape_b;
  vector position_a{}, position_b{};
  rotor attitude_a{1, 0, 0, 0}, attitude_b{1, 0, 0, 0};
  ccd_shape ccd_a{}, ccd_b{};
};

class oracle {
 public:
  explicit oracle(std::uint64_t seed) : random_(seed) {}

  real uniform(real low, real high) {
    return std::uniform_real_distribution<real>(low, high)(random_);
  }
  vector unit_vector() {
    while (true) {
      const vector v{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
      const real l = e3ga::norm(v);
      if (l > 0.1 && l <= 1) return v / l;
    }
  }
  rotor attitude() { return e3ga::exp(uniform(-3.2, 3.2) * e3ga::dual(unit_vector())); }

  // The shape's support points at a pose, computed here with the algebra.
  static ccd_shape corners_of(const std::vector<vector>& local, const vector& position,
                              const rotor& attitude) {
    ccd_shape s;
    for (const vector& p : local) s.points.push_back(position + e3ga::apply(attitude, p));
    return s;
  }

  std::vector<vector> hull_points() {
    const int count = int(uniform(8, 21));
    const vector stretch{uniform(0.3, 1), uniform(0.3, 1), uniform(0.3, 1)};
    std::vector<vector> points;
    for (int i = 0; i < count; ++i) {
      points.push_back({stretch.e1() * uniform(-1, 1), stretch.e2() * uniform(-1, 1),
                        stretch.e3() * uniform(-1, 1)});
    }
    return points;
  }
  vector half_extents() { return {uniform(0.1, 1), uniform(0.1, 1), uniform(0.1, 1)}; }
  static std::vector<vector> box_corners(const vector& h) {
    std::vector<vector> corners;
    for (int i = 0; i < 8; ++i) {
      corners.push_back(
          {(i & 1) ? h.e1() : -h.e1(), (i & 2) ? h.e2() : -h.e2(), (i & 4) ? h.e3() : -h.e3()});
    }
    return corners;
  }

  // B placed along a random direction from A at `fraction` of the offset
  // where they touch (found by bisection with libccd): < 1 overlapping,
  // 1 ± 1e-9 touching, > 1 apart.
  void place_apart(placed_pair& p, const std::vector<vector>& local_a,
                   const std::vector<vector>& local_b, real fraction) {
    p.position_a = vector{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
    p.attitude_a = attitude();
    p.attitude_b = attitude();
    const vector direction = unit_vector();
    ccd_shape a = corners_of(local_a, p.position_a, p.attitude_a);
    a.radius = p.ccd_a.radius;
    auto b_at = [&](real offset) {
      ccd_shape b = corners_of(local_b, p.position_a + offset * direction, p.attitude_b);
      b.radius = p.ccd_b.radius;
      return b;
    };
    real low = 0, high = 8;
    for (int i = 0; i < 48; ++i) {
      const real middle = real(0.5) * (low + high);
      (ccd_intersect(a, b_at(middle)) ? low : high) = middle;
    }
    const real offset = real(0.5) * (low + high) * fraction;
    p.position_b = p.position_a + offset * direction;
    p.ccd_a = a;
    p.ccd_b = b_at(offset);
  }

  real fraction(int trial) {
    switch (trial % 3) {
      case 0:
        return uniform(0.4, 0.999);
      case 1:
        return 1 + uniform(-1e-9, 1e-9);
      default:
        return uniform(1.001, 1.6);
    }
  }

 private:
  std::mt19937_64 random_;
};

// ---- The comparison ----------------------------------------------------------

struct tally {
  const char* name;
  int cases = 0, apart = 0, overlapping = 0;
  int ties = 0;           // EPA's direction differs from ours but is as deep: two minima
  int epa_failures = 0;   // EPA's depth is not the overlap along its own direction
  int near_touching = 0;  // libccd's intersection test and ours disagree within its resolution
  real max_certificate_error = 0;  // |overlap along our normal + our signed distance|
  real max_distance_error = 0;     // apart: |ours - bisection|
  real max_depth_error = 0;        // overlapping: |our depth - EPA's|
  real max_normal_error = 0;       // overlapping, one minimum: |our n - EPA's n|

  void print() const {
    std::printf(
        "%s: %d cases, %d apart, %d overlapping (libccd); %d tied minima, %d EPA failures, %d "
        "within libccd's touching resolution; max errors: certificate %.3g, distance %.3g, "
        "depth %.3g, normal %.3g\n",
        name, cases, apart, overlapping, ties, epa_failures, near_touching, max_certificate_error,
        max_distance_error, max_depth_error, max_normal_error);
  }
};

// Tolerances, metres (what each run saw is printed with the tally):
//  - certificate: our signed distance against the gap, or minus the
//    overlap, along our own normal, read from libccd's support points: a
//    lower bound of the distance when apart and an upper bound of the depth
//    when overlapping, so agreement proves ours exact. 1e-12 (seen 1e-13).
//  - resolution: libccd's GJK decides whether two solids meet only to a few
//    1e-8 (bisection distances differ from ours by up to 4.1e-8, where ours
//    meet the certificate to 3e-15; scaling the shapes does not change it).
//    Distances, and shapes it calls touching, are compared to 1e-7.
//  - depth: EPA's depth against ours, where EPA's direction reproduces its
//    own depth. Polytopes 1e-9 (seen 1.2e-15); a capsule's round ends are
//    only approached by EPA's polytope, 1e-6 (seen 9.4e-7).
//  - normal: polytopes 1e-6 (seen 4.4e-13); capsules 5e-3, EPA's direction
//    on a curved surface being good to about sqrt(2 depth error / radius)
//    (seen 2.9e-3). Beyond it with equal depths: a tie of two minima.
struct tolerances {
  real certificate, resolution, depth, normal;
};

void compare(const placed_pair& p, const tolerances& tol, tally& t) {
  const placed_shape a = place(p.shape_a, p.position_a, p.attitude_a);
  const placed_shape b = place(p.shape_b, p.position_b, p.attitude_b);
  const detail::separation ours = detail::convex_separation(a, b);
  ++t.cases;
  ASSERT_NEAR(e3ga::norm(ours.normal), 1, 1e-12) << t.name << " case " << t.cases;
  const real certificate = std::fabs(overlap_along(p.ccd_a, p.ccd_b, ours.normal) + ours.distance);
  t.max_certificate_error = std::max(t.max_certificate_error, certificate);
  EXPECT_LE(certificate, tol.certificate) << t.name << " case " << t.cases;

  // The manifold: points when they overlap, none when apart beyond the
  // margin, and no point deeper than the solids overlap along its normal.
  constexpr real margin = 0.01;
  contact_manifold manifold;
  detail::collide_convex(a, b, margin, manifold);
  if (ours.distance < -tol.resolution) {
    EXPECT_GE(manifold.count, 1) << t.name << " case " << t.cases;
  }
  if (ours.distance > margin + tol.resolution) {
    EXPECT_EQ(manifold.count, 0) << t.name << " case " << t.cases;
  }
  for (int i = 0; i < manifold.count; ++i) {
    const contact_geometry& g = manifold.points[i].geometry;
    EXPECT_NEAR(e3ga::norm(g.normal), 1, 1e-12) << t.name << " case " << t.cases;
    EXPECT_LE(g.depth, overlap_along(p.ccd_a, p.ccd_b, g.normal) + tol.certificate)
        << t.name << " case " << t.cases << " point " << i;
  }

  if (!ccd_intersect(p.ccd_a, p.ccd_b)) {
    ++t.apart;
    const real distance = ccd_distance(p.ccd_a, p.ccd_b);
    const real error = std::fabs(ours.distance - distance);
    t.max_distance_error = std::max(t.max_distance_error, error);
    EXPECT_LE(error, tol.resolution)
        << t.name << " case " << t.cases << ": ours " << ours.distance << ", libccd " << distance;
    return;
  }
  ++t.overlapping;
  ccd_t ccd = make_ccd();
  ccd_real_t depth;
  ccd_vec3_t direction, position;
  if (ccdGJKPenetration(&p.ccd_a, &p.ccd_b, &ccd, &depth, &direction, &position) != 0) {
    // Unscaled, libccd's GJK calls them apart: they touch, to its resolution.
    ++t.near_touching;
    EXPECT_LE(std::fabs(ours.distance), tol.resolution) << t.name << " case " << t.cases;
    return;
  }
  // libccd's direction moves B out of A; ours, from B into A, is its opposite.
  const vector theirs = -vector{real(direction.v[0]), real(direction.v[1]), real(direction.v[2])};
  const real theirs_overlap = overlap_along(p.ccd_a, p.ccd_b, theirs);
  const real error = std::fabs(-ours.distance - depth);
  // Touching, to libccd's resolution: its EPA then starts from a flat
  // simplex and its direction means little; the depths must agree.
  const bool touching = ours.distance > -tol.resolution || depth < tol.resolution;
  if (touching) ++t.near_touching;
  if (touching ? error > 2 * tol.resolution : std::fabs(theirs_overlap - depth) > tol.depth) {
    // EPA lost its way: its depth is not the overlap along its own
    // direction, or (touching) it found a direction of large overlap, not
    // the least. That overlap still bounds the depth: ours must be no deeper.
    ++t.epa_failures;
    EXPECT_LE(-ours.distance, theirs_overlap + tol.certificate) << t.name << " case " << t.cases;
    return;
  }
  if (touching) return;
  t.max_depth_error = std::max(t.max_depth_error, error);
  EXPECT_LE(error, tol.depth) << t.name << " case " << t.cases << ": ours " << -ours.distance
                              << ", libccd " << depth;
  // Where the normals differ, both depths agree: the least translation is
  // not unique (a tie of two axes), and either answer is right.
  const real normal_error = e3ga::norm(ours.normal - theirs);
  if (normal_error > tol.normal) {
    ++t.ties;
  } else {
    t.max_normal_error = std::max(t.max_normal_error, normal_error);
  }
}

constexpr int cases_per_kind = 10000;

TEST(ConvexOracle, hulls_against_hulls_match_libccd) {
  oracle o(0x5eed0001);
  tally t{"hull-hull"};
  for (int trial = 0; trial < cases_per_kind; ++trial) {
    const std::vector<vector> points_a = o.hull_points(), points_b = o.hull_points();
    placed_pair p{shape::convex_hull(points_a), shape::convex_hull(points_b)};
    o.place_apart(p, points_a, points_b, o.fraction(trial));
    compare(p, {1e-12, 1e-7, 1e-9, 1e-6}, t);
    if (HasFatalFailure()) return;
  }
  t.print();
}

TEST(ConvexOracle, boxes_against_boxes_match_libccd) {
  oracle o(0x5eed0002);
  tally t{"box-box"};
  for (int trial = 0; trial < cases_per_kind; ++trial) {
    const vector ha = o.half_extents(), hb = o.half_extents();
    placed_pair p{shape::box(ha), shape::box(hb)};
    o.place_apart(p, oracle::box_corners(ha), oracle::box_corners(hb), o.fraction(trial));
    compare(p, {1e-12, 1e-7, 1e-9, 1e-6}, t);
    if (HasFatalFailure()) return;
  }
  t.print();
}

TEST(ConvexOracle, capsules_against_boxes_match_libccd) {
  oracle o(0x5eed0003);
  tally t{"capsule-box"};
  for (int trial = 0; trial < cases_per_kind; ++trial) {
    const vector h = o.half_extents();
    const real half_height = o.uniform(0, 1), radius = o.uniform(0.1, 0.5);
    const std::vector<vector> segment{{0, 0, -half_height}, {0, 0, half_height}};
    // Either order: the capsule as A, then as B.
    const bool capsule_first = trial % 2 == 0;
    placed_pair p{capsule_first ? shape::capsule(half_height, radius) : shape::box(h),
                  capsule_first ? shape::box(h) : shape::capsule(half_height, radius)};
    (capsule_first ? p.ccd_a : p.ccd_b).radius = radius;
    if (capsule_first) {
      o.place_apart(p, segment, oracle::box_corners(h), o.fraction(trial));
    } else {
      o.place_apart(p, oracle::box_corners(h), segment, o.fraction(trial));
    }
    compare(p, {1e-12, 1e-7, 1e-6, 5e-3}, t);
    if (HasFatalFailure()) return;
  }
  t.print();
}

}  // namespace
}  // namespace gaphys::testing
