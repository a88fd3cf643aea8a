// Mass properties against truths computed here independently: textbook
// closed forms (in full widths and cylinder heights rather than the engine's
// half extents), Monte Carlo integrals with their error bars, the parallel-
// axis theorem applied by hand, and rotation matrices from Rodrigues'
// formula rather than rotors.
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "engine_test_support.hpp"
#include "matrix3.hpp"

namespace gaphys::testing {
namespace {

triple unit(real x, real y, real z) {
  const real l = std::sqrt(x * x + y * y + z * z);
  return {x / l, y / l, z / l};
}

// A point mass m at d from the axis point adds m (|d|^2 1 - d d^T).
matrix parallel_axis(real mass, const triple& d) {
  const real d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  matrix m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[3 * i + j] = mass * ((i == j ? d2 : 0) - d[i] * d[j]);
  return m;
}

// A solid box's inertia about its centre, from its full widths.
matrix box_inertia(real mass, real wx, real wy, real wz) {
  return diagonal(mass * (wy * wy + wz * wz) / 12, mass * (wx * wx + wz * wz) / 12,
                  mass * (wx * wx + wy * wy) / 12);
}

::testing::AssertionResult rows_near(const inertia& actual, const matrix& expected, real relative) {
  real scale = 0;
  for (real x : expected) scale = std::max(scale, std::fabs(x));
  for (int i = 0; i < 9; ++i) {
    if (!(std::fabs(actual.rows()[i] - expected[i]) <= relative * scale)) {
      return ::testing::AssertionFailure()
             << "entry " << i << ": " << actual.rows()[i] << " vs " << expected[i] << " (tolerance "
             << relative * scale << ")";
    }
  }
  return ::testing::AssertionSuccess();
}

triple components(const vector& v) { return {x(v), y(v), z(v)}; }

class MassPropertiesTest : public engine_test {};

TEST_F(MassPropertiesTest, solids_are_the_shapes_with_a_volume) {
  for (const shape& s : {shape::sphere(0.5), shape::box(vector{1, 2, 3}), shape::capsule(1, 0.5),
                         shape::convex_hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}})}) {
    EXPECT_TRUE(is_solid(s));
    EXPECT_GT(volume(s), 0);
  }
  for (const shape& s : {shape::plane(vector{0, 0, 1}, 0), shape::point()}) {
    EXPECT_FALSE(is_solid(s));
    EXPECT_EQ(volume(s), 0);
  }
}

TEST_F(MassPropertiesTest, of_a_sphere) {
  const mass_properties p = solid_mass_properties(shape::sphere(0.5), 2000);
  const real mass = 2000 * 4 * pi * 0.125 / 3;
  EXPECT_NEAR(p.mass, mass, tolerance(1e-12, 1e-6) * mass);
  EXPECT_TRUE(near(p.center, vector{}, 0));
  const real moment = 2 * mass * 0.25 / 5;
  EXPECT_TRUE(rows_near(p.inertia, diagonal(moment, moment, moment), tolerance(1e-14, 1e-6)));
  EXPECT_TRUE(p.inertia.is_isotropic());
}

TEST_F(MassPropertiesTest, of_a_box) {
  const mass_properties p = solid_mass_properties(shape::box(vector{0.5, 1, 2}), 3);
  const real mass = 3 * (1 * 2 * 4);  // density times width x depth x height
  EXPECT_NEAR(p.mass, mass, tolerance(1e-12, 1e-6) * mass);
  EXPECT_TRUE(near(p.center, vector{}, 0));
  EXPECT_TRUE(rows_near(p.inertia, box_inertia(mass, 1, 2, 4), tolerance(1e-14, 1e-6)));
}

// Millimetre bodies of a gram: the moments (1e-10 kg m^2) and their inverses
// are ordinary numbers in float too, though at the unit density the shapes'
// moments are first found at, their determinant (1e-51) is not. Every body
// is made, with the closed-form moments where there is one, and an inverse
// that undoes the tensor.
TEST_F(MassPropertiesTest, of_millimetre_bodies_of_a_gram_in_either_precision) {
  const real half = 0.0005, mass = 0.001;
  const std::vector<vector> pyramid = {vector{-half, -half, 0}, vector{half, -half, 0},
                                       vector{half, half, 0}, vector{-half, half, 0},
                                       vector{0, 0, 2 * half}};
  const std::vector<shape> shapes = {shape::box(vector{half, half, half}), shape::sphere(half),
                                     shape::capsule(half, real(0.6) * half),
                                     shape::convex_hull(pyramid)};
  const real closed_form[] = {mass * (2 * half * half) / 3, real(0.4) * mass * half * half};
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    for (const bool by_density : {false, true}) {
      world w = make_world();
      body_definition d;
      d.shape = shapes[k];
      if (by_density) {
        d.density = 1000;
      } else {
        d.mass = mass;
      }
      const body& b = w.at(w.create_body(d));
      const bivector turn{1, 0, 0};
      const bivector momentum = b.body_inertia()(turn);
      EXPECT_TRUE(near(b.body_inertia().inverse(momentum), turn, tolerance(1e-12, 1e-5)))
          << "shape " << k << (by_density ? " by density" : "");
      if (k < 2 && !by_density) {
        EXPECT_NEAR(momentum.e12(), closed_form[k], tolerance(1e-12, 1e-5) * closed_form[k]) << k;
      }
    }
  }
}

