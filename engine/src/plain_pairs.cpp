// The plain sweeps of a double engine on x86-64 on several contacts at
// once (plain_pairs.hpp): each part's contacts put in lanes before the
// sweeps, solved two, four or eight at a time in them, their impulses back
// into the constraints after.
#include "plain_pairs.hpp"

#include <algorithm>
#include <type_traits>

#include "contact_solver.hpp"

// Four lanes need AVX and eight AVX-512, which the x86-64 baseline the
// engine is built for lacks: the functions that solve them are built for
// those on their own (target), and called only where the processor has them.
// (Each width's sweep is written out: GCC inlines no function of one target
// into a template of the default target, nor returns a wide vector from
// it, so one template over the widths' instructions cannot serve both.)
#if defined(__SSE2__) && defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define GAPHYS_PLAIN_WIDE_LANES 1
#include <immintrin.h>
#define GAPHYS_AVX __attribute__((target("avx")))
#define GAPHYS_AVX512 __attribute__((target("avx512f")))
#else
#define GAPHYS_PLAIN_WIDE_LANES 0
#endif

namespace gaphys {

namespace detail {

int widest_plain_lanes_allowed = 8;

int plain_lanes_here() {
#if GAPHYS_PLAIN_WIDE_LANES
  // The widest the processor has (and the system keeps the registers of).
  static const int widest = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f") ? 8 : __builtin_cpu_supports("avx") ? 4 : 2;
  }();
  return std::min(widest, std::max(widest_plain_lanes_allowed, 2));
#else
  return 2;
#endif
}

#if GAPHYS_PLAIN_WIDE_LANES

namespace {

// x, y, z and inverse mass of the plain bodies at four places, each in the
// four lanes (a 4 x 4 transpose of their rows).
template <class Body>
GAPHYS_AVX inline __attribute__((always_inline)) void gather_bodies(const Body* at,
                                                                    const std::uint32_t* place,
                                                                    __m256d& x, __m256d& y,
                                                                    __m256d& z, __m256d& m) {
  static_assert(sizeof(Body) == 32 && alignof(Body) == 32 && offsetof(Body, inverse_mass) == 24);
  const __m256d r0 = _mm256_load_pd(&at[place[0]].velocity.c[0]);  // x0 y0 z0 m0
  const __m256d r1 = _mm256_load_pd(&at[place[1]].velocity.c[0]);
  const __m256d r2 = _mm256_load_pd(&at[place[2]].velocity.c[0]);
  const __m256d r3 = _mm256_load_pd(&at[place[3]].velocity.c[0]);
  const __m256d xz01 = _mm256_unpacklo_pd(r0, r1), ym01 = _mm256_unpackhi_pd(r0, r1);
  const __m256d xz23 = _mm256_unpacklo_pd(r2, r3), ym23 = _mm256_unpackhi_pd(r2, r3);
  x = _mm256_permute2f128_pd(xz01, xz23, 0x20);
  z = _mm256_permute2f128_pd(xz01, xz23, 0x31);
  y = _mm256_permute2f128_pd(ym01, ym23, 0x20);
  m = _mm256_permute2f128_pd(ym01, ym23, 0x31);
}

// The lanes' velocities back into the bodies with mass (their inverse
// masses, m, are stored as they were read).
template <class Body>
GAPHYS_AVX inline __attribute__((always_inline)) void scatter_bodies(Body* at,
                                                                     const std::uint32_t* place,
                                                                     __m256d x, __m256d y,
                                                                     __m256d z, __m256d m) {
  const __m256d xy02 = _mm256_unpacklo_pd(x, y), xy13 = _mm256_unpackhi_pd(x, y);
  const __m256d zm02 = _mm256_unpacklo_pd(z, m), zm13 = _mm256_unpackhi_pd(z, m);
  const __m256d rows[4] = {
      _mm256_permute2f128_pd(xy02, zm02, 0x20), _mm256_permute2f128_pd(xy13, zm13, 0x20),
      _mm256_permute2f128_pd(xy02, zm02, 0x31), _mm256_permute2f128_pd(xy13, zm13, 0x31)};
  // (!(m > 0), as solve_plain_pair: a NaN mass is no mass.)
  const int moving = _mm256_movemask_pd(_mm256_cmp_pd(m, _mm256_setzero_pd(), _CMP_GT_OQ));
  for (int lane = 0; lane < 4; ++lane) {
    if (moving & (1 << lane)) _mm256_store_pd(&at[place[lane]].velocity.c[0], rows[lane]);
  }
}

// One sweep of quads [first, end): solve_plain_pair's operations, in its
// order, on four lanes.
template <bool last, class Body>
GAPHYS_AVX void solve_plain_quads(plain_quad* quads, std::size_t first, std::size_t end, Body* at,
                                  double& largest) {
  const __m256d zero = _mm256_setzero_pd();
  __m256d most = zero;
  for (std::size_t q = first; q < end; ++q) {
    plain_quad& p = quads[q];
    __m256d ax, ay, az, am, bx, by, bz, bm;
    gather_bodies(at, p.place_a, ax, ay, az, am);
    gather_bodies(at, p.place_b, bx, by, bz, bm);
    const __m256d nx = _mm256_load_pd(p.normal_x), ny = _mm256_load_pd(p.normal_y);
    const __m256d nz = _mm256_load_pd(p.normal_z);
    __m256d speed = _mm256_mul_pd(_mm256_sub_pd(ax, bx), nx);
    speed = _mm256_add_pd(speed, _mm256_mul_pd(_mm256_sub_pd(ay, by), ny));
    speed = _mm256_add_pd(speed, _mm256_mul_pd(_mm256_sub_pd(az, bz), nz));
    const __m256d relaxation = last ? _mm256_set1_pd(1) : _mm256_load_pd(p.relaxation);
    const __m256d closing = _mm256_sub_pd(_mm256_load_pd(p.target_speed), speed);
    const __m256d wanted =
        _mm256_mul_pd(_mm256_mul_pd(relaxation, closing), _mm256_load_pd(p.normal_mass));
    const __m256d accumulated = _mm256_load_pd(p.accumulated);
    const __m256d total = _mm256_max_pd(zero, _mm256_add_pd(accumulated, wanted));
    const __m256d j = _mm256_sub_pd(total, accumulated);
    _mm256_store_pd(p.accumulated, total);
    const __m256d magnitude = _mm256_andnot_pd(_mm256_set1_pd(-0.0), j);
    most = _mm256_max_pd(most, _mm256_mul_pd(magnitude, _mm256_load_pd(p.mass_inverse)));
    const __m256d ja = _mm256_mul_pd(j, am), jb = _mm256_mul_pd(j, bm);
    ax = _mm256_add_pd(ax, _mm256_mul_pd(ja, nx));
    ay = _mm256_add_pd(ay, _mm256_mul_pd(ja, ny));
    az = _mm256_add_pd(az, _mm256_mul_pd(ja, nz));
    bx = _mm256_sub_pd(bx, _mm256_mul_pd(jb, nx));
    by = _mm256_sub_pd(by, _mm256_mul_pd(jb, ny));
    bz = _mm256_sub_pd(bz, _mm256_mul_pd(jb, nz));
    scatter_bodies(at, p.place_a, ax, ay, az, am);
    scatter_bodies(at, p.place_b, bx, by, bz, bm);
  }
  // (The largest of numbers, none a NaN, does not depend on their order.)
  const __m128d half = _mm_max_pd(_mm256_castpd256_pd128(most), _mm256_extractf128_pd(most, 1));
  const __m128d one = _mm_max_sd(half, _mm_unpackhi_pd(half, half));
  largest = std::max(largest, _mm_cvtsd_f64(one));
}

// (GCC 12's AVX-512 intrinsics pass _mm512_undefined_pd() where a result
// takes no lane from it, and GCC then warns that it is, or may be, used
// uninitialized.)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"

// x, y, z and inverse mass of the plain bodies at eight places, each in the
// eight lanes: rows k and k + 4 side by side in a, then their x and z, y and
// m in pairs (unpack), then each number's pairs together (permute).
template <class Body>
GAPHYS_AVX512 inline __attribute__((always_inline)) void gather_bodies(const Body* at,
                                                                       const std::uint32_t* place,
                                                                       __m512d& x, __m512d& y,
                                                                       __m512d& z, __m512d& m) {
  static_assert(sizeof(Body) == 32 && alignof(Body) == 32 && offsetof(Body, inverse_mass) == 24);
  __m512d a[4];
  for (int k = 0; k < 4; ++k) {
    const __m256d low = _mm256_load_pd(&at[place[k]].velocity.c[0]);
    const __m256d high = _mm256_load_pd(&at[place[k + 4]].velocity.c[0]);
    a[k] = _mm512_insertf64x4(_mm512_castpd256_pd512(low), high, 1);
  }
  const __m512d xz01 = _mm512_unpacklo_pd(a[0], a[1]);  // x0 x1 z0 z1 x4 x5 z4 z5
  const __m512d ym01 = _mm512_unpackhi_pd(a[0], a[1]);  // y0 y1 m0 m1 y4 y5 m4 m5
  const __m512d xz23 = _mm512_unpacklo_pd(a[2], a[3]);
  const __m512d ym23 = _mm512_unpackhi_pd(a[2], a[3]);
  const __m512i first = _mm512_setr_epi64(0, 1, 8, 9, 4, 5, 12, 13);
  const __m512i second = _mm512_setr_epi64(2, 3, 10, 11, 6, 7, 14, 15);
  x = _mm512_permutex2var_pd(xz01, first, xz23);
  z = _mm512_permutex2var_pd(xz01, second, xz23);
  y = _mm512_permutex2var_pd(ym01, first, ym23);
  m = _mm512_permutex2var_pd(ym01, second, ym23);
}

// The eight lanes' velocities back into the bodies with mass (the gather's
// steps undone).
template <class Body>
GAPHYS_AVX512 inline __attribute__((always_inline)) void scatter_bodies(Body* at,
                                                                        const std::uint32_t* place,
                                                                        __m512d x, __m512d y,
                                                                        __m512d z, __m512d m) {
  const __m512i first = _mm512_setr_epi64(0, 1, 8, 9, 4, 5, 12, 13);
  const __m512i second = _mm512_setr_epi64(2, 3, 10, 11, 6, 7, 14, 15);
  const __m512d xz01 = _mm512_permutex2var_pd(x, first, z);
  const __m512d xz23 = _mm512_permutex2var_pd(x, second, z);
  const __m512d ym01 = _mm512_permutex2var_pd(y, first, m);
  const __m512d ym23 = _mm512_permutex2var_pd(y, second, m);
  const __m512d a[4] = {_mm512_unpacklo_pd(xz01, ym01), _mm512_unpackhi_pd(xz01, ym01),
                        _mm512_unpacklo_pd(xz23, ym23), _mm512_unpackhi_pd(xz23, ym23)};
  // (!(m > 0), as solve_plain_pair: a NaN mass is no mass.)
  const unsigned moving = _mm512_cmp_pd_mask(m, _mm512_setzero_pd(), _CMP_GT_OQ);
  for (int k = 0; k < 4; ++k) {
    if (moving & (1u << k))
      _mm256_store_pd(&at[place[k]].velocity.c[0], _mm512_castpd512_pd256(a[k]));
    if (moving & (1u << (k + 4))) {
      _mm256_store_pd(&at[place[k + 4]].velocity.c[0], _mm512_extractf64x4_pd(a[k], 1));
    }
  }
}

// One sweep of octets [first, end): solve_plain_pair's operations, in its
// order, on eight lanes.
template <bool last, class Body>
GAPHYS_AVX512 void solve_plain_octets(plain_octet* octets, std::size_t first, std::size_t end,
                                      Body* at, double& largest) {
  const __m512d zero = _mm512_setzero_pd();
  __m512d most = zero;
  for (std::size_t o = first; o < end; ++o) {
    plain_octet& p = octets[o];
    __m512d ax, ay, az, am, bx, by, bz, bm;
    gather_bodies(at, p.place_a, ax, ay, az, am);
    gather_bodies(at, p.place_b, bx, by, bz, bm);
    const __m512d nx = _mm512_load_pd(p.normal_x), ny = _mm512_load_pd(p.normal_y);
    const __m512d nz = _mm512_load_pd(p.normal_z);
    __m512d speed = _mm512_mul_pd(_mm512_sub_pd(ax, bx), nx);
    speed = _mm512_add_pd(speed, _mm512_mul_pd(_mm512_sub_pd(ay, by), ny));
    speed = _mm512_add_pd(speed, _mm512_mul_pd(_mm512_sub_pd(az, bz), nz));
    const __m512d relaxation = last ? _mm512_set1_pd(1) : _mm512_load_pd(p.relaxation);
    const __m512d closing = _mm512_sub_pd(_mm512_load_pd(p.target_speed), speed);
    const __m512d wanted =
        _mm512_mul_pd(_mm512_mul_pd(relaxation, closing), _mm512_load_pd(p.normal_mass));
    const __m512d accumulated = _mm512_load_pd(p.accumulated);
    const __m512d total = _mm512_max_pd(zero, _mm512_add_pd(accumulated, wanted));
    const __m512d j = _mm512_sub_pd(total, accumulated);
    _mm512_store_pd(p.accumulated, total);
    const __m512d magnitude = _mm512_abs_pd(j);
    most = _mm512_max_pd(most, _mm512_mul_pd(magnitude, _mm512_load_pd(p.mass_inverse)));
    const __m512d ja = _mm512_mul_pd(j, am), jb = _mm512_mul_pd(j, bm);
    ax = _mm512_add_pd(ax, _mm512_mul_pd(ja, nx));
    ay = _mm512_add_pd(ay, _mm512_mul_pd(ja, ny));
    az = _mm512_add_pd(az, _mm512_mul_pd(ja, nz));
    bx = _mm512_sub_pd(bx, _mm512_mul_pd(jb, nx));
    by = _mm512_sub_pd(by, _mm512_mul_pd(jb, ny));
    bz = _mm512_sub_pd(bz, _mm512_mul_pd(jb, nz));
    scatter_bodies(at, p.place_a, ax, ay, az, am);
    scatter_bodies(at, p.place_b, bx, by, bz, bm);
  }
  // (The largest of numbers, none a NaN, does not depend on their order.)
  const __m256d half = _mm256_max_pd(_mm512_castpd512_pd256(most), _mm512_extractf64x4_pd(most, 1));
  const __m128d quarter = _mm_max_pd(_mm256_castpd256_pd128(half), _mm256_extractf128_pd(half, 1));
  const __m128d one = _mm_max_sd(quarter, _mm_unpackhi_pd(quarter, quarter));
  largest = std::max(largest, _mm_cvtsd_f64(one));
}

#pragma GCC diagnostic pop

}  // namespace

#endif

}  // namespace detail

