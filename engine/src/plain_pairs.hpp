// Plain contacts (frictionless, through the centres) several at a time, a
// lane each, for the sweeps of a double engine on x86-64: what the sweeps
// read of W contacts of one colour, laid out as the W lanes of each number
// (plain_lanes), and one sweep's solve of them: two lanes with SSE2
// (solve_plain_pair), four with AVX and eight with AVX-512 where the
// processor has them (plain_pairs.cpp's solve_plain_quads and
// solve_plain_octets, chosen at run time: the engine is built for the
// x86-64 baseline, which has neither).
//
// The lanes are W contacts of different runs of one colour, next to each
// other in the sweeps' order, whose moving bodies therefore differ; where a
// contact has fewer such neighbours, the lanes left are empty: no mass,
// against a spare body without mass (contact_solver::spare_place), and
// their impulses are zero. Each lane takes the same operations on the same
// numbers as contact_solver::solve_plain on the contact alone, so the
// sweeps end with the same bits on any width.
#pragma once

#include <cstddef>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "gaphys/ga/compiler.hpp"
#include "impulse_row.hpp"

namespace gaphys::detail {

// W contacts' rows: each number's W lanes side by side, so that a sweep
// loads each with one instruction (picked from two constraints, each took
// two, and the sweeps more than a fifth of their instructions).
template <int W>
struct alignas(8 * W) plain_lanes {
  static constexpr int lanes = W;
  double normal_x[W], normal_y[W], normal_z[W];  // n, from B to A
  double target_speed[W], relaxation[W], normal_mass[W], accumulated[W], mass_inverse[W];
  std::uint32_t place_a[W], place_b[W];  // the bodies' places in the plain bodies
};
using plain_pair = plain_lanes<2>;
using plain_quad = plain_lanes<4>;
using plain_octet = plain_lanes<8>;

// The widest plain lanes this processor takes: 8 where it has AVX-512, 4
// where it has AVX (the engine built for x86-64 with GCC or Clang), else 2;
// at most `widest_plain_lanes_allowed` (8; the tests lower it to step the
// narrower sweeps beside the wider ones).
int plain_lanes_here();
extern int widest_plain_lanes_allowed;

#if defined(__SSE2__)

// One sweep of the two contacts of p on `at` (plain_body, by place): each
// lane as solve_plain on its contact alone, in the order of e3ga::scp, with a
// relaxation of 1 in the last sweep. Raises either lane of `largest` by
// their speed changes. (A template, so that a float engine, which never
// calls it, compiles it not at all.)
template <bool last, class Body>
GAPHYS_ALWAYS_INLINE void solve_plain_pair(plain_pair& p, Body* at, __m128d& largest) {
  // A body's z and inverse mass are one aligned pair of doubles.
  static_assert(offsetof(Body, inverse_mass) == 3 * sizeof(double) && alignof(Body) % 16 == 0);
  Body& a0 = at[p.place_a[0]];
  Body& a1 = at[p.place_a[1]];
  Body& b0 = at[p.place_b[0]];
  Body& b1 = at[p.place_b[1]];
  // x, y, z and inverse mass of two bodies, each in the two lanes.
  struct in_lanes {
    __m128d x, y, z, inverse_mass;
  };
  const auto lanes = [](const Body& x0, const Body& x1) {
    const __m128d xy0 = _mm_load_pd(&x0.velocity.c[0]), zm0 = _mm_load_pd(&x0.velocity.c[2]);
    const __m128d xy1 = _mm_load_pd(&x1.velocity.c[0]), zm1 = _mm_load_pd(&x1.velocity.c[2]);
    return in_lanes{_mm_unpacklo_pd(xy0, xy1), _mm_unpackhi_pd(xy0, xy1), _mm_unpacklo_pd(zm0, zm1),
                    _mm_unpackhi_pd(zm0, zm1)};
  };
  auto [ax, ay, az, am] = lanes(a0, a1);
  auto [bx, by, bz, bm] = lanes(b0, b1);
  const __m128d nx = _mm_load_pd(p.normal_x), ny = _mm_load_pd(p.normal_y);
  const __m128d nz = _mm_load_pd(p.normal_z);
  // row_speed: n . (vA - vB).
  __m128d speed = _mm_mul_pd(_mm_sub_pd(ax, bx), nx);
  speed = _mm_add_pd(speed, _mm_mul_pd(_mm_sub_pd(ay, by), ny));
  speed = _mm_add_pd(speed, _mm_mul_pd(_mm_sub_pd(az, bz), nz));
  // normal_impulse (1 x is x: the last sweep's relaxation of 1 multiplies).
  const __m128d relaxation = last ? _mm_set1_pd(1) : _mm_load_pd(p.relaxation);
  const __m128d closing = _mm_sub_pd(_mm_load_pd(p.target_speed), speed);
  const __m128d wanted = _mm_mul_pd(_mm_mul_pd(relaxation, closing), _mm_load_pd(p.normal_mass));
  const __m128d accumulated = _mm_load_pd(p.accumulated);
  const __m128d total = _mm_max_pd(_mm_setzero_pd(), _mm_add_pd(accumulated, wanted));
  const __m128d j = _mm_sub_pd(total, accumulated);
  _mm_store_pd(p.accumulated, total);
  const __m128d magnitude = _mm_andnot_pd(_mm_set1_pd(-0.0), j);
  largest = _mm_max_pd(largest, _mm_mul_pd(magnitude, _mm_load_pd(p.mass_inverse)));
  // row_apply: only a body with mass changes.
  const __m128d ja = _mm_mul_pd(j, am), jb = _mm_mul_pd(j, bm);
  ax = _mm_add_pd(ax, _mm_mul_pd(ja, nx));
  ay = _mm_add_pd(ay, _mm_mul_pd(ja, ny));
  az = _mm_add_pd(az, _mm_mul_pd(ja, nz));
  bx = _mm_sub_pd(bx, _mm_mul_pd(jb, nx));
  by = _mm_sub_pd(by, _mm_mul_pd(jb, ny));
  bz = _mm_sub_pd(bz, _mm_mul_pd(jb, nz));
  const auto store = [](Body& x, __m128d xy, __m128d z) {
    if (!(x.inverse_mass > 0)) return;
    _mm_store_pd(&x.velocity.c[0], xy);
    _mm_store_sd(&x.velocity.c[2], z);
  };
  store(a0, _mm_unpacklo_pd(ax, ay), az);
  store(a1, _mm_unpackhi_pd(ax, ay), _mm_unpackhi_pd(az, az));
  store(b0, _mm_unpacklo_pd(bx, by), bz);
  store(b1, _mm_unpackhi_pd(bx, by), _mm_unpackhi_pd(bz, bz));
}

#endif

}  // namespace gaphys::detail