// The textbook capsule: a cylinder of height H and two hemispheres, each of
// mass m_h = rho (2/3) pi r^3:
//   about the axis:  m_c r^2 / 2 + 2 (2/5) m_h r^2
//   across it:       m_c (H^2 / 12 + r^2 / 4) + 2 m_h (2 r^2 / 5 + H^2 / 4 + 3 H r / 8)
TEST_F(MassPropertiesTest, of_a_capsule) {
  const real density = 7, r = 0.3, height = 1.7;
  const mass_properties p = solid_mass_properties(shape::capsule(height / 2, r), density);
  const real m_c = density * pi * r * r * height;
  const real m_h = density * 2 * pi * r * r * r / 3;
  EXPECT_NEAR(p.mass, m_c + 2 * m_h, tolerance(1e-13, 1e-6) * p.mass);
  EXPECT_TRUE(near(p.center, vector{}, 0));
  const real axial = m_c * r * r / 2 + 2 * real(0.4) * m_h * r * r;
  const real across = m_c * (height * height / 12 + r * r / 4) +
                      2 * m_h * (2 * r * r / 5 + height * height / 4 + 3 * height * r / 8);
  EXPECT_TRUE(rows_near(p.inertia, diagonal(across, across, axial), tolerance(1e-13, 1e-6)));
  EXPECT_NEAR(volume(shape::capsule(height / 2, r)), p.mass / density, tolerance(1e-15, 1e-7));

  // Without its cylinder, a sphere.
  const mass_properties ball = solid_mass_properties(shape::capsule(0, r), density);
  const mass_properties sphere = solid_mass_properties(shape::sphere(r), density);
  EXPECT_NEAR(ball.mass, sphere.mass, tolerance(1e-14, 1e-6) * sphere.mass);
  EXPECT_TRUE(rows_near(ball.inertia, sphere.inertia.rows(), tolerance(1e-14, 1e-6)));
}

TEST_F(MassPropertiesTest, volumes) {
  EXPECT_NEAR(volume(shape::sphere(2)), 32 * pi / 3, tolerance(1e-13, 1e-6));
  EXPECT_EQ(volume(shape::box(vector{0.5, 1, 2})), 8);
  EXPECT_NEAR(volume(shape::capsule(1, 1)), 2 * pi + 4 * pi / 3, tolerance(1e-13, 1e-6));
  EXPECT_NEAR(volume(shape::convex_hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}})), 1.0 / 6,
              tolerance(1e-16, 1e-7));
  EXPECT_EQ(volume(shape::plane(vector{0, 0, 1}, 0)), 0);
  EXPECT_EQ(volume(shape::point()), 0);
}

// The hull of a box's corners, away from the origin, is that box.
TEST_F(MassPropertiesTest, of_a_hull_of_box_corners_equal_the_box) {
  const vector h{0.3, 0.7, 1.1}, centre{2, -1, 0.5};
  std::vector<vector> corners;
  for (int i = 0; i < 8; ++i) {
    corners.push_back(centre +
                      vector{i & 1 ? x(h) : -x(h), i & 2 ? y(h) : -y(h), i & 4 ? z(h) : -z(h)});
  }
  const mass_properties hull = solid_mass_properties(shape::convex_hull(corners), 5);
  const mass_properties box = solid_mass_properties(shape::box(h), 5);
  EXPECT_NEAR(hull.mass, box.mass, tolerance(1e-12, 1e-6) * box.mass);
  EXPECT_TRUE(near(hull.center, centre, tolerance(1e-12, 1e-6) * length(centre)));
  EXPECT_TRUE(rows_near(hull.inertia, box.inertia.rows(), tolerance(1e-12, 1e-6)));
}