int contact_solver::plain_lanes() {
#if defined(__SSE2__)
  return std::is_same_v<real, double> ? detail::plain_lanes_here() : 0;
#else
  return 0;
#endif
}

// visit(records): the records of plain_lanes_'s width.
template <class Visit>
void contact_solver::with_plain_records(const Visit& visit) {
  if (plain_lanes_ == 8) {
    visit(plain_octets_);
  } else if (plain_lanes_ == 4) {
    visit(plain_quads_);
  } else {
    visit(plain_pairs_);
  }
}

void contact_solver::put_plain_contacts() {
  with_plain_records([&](auto& records) { put_in_lanes(records); });
}

// Each part's contacts, from its first slot on, in the order the sweeps
// solved them one by one: up to W contacts in a row of different runs into
// one record, the lanes left empty; contacts the sweeps leave out into none.
// Part p's records start where its slots do (it has no more records than
// slots).
template <int W>
void contact_solver::put_in_lanes(detail::scratch_array<detail::plain_lanes<W>>& records) {
  const std::size_t count = constraints_.size();
  const std::uint32_t spare = spare_place();
  records.reset(count);
  lane_slots_.reset(count * W);
  part_records_.resize(colouring_.colours() * static_cast<std::size_t>(sweep_threads_) * 2);
  for_each_part([&](std::size_t part) {
    const auto [first_run, end_run] = part_runs(part);
    const std::size_t first = colouring_.run_starts[first_run];
    const std::size_t end = colouring_.run_starts[end_run];
    std::size_t out = first;
    // Lane `lane` of record `out`: slot s's contact, or none (no_slot).
    const auto put = [&](int lane, std::uint32_t s) {
      detail::plain_lanes<W>& p = records[out];
      lane_slots_[out * W + static_cast<std::size_t>(lane)] = s;
      if (s == no_slot) {
        p.normal_x[lane] = p.normal_y[lane] = p.normal_z[lane] = 0;
        p.target_speed[lane] = p.normal_mass[lane] = p.accumulated[lane] = 0;
        p.mass_inverse[lane] = 0;
        p.relaxation[lane] = 1;
        p.place_a[lane] = p.place_b[lane] = spare;
        return;
      }
      const constraint& k = constraints_[s];
      p.normal_x[lane] = k.normal.e1();
      p.normal_y[lane] = k.normal.e2();
      p.normal_z[lane] = k.normal.e3();
      p.target_speed[lane] = k.target_speed;
      p.relaxation[lane] = k.relaxation;
      p.normal_mass[lane] = k.normal_mass;
      p.accumulated[lane] = k.accumulated;
      p.mass_inverse[lane] = k.mass_inverse;
      p.place_a[lane] = k.place_a;
      p.place_b[lane] = k.place_b;
    };
    std::size_t s = first;
    while (s < end) {
      int lane = 0;
      const constraint* last = nullptr;
      for (; lane < W && s < end; ++s) {
        const constraint& k = constraints_[s];
        if (left_out(k)) continue;
        // (Contacts of one run share their bodies: one after the other.)
        if (last && k.place_a == last->place_a && k.place_b == last->place_b) break;
        put(lane++, static_cast<std::uint32_t>(s));
        last = &k;
      }
      if (lane == 0) break;  // (only contacts left out were left)
      for (int empty = lane; empty < W; ++empty) put(empty, no_slot);
      ++out;
    }
    part_records_[part] = {first, out};
  });
}

// The records' impulses back into their constraints (store_impulses reads
// them there).
void contact_solver::store_plain_impulses() {
  with_plain_records([&](const auto& records) {
    constexpr std::size_t W = std::decay_t<decltype(records)>::value_type::lanes;
    for_each_part([&](std::size_t part) {
      const auto [first, end] = part_records_[part];
      for (std::size_t at = first; at < end; ++at) {
        for (std::size_t lane = 0; lane < W; ++lane) {
          const std::uint32_t s = lane_slots_[at * W + lane];
          if (s != no_slot) constraints_[s].accumulated = records[at].accumulated[lane];
        }
      }
    });
  });
}

// One sweep of part `part`'s records.
void contact_solver::solve_plain_part(std::size_t part, const sweep_kind& kind,
                                      sweep_result& result) {
  // (Past solver_iterations only contacts that turn a body are solved.)
  if (kind.turning_only) return;
  const auto [first, end] = part_records_[part];
  if (first == end) return;
  if (kind.last_of_all) {
    solve_plain_records<true>(first, end, result);
  } else {
    solve_plain_records<false>(first, end, result);
  }
}

template <bool last>
void contact_solver::solve_plain_records(std::size_t first, std::size_t end, sweep_result& result) {
#if defined(__SSE2__)
  if constexpr (std::is_same_v<real, double>) {
    // (In locals: GCC read the arrays' addresses again for every record, as
    // its stores might have changed them.)
    detail::plain_body* const at = plain_bodies_.data();
    double largest_change = 0;
#if GAPHYS_PLAIN_WIDE_LANES
    if (plain_lanes_ == 8) {
      detail::solve_plain_octets<last>(plain_octets_.data(), first, end, at, largest_change);
    }
    if (plain_lanes_ == 4) {
      detail::solve_plain_quads<last>(plain_quads_.data(), first, end, at, largest_change);
    }
#endif
    if (plain_lanes_ == 2) {
      detail::plain_pair* const pairs = plain_pairs_.data();
      // The largest change in either lane (the largest of numbers, none a
      // NaN, does not depend on the order they come in).
      __m128d largest = _mm_setzero_pd();
      for (std::size_t p = first; p < end; ++p) {
        detail::solve_plain_pair<last>(pairs[p], at, largest);
      }
      largest_change = _mm_cvtsd_f64(_mm_max_sd(largest, _mm_unpackhi_pd(largest, largest)));
    }
    result.any = true;
    result.largest_change = std::max(result.largest_change, static_cast<real>(largest_change));
  }
#endif
}

}  // namespace gaphys