// Monte Carlo over the bounding box, the hull's inside being the face
// planes' intersection: volume, first moments and the inertia about the
// origin, each within 4 standard errors (estimated from the same samples).
TEST_F(MassPropertiesTest, of_a_hull_of_random_points_match_monte_carlo) {
  std::vector<vector> points;
  for (int i = 0; i < 40; ++i) {
    points.push_back({uniform(-1, 1.5), uniform(-0.5, 0.8), uniform(0.2, 1.4)});
  }
  const shape hull = shape::convex_hull(points);
  const convex_polyhedron& poly = *hull.polyhedron();
  const real density = 2.5;
  const mass_properties p = solid_mass_properties(hull, density);

  triple low{1e9, 1e9, 1e9}, high{-1e9, -1e9, -1e9};
  for (const vector& v : poly.vertices) {
    for (int k = 0; k < 3; ++k)
      low[k] = std::min(low[k], v.c[k]), high[k] = std::max(high[k], v.c[k]);
  }
  const real box_volume = (high[0] - low[0]) * (high[1] - low[1]) * (high[2] - low[2]);
  // Integrands: 1, x, y, z, and the origin inertia's six entries.
  constexpr int quantities = 10;
  std::array<real, quantities> sum{}, sum_squares{};
  const int samples = 200000;
  std::mt19937_64 sampler(77);
  std::uniform_real_distribution<real> unit(0, 1);
  for (int s = 0; s < samples; ++s) {
    const triple q{low[0] + (high[0] - low[0]) * unit(sampler),
                   low[1] + (high[1] - low[1]) * unit(sampler),
                   low[2] + (high[2] - low[2]) * unit(sampler)};
    bool inside = true;
    for (const polyhedron_face& f : poly.faces) {
      if (x(f.normal) * q[0] + y(f.normal) * q[1] + z(f.normal) * q[2] > f.offset) inside = false;
    }
    if (!inside) continue;
    const real r2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    const std::array<real, quantities> g{1,
                                         q[0],
                                         q[1],
                                         q[2],
                                         r2 - q[0] * q[0],
                                         r2 - q[1] * q[1],
                                         r2 - q[2] * q[2],
                                         -q[0] * q[1],
                                         -q[0] * q[2],
                                         -q[1] * q[2]};
    for (int k = 0; k < quantities; ++k) sum[k] += g[k], sum_squares[k] += g[k] * g[k];
  }

  // The engine's figures as the same integrals (per unit density), about
  // the origin: J_origin = J_centre + V (|c|^2 1 - c c^T).
  const real v = p.mass / density;
  const triple c = components(p.center);
  matrix j = p.inertia.rows();
  for (real& e : j) e /= density;
  j = plus(j, parallel_axis(v, c));
  const std::array<real, quantities> engine{v,    v * c[0], v * c[1], v * c[2], j[0],
                                            j[4], j[8],     j[1],     j[2],     j[5]};
  for (int k = 0; k < quantities; ++k) {
    const real mean = sum[k] / samples;
    const real variance = sum_squares[k] / samples - mean * mean;
    const real estimate = box_volume * mean;
    const real sigma = box_volume * std::sqrt(variance / samples);
    EXPECT_LT(std::fabs(engine[k] - estimate), 4 * sigma + tolerance(1e-12, 1e-6))
        << "integral " << k << ": engine " << engine[k] << ", Monte Carlo " << estimate << " +- "
        << sigma;
  }
  EXPECT_GT(sum[0], 0.2 * samples);  // the hull fills a fair part of its box
}

// The capsule's hemispheres by Monte Carlo too: the closed form's shift of
// each cap (3r/8 off its face) is where a slip would hide.
TEST_F(MassPropertiesTest, of_a_capsule_match_monte_carlo) {
  const real h = 0.6, r = 0.4;
  const mass_properties p = solid_mass_properties(shape::capsule(h, r), 1);
  const int samples = 200000;
  std::mt19937_64 sampler(78);
  std::uniform_real_distribution<real> across(-r, r), along(-h - r, h + r);
  std::array<real, 3> sum{}, sum_squares{};
  for (int s = 0; s < samples; ++s) {
    const real qx = across(sampler), qy = across(sampler), qz = along(sampler);
    const real off = std::max(std::fabs(qz) - h, real(0));
    if (qx * qx + qy * qy + off * off > r * r) continue;
    const std::array<real, 3> g{1, qy * qy + qz * qz, qx * qx + qy * qy};
    for (int k = 0; k < 3; ++k) sum[k] += g[k], sum_squares[k] += g[k] * g[k];
  }
  const real box_volume = 4 * r * r * 2 * (h + r);
  const std::array<real, 3> engine{p.mass, p.inertia.rows()[0], p.inertia.rows()[8]};
  for (int k = 0; k < 3; ++k) {
    const real mean = sum[k] / samples;
    const real sigma = box_volume * std::sqrt((sum_squares[k] / samples - mean * mean) / samples);
    EXPECT_LT(std::fabs(engine[k] - box_volume * mean), 4 * sigma)
        << "integral " << k << ": engine " << engine[k] << ", Monte Carlo " << box_volume * mean
        << " +- " << sigma;
  }
}

// A box turned about a skew axis: J' = M diag M^T, M from Rodrigues.
TEST_F(MassPropertiesTest, of_a_turned_box_have_its_off_diagonals) {
  const triple axis = unit(1, -2, 0.5);
  const real angle = 0.9, density = 4;
  const attached_shape turned{shape::box(vector{0.2, 0.5, 1}), vector{}, rotor_of(axis, angle)};
  const mass_properties p = solid_mass_properties(std::vector<attached_shape>{turned}, density);
  const real mass = density * 0.4 * 1 * 2;
  const matrix m = rotation(axis, angle);
  const matrix expected = product(product(m, box_inertia(mass, 0.4, 1, 2)), transposed(m));
  EXPECT_NEAR(p.mass, mass, tolerance(1e-13, 1e-6) * mass);
  EXPECT_TRUE(near(p.center, vector{}, tolerance(1e-15, 1e-7)));
  EXPECT_TRUE(rows_near(p.inertia, expected, tolerance(1e-13, 1e-6)));
  EXPECT_GT(std::fabs(p.inertia.rows()[1]), 0.05 * p.inertia.rows()[0]);  // really off-diagonal
}

// One shape at a pose: its single-shape properties turned and moved.
TEST_F(MassPropertiesTest, of_one_posed_shape_are_its_own_turned_and_moved) {
  std::vector<vector> points;
  for (int i = 0; i < 30; ++i) points.push_back({uniform(0, 1), uniform(0, 2), uniform(-1, 0)});
  const shape hull = shape::convex_hull(points);
  const mass_properties own = solid_mass_properties(hull, 3);
  const triple axis = unit(0.3, 0.4, -1);
  const real angle = 2.1;
  const vector offset{1, -2, 3};
  const mass_properties posed =
      solid_mass_properties(std::vector<attached_shape>{{hull, offset, rotor_of(axis, angle)}}, 3);

  const matrix m = rotation(axis, angle);
  const triple c = components(own.center);
  const vector turned_centre{m[0] * c[0] + m[1] * c[1] + m[2] * c[2],
                             m[3] * c[0] + m[4] * c[1] + m[5] * c[2],
                             m[6] * c[0] + m[7] * c[1] + m[8] * c[2]};
  EXPECT_NEAR(posed.mass, own.mass, tolerance(1e-14, 1e-6) * own.mass);
  EXPECT_TRUE(near(posed.center, offset + turned_centre, tolerance(1e-13, 1e-6)));
  EXPECT_TRUE(
      rows_near(posed.inertia, product(product(m, own.inertia.rows()), transposed(m)), tolerance(1e-13, 1e-6)));
}

// A table: a top on four legs, summed by hand with the parallel-axis
// theorem about the centre of mass.
TEST_F(MassPropertiesTest, of_a_table_sum_their_parts) {
  const real density = 600;
  const real top_w = 2, top_d = 1.2, top_t = 0.1, leg_w = 0.1, leg_h = 0.7;
  std::vector<attached_shape> table{
      {shape::box(vector{top_w / 2, top_d / 2, top_t / 2}), vector{0, 0, leg_h + top_t / 2}}};
  std::vector<triple> leg_centres;
  for (real sx : {-1.0, 1.0}) {
    for (real sy : {-1.0, 1.0}) {
      const triple at{sx * real(0.9), sy * real(0.5), leg_h / 2};
      leg_centres.push_back(at);
      table.push_back(
          {shape::box(vector{leg_w / 2, leg_w / 2, leg_h / 2}), vector{at[0], at[1], at[2]}});
    }
  }
  table.push_back({shape::point(), vector{5, 5, 5}});  // adds nothing
  const mass_properties p = solid_mass_properties(table, density);

  const real top_mass = density * top_w * top_d * top_t;
  const real leg_mass = density * leg_w * leg_w * leg_h;
  const real mass = top_mass + 4 * leg_mass;
  const real centre_z = (top_mass * (leg_h + top_t / 2) + 4 * leg_mass * leg_h / 2) / mass;
  matrix expected = plus(box_inertia(top_mass, top_w, top_d, top_t),
                         parallel_axis(top_mass, {0, 0, leg_h + top_t / 2 - centre_z}));
  for (const triple& at : leg_centres) {
    expected = plus(expected, plus(box_inertia(leg_mass, leg_w, leg_w, leg_h),
                                   parallel_axis(leg_mass, {at[0], at[1], at[2] - centre_z})));
  }
  EXPECT_NEAR(p.mass, mass, tolerance(1e-12, 1e-6) * mass);
  EXPECT_TRUE(near(p.center, vector{0, 0, centre_z}, tolerance(1e-14, 1e-6)));
  EXPECT_TRUE(rows_near(p.inertia, expected, tolerance(1e-13, 1e-6)));
}

// Two boxes at turned poses: each turned by its matrix, then shifted.
TEST_F(MassPropertiesTest, of_two_turned_boxes_sum_their_parts) {
  const triple axis_a = unit(0, 1, 1), axis_b = unit(1, 0.2, -0.3);
  const real angle_a = 0.6, angle_b = -1.3;
  const triple at_a{-1, 0.5, 0}, at_b{0.8, 0, 0.4};
  const mass_properties p = solid_mass_properties(
      std::vector<attached_shape>{{shape::box(vector{0.5, 0.25, 0.1}),
                                   vector{at_a[0], at_a[1], at_a[2]}, rotor_of(axis_a, angle_a)},
                                  {shape::box(vector{0.2, 0.2, 0.6}),
                                   vector{at_b[0], at_b[1], at_b[2]}, rotor_of(axis_b, angle_b)}},
      1);
  const real mass_a = 1 * 0.5 * 0.2, mass_b = 0.4 * 0.4 * 1.2;
  const real mass = mass_a + mass_b;
  triple centre;
  for (int k = 0; k < 3; ++k) centre[k] = (mass_a * at_a[k] + mass_b * at_b[k]) / mass;
  const matrix ma = rotation(axis_a, angle_a), mb = rotation(axis_b, angle_b);
  matrix expected = plus(product(product(ma, box_inertia(mass_a, 1, 0.5, 0.2)), transposed(ma)),
                         product(product(mb, box_inertia(mass_b, 0.4, 0.4, 1.2)), transposed(mb)));
  expected =
      plus(expected,
           parallel_axis(mass_a, {at_a[0] - centre[0], at_a[1] - centre[1], at_a[2] - centre[2]}));
  expected =
      plus(expected,
           parallel_axis(mass_b, {at_b[0] - centre[0], at_b[1] - centre[1], at_b[2] - centre[2]}));
  EXPECT_NEAR(p.mass, mass, tolerance(1e-13, 1e-6) * mass);
  EXPECT_TRUE(near(p.center, vector{centre[0], centre[1], centre[2]}, tolerance(1e-14, 1e-6)));
  EXPECT_TRUE(rows_near(p.inertia, expected, tolerance(1e-13, 1e-6)));
}

TEST_F(MassPropertiesTest, reject_what_has_no_mass) {
  const shape ball = shape::sphere(1);
  EXPECT_TRUE(rejects([&] { solid_mass_properties(ball, 0); }, "density"));
  EXPECT_TRUE(rejects([&] { solid_mass_properties(ball, -1); }, "density"));
  EXPECT_TRUE(rejects([&] { solid_mass_properties(ball, nan); }, "density"));
  EXPECT_TRUE(
      rejects([&] { solid_mass_properties(std::vector<attached_shape>{{ball}}, nan); }, "density"));
  EXPECT_TRUE(rejects(
      [] {
        solid_mass_properties(shape::plane(vector{0, 0, 1}, 0), 1);
      },
      "no volume"));
  EXPECT_TRUE(rejects([] { solid_mass_properties(shape::point(), 1); }, "no volume"));
  EXPECT_TRUE(
      rejects([] { solid_mass_properties(std::vector<attached_shape>{}, 1); }, "solid shape"));
  EXPECT_TRUE(rejects(
      [] {
        solid_mass_properties(
            std::vector<attached_shape>{{shape::point()}, {shape::plane(vector{1, 0, 0}, 1)}}, 1);
      },
      "solid shape"));
  EXPECT_TRUE(rejects(
      [&] {
        solid_mass_properties(std::vector<attached_shape>{{ball, vector{nan, 0, 0}}}, 1);
      },
      "shape offset"));
  EXPECT_TRUE(rejects(
      [&] {
        solid_mass_properties(std::vector<attached_shape>{{ball, vector{}, rotor{0, 0, 0, 0}}}, 1);
      },
      "shape attitude"));
}

}  // namespace
}  // namespace gaphys::testing
