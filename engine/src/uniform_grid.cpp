#include "gaphys/detail/uniform_grid.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <new>
#include <tuple>
#include <type_traits>

#include "counting_sort.hpp"
#include "precision.hpp"
#include "thread_count.hpp"

namespace gaphys::detail {

namespace {

// Bounds are widened by this share of their scale (1 + |centre| + r), far
// above the rounding of the narrow phase's test, so a pair the meet calls
// touching is never lost to rounding here.
const real relative_margin = by_precision(1e-9, 1e-5);
// Cell coordinates must fit in 64-bit integers with room for the +-1 offsets.
constexpr real largest_cell_coordinate = 0x1.0p50;

real largest_magnitude(const vector& v) {
  return std::max({std::fabs(v.e1()), std::fabs(v.e2()), std::fabs(v.e3())});
}

// Calls find(begin, end, out) over [0, count), appending what it finds to
// `pairs`: on one thread directly; on several (no fewer than per_thread
// items each) in four shares per thread, each thread's own first, then
// what the others have left (visit_on_threads), each into its own list of
// `scratch`. The pairs are sorted afterwards (sort_pairs), so the order in
// which the shares find them changes nothing.
template <class Find>
void find_in_shares(std::size_t count, std::size_t per_thread, int threads,
                    std::vector<cache_padded<std::vector<index_pair>>>& scratch,
                    std::vector<index_pair>& pairs, const Find& find) {
  const int shares = threads_for(threads, count, per_thread);
  if (shares == 1) {
    find(std::size_t{0}, count, pairs);
    return;
  }
  const auto share_count = static_cast<std::size_t>(4 * shares);
  scratch.resize(share_count);
  visit_on_threads(shares, share_count, 1, [&](std::size_t at) {
    std::vector<index_pair>& found = scratch[at].value;
    found.clear();
    find(count * at / share_count, count * (at + 1) / share_count, found);
  });
  for (const auto& found : scratch) {
    pairs.insert(pairs.end(), found.value.begin(), found.value.end());
  }
}

// A histogram bucket of widths > 0: the binary exponent and three leading
// bits of the mantissa (positive reals order as their bits do), so a
// bucket's widths are within 1/8 of each other.
using real_bits = std::conditional_t<sizeof(real) == 8, std::uint64_t, std::uint32_t>;
constexpr int width_bucket_shift = sizeof(real) == 8 ? 49 : 20;

std::size_t width_bucket(real width) {
  real_bits bits;
  std::memcpy(&bits, &width, sizeof bits);
  // (A NaN with its sign bit set would index past the buckets: the world
  // never holds one, but the grid must not write out of bounds if it did.)
  constexpr std::size_t last = (std::size_t{1} << (8 * sizeof(real) - 1 - width_bucket_shift)) - 1;
  return std::min(static_cast<std::size_t>(bits >> width_bucket_shift), last);
}

// The least width above every width of `bucket` (infinity from the largest
// finite widths' bucket on).
real width_bucket_end(std::size_t bucket) {
  if (bucket >= width_bucket(std::numeric_limits<real>::max())) {
    return std::numeric_limits<real>::infinity();
  }
  const real_bits bits = static_cast<real_bits>(bucket + 1) << width_bucket_shift;
  real end;
  std::memcpy(&end, &bits, sizeof end);
  return end;
}

std::uint64_t hash(std::int64_t x, std::int64_t y, std::int64_t z) {
  std::uint64_t h = static_cast<std::uint64_t>(x) * 0x9e3779b97f4a7c15ull;
  h ^= static_cast<std::uint64_t>(y) * 0xc2b2ae3d27d4eb4full + (h << 6) + (h >> 2);
  h ^= static_cast<std::uint64_t>(z) * 0x165667b19e3779f9ull + (h << 6) + (h >> 2);
  return h ^ (h >> 29);
}

}  // namespace

bool uniform_grid::find_pairs(const std::vector<body>& bodies, const std::vector<std::size_t>& shaped,
                              real lookahead, real margin, std::vector<index_pair>& pairs,
                              int threads) {
  pairs.clear();
  margin_ = margin;
  // (Where `shaped` is as it was, kept_still_cover has made this step's
  // bounds, covered or not.)
  const bool bounds_made = kept_valid_ && shaped == kept_shaped_;
  used_kept_ = bounds_made && kept_still_cover(bodies, shaped, lookahead, margin, threads);
  if (used_kept_) {
    ++kept_uses_;
    pair_kept(pairs, threads);
    return true;
  }
  collect(bodies, shaped, lookahead, margin, threads, bounds_made);
  find_plane_tests(bodies);
  // The cells' pairs of bounds grown by the skin, kept; then those of them
  // that overlap now. (Which bounds are large stays as collect found them:
  // each grows by the same skin, and the cells with it. A kept pair holds
  // its bodies' places in 32 bits.)
  const real skin = shaped.size() <= std::numeric_limits<std::uint32_t>::max() ? next_skin() : 0;
  for (bound& b : bounds_) b.radius += skin;
  cell_size_ += 2 * skin;
  if (!sort_into_cells(threads)) return false;
  pair_cells(pairs, threads);
  pair_large(pairs);
  pair_planes(pairs, threads);
  sort_pairs(bodies.size(), pairs, threads);
  if (skin > 0) {
    keep(pairs, shaped, bodies.size(), skin);
    pairs.clear();
    pair_kept(pairs, threads);
  }
  return true;
}

// The skin of the next kept list: a quarter of the cell. In a pile of
// spheres (M6, steps 120-220) a list then lasted 5-6 steps; an eighth of
// the cell grew the cells and the lists less but lasted half as long, and
// the steps' mean was slower (10,000 spheres' broad phase 1.2 against 1.0
// ms a step). None (the plain grid) for the next 16 steps after two lists
// in a row lasted only the step that made them: bodies too fast for the
// skin, where a list costs the grown cells' extra candidates and nothing
// comes back.
real uniform_grid::next_skin() {
  if (kept_valid_) short_lists_ = kept_uses_ > 1 ? 0 : short_lists_ + 1;
  kept_valid_ = false;
  if (short_lists_ >= 2) {
    short_lists_ = 0;
    plain_steps_left_ = 16;
  }
  if (plain_steps_left_ > 0) {
    --plain_steps_left_;
    return 0;
  }
  const real skin = cell_size_ / 4;
  return std::isfinite(skin) && skin > 0 ? skin : 0;
}

// Whether the kept pairs still hold every pair of bounds that overlaps (or
// plane that a bound reaches): `shaped` and the plane tests as they were,
// each body's way of moving too (may_meet), and each bound within its kept
// one grown by the skin. Then two bounds that overlap now, |cA - cB| <= rA
// + rB, overlapped grown when kept: |cA' - cB'| <= |cA - cB| + |cA - cA'| +
// |cB - cB'| <= (rA' + skin) + (rB' + skin) where each bound's |c - c'| + r
// <= r' + skin; and a plane that a bound reaches now, n . c - r <= d,
// reached it grown: n . c' - (r' + skin) <= n . c - r <= d. (Less a rounding
// margin: kept_reach_.) The bounds are made here, in unplaced_ (as collect
// makes them), and the plane tests (planes_ is as the keeping step's collect
// left it: `shaped` and which bodies are planes are the same); while the
// kept pairs serve, the width histogram and the bounds' placement (collect)
// are not needed. (`shaped` is the kept one: find_pairs checks.)
bool uniform_grid::kept_still_cover(const std::vector<body>& bodies,
                                    const std::vector<std::size_t>& shaped, real lookahead,
                                    real margin, int threads) {
  bool covered = true;
  const int shares = threads_for(threads, shaped.size(), 4096);
  const auto count = static_cast<std::ptrdiff_t>(shaped.size());
#pragma omp parallel for num_threads(shares) schedule(static) if (shares > 1) reduction(&& : covered)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    const auto at = static_cast<std::size_t>(k);
    // (Made in its place: collect.)
    const bound& now = *::new (static_cast<void*>(&unplaced_[at]))
                           bound(bound_of(bodies[shaped[at]], shaped[at], lookahead, margin));
    const bound& then = kept_bounds_[at];
    const bool planes = now.radius < 0 && then.radius < 0;
    const real room = kept_reach_[at] - now.radius;
    const vector d = now.centre - then.centre;
    covered = covered && now.moves == then.moves &&
              (planes || (now.radius >= 0 && then.radius >= 0 && room >= 0 &&
                          e3ga::scp(d, d) <= room * room));
  }
  if (!covered) return false;
  find_plane_tests(bodies);
  if (plane_tests_.size() != kept_planes_.size()) return false;
  for (std::size_t p = 0; p < plane_tests_.size(); ++p) {
    const plane_test& now = plane_tests_[p];
    const plane_test& then = kept_planes_[p];
    if (!(now.normal.e1() == then.normal.e1() && now.normal.e2() == then.normal.e2() &&
          now.normal.e3() == then.normal.e3() && now.reach == then.reach && now.body == then.body &&
          now.moves == then.moves)) {
      return false;
    }
  }
  return true;
}

// Keeps `grown_pairs` (sorted, found with every bound grown by the skin)
// and what kept_still_cover checks them against.
void uniform_grid::keep(const std::vector<index_pair>& grown_pairs,
                        const std::vector<std::size_t>& shaped, std::size_t body_count, real skin) {
  const std::size_t count = shaped.size();
  place_of_.resize(body_count);
  plane_of_.resize(count);
  kept_reach_.resize(count);
  std::uint32_t plane = 0;
  for (std::size_t at = 0; at < count; ++at) {
    place_of_[shaped[at]] = static_cast<std::uint32_t>(at);
    const bound& b = unplaced_[at];
    if (b.radius < 0) {
      plane_of_[at] = plane++;  // (planes_' order, and plane_tests_')
      continue;
    }
    const real grown = b.radius + skin;
    kept_reach_[at] = grown - relative_margin * (1 + largest_magnitude(b.centre) + grown);
  }
  kept_.resize(grown_pairs.size());
  for (std::size_t k = 0; k < grown_pairs.size(); ++k) {
    kept_[k] = kept_pair{place_of_[grown_pairs[k].first], place_of_[grown_pairs[k].second]};
  }
  kept_bounds_.assign(unplaced_.begin(), unplaced_.end());
  kept_shaped_ = shaped;
  kept_planes_ = plane_tests_;
  kept_valid_ = true;
  kept_uses_ = 1;
}

// The kept pairs that overlap now, tested as the cells test theirs (and in
// the same order as they were found and sorted): the grid's pairs. Every
// kept pair is written and only those that overlap are counted: a third of
// a pile's kept pairs do not, in no pattern, and the branch around the
// write, mispredicted, cost more than the writes (a kept step's broad
// phase at 10,000 spheres 0.83 -> 0.48 ms).
void uniform_grid::pair_kept(std::vector<index_pair>& pairs, int threads) {
  find_in_shares(kept_.size(), 4096, threads, thread_pairs_, pairs,
                 [this](std::size_t begin, std::size_t end, std::vector<index_pair>& out) {
                   std::size_t at = out.size();
                   out.resize(at + (end - begin));
                   for (std::size_t k = begin; k < end; ++k) {
                     const kept_pair& kept = kept_[k];
                     const bound& a = unplaced_[kept.a];
                     const bound& b = unplaced_[kept.b];
                     const bool meets = a.radius < 0   ? reaches(plane_tests_[plane_of_[kept.a]], b)
                                        : b.radius < 0 ? reaches(plane_tests_[plane_of_[kept.b]], a)
                                                       : overlapping(a, b);
                     out[at] = index_pair{a.body, b.body};
                     at += meets;
                   }
                   out.resize(at);
                 });
}

// All pairs' order, which the solver (and its warm starting) relies on: a
// counting sort on the first body, then each (short) run by the second.
// (The runs on the threads, for many bodies; each is a few pairs, sorted by
// insertion.)
void uniform_grid::sort_pairs(std::size_t body_count, std::vector<index_pair>& pairs, int threads) {
  sorted_.resize(pairs.size());
  counting_sort(
      threads, 8192, pairs.size(), body_count, [&](std::size_t i) { return pairs[i].first; },
      starts_, fill_, [&](std::size_t i, std::size_t at) { sorted_[at] = pairs[i]; });
  parallel_for(threads, body_count, 4096, [&](std::size_t i) {
    index_pair* first = sorted_.data() + starts_[i];
    index_pair* last = sorted_.data() + starts_[i + 1];
    if (last - first > 16) {
      // (A plane's run, a pair for each body above it, comes from
      // pair_planes in order: checked, it is not sorted again.)
      if (!std::is_sorted(first, last)) std::sort(first, last);
      return;
    }
    for (index_pair* at = first + 1; at < last; ++at) {
      const index_pair moving = *at;
      index_pair* to = at;
      for (; to > first && moving < to[-1]; --to) *to = to[-1];
      *to = moving;
    }
  });
  pairs.swap(sorted_);
}

// A body's bound, a plane's marked by a radius < 0: as far as the body can
// move or turn within the lookahead, and half the margin (two bounds then
// overlap when their gap is up to it).
uniform_grid::bound uniform_grid::bound_of(const body& b, std::size_t index, real lookahead,
                                           real margin) {
  if (b.shape()->kind() == shape_kind::plane) return bound{vector{}, -1, index, motion::fixed};
  const vector& c = b.position();
  const real r = b.bounding_radius();
  const real sweep =
      lookahead * (e3ga::norm(b.velocity()) + e3ga::norm(b.angular_velocity()) * r) + margin / 2;
  const real reach = r + sweep + relative_margin * (1 + largest_magnitude(c) + r + sweep);
  return bound{c, reach, index, motion_of(b)};
}

// add_if_overlapping's test and pair_planes', on two bodies.
bool uniform_grid::pairs_bounds(const bound& bound_a, const bound& bound_b, const body& a,
                                const body& b, real margin) {
  const bool plane_a = bound_a.radius < 0, plane_b = bound_b.radius < 0;
  if (plane_a && plane_b) return false;  // (the grid tests planes against bounds only)
  if (plane_a || plane_b) {
    const bound& plane = plane_a ? bound_a : bound_b;
    return reaches(plane_test_of(plane_a ? a : b, plane.body, margin), plane_a ? bound_b : bound_a);
  }
  return overlapping(bound_a, bound_b);
}

// Bounds overlap when |cA - cB| <= rA + rB (radii widened by the margin).
// (Inline: the grid tests every candidate, and as a call the test was a
// third of the pairing's instructions.)
GAPHYS_ALWAYS_INLINE bool uniform_grid::overlapping(const bound& a, const bound& b) {
  if (!may_meet(a.moves, b.moves)) return false;
  const vector d = a.centre - b.centre;
  const real reach = a.radius + b.radius;
  return e3ga::scp(d, d) <= reach * reach;
}

// A plane, exactly: a bound's sphere reaches the solid side n . x <= d when
// n . c - r <= d; within the contact margin when n . c - r <= d + margin
// (the bound holds half of it already).
uniform_grid::plane_test uniform_grid::plane_test_of(const body& p, std::size_t index,
                                                     real margin) {
  const vector n = e3ga::apply(p.attitude(), p.shape()->normal());
  const real d = p.shape()->offset() + e3ga::scp(n, p.position());
  return plane_test{n, d + margin / 2, index, motion_of(p)};
}

GAPHYS_ALWAYS_INLINE bool uniform_grid::reaches(const plane_test& plane, const bound& b) {
  return may_meet(plane.moves, b.moves) &&
         e3ga::scp(plane.normal, b.centre) - b.radius <= plane.reach;
}

// Bounds of the shaped bodies, and the cell size: the widest bound that
// is not "large" (wider than twice the median width, rounded up to the end
// of its bucket below). On threads_for(threads, count, 1024) threads, each
// taking a contiguous share of the bodies: their bounds, and a histogram of
// the widths; then the median's bucket (a function of the widths alone, so
// the same on any number of threads); then each share's bounds moved to
// their places without the planes, the large ones listed and the widest
// other one found. (Which bounds are large, and the cell size, change which
// candidates the grid tests, not the pairs it finds.)
void uniform_grid::collect(const std::vector<body>& bodies, const std::vector<std::size_t>& shaped,
                           real lookahead, real margin, int threads, bool bounds_made) {
  // (A bucket for every pattern of the bits below the sign.)
  static_assert(width_buckets == std::size_t{1} << (8 * sizeof(real) - 1 - width_bucket_shift));
  const std::size_t count = shaped.size();
  const auto bound_of = [&](std::size_t index) {
    return uniform_grid::bound_of(bodies[index], index, lookahead, margin);
  };
  const int parts = threads_for(threads, count, 1024);
  const auto most = static_cast<std::size_t>(parts);
  unplaced_.resize(count);
  width_counts_.resize(most * width_buckets);
  part_planes_.assign(most + 1, 0);
  part_lowest_.resize(most);
  part_large_.resize(most);
  part_widest_.assign(most, 0);
  std::size_t ordinary = 0, planes = 0;
  real large_width = 0;
#pragma omp parallel num_threads(parts) if (parts > 1)
  {
    // (As many parts as the threads OpenMP gives: inside an application's
    // own parallel region, one.)
    const auto shares = static_cast<std::size_t>(omp_get_num_threads());
    const auto part = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t first = count * part / shares, end = count * (part + 1) / shares;
    // (The histograms are all zero between calls: each share clears the
    // buckets it used.)
    std::uint32_t* counts = &width_counts_[part * width_buckets];
    std::size_t own_planes = 0, lowest = width_buckets, highest = 0;
    for (std::size_t at = first; at < end; ++at) {
      // (Made in its place: assigned from a copy made aside, its bytes were
      // read back as soon as written, in wider loads than the stores, each
      // waiting for them: half of this loop.)
      // (Or made already, by kept_still_cover.)
      static_assert(std::is_trivially_destructible_v<bound>);
      const bound& b =
          bounds_made ? unplaced_[at]
                      : *::new (static_cast<void*>(&unplaced_[at])) bound(bound_of(shaped[at]));
      if (b.radius < 0) {
        ++own_planes;
        continue;
      }
      const std::size_t bucket = width_bucket(2 * b.radius);
      ++counts[bucket];
      lowest = std::min(lowest, bucket), highest = std::max(highest, bucket);
    }
    part_planes_[part + 1] = own_planes;
    part_lowest_[part] = lowest;
#pragma omp barrier
#pragma omp single
    {
      for (std::size_t p = 0; p < shares; ++p) part_planes_[p + 1] += part_planes_[p];
      planes = part_planes_[shares];
      ordinary = count - planes;
      // The bucket of the width std::nth_element would put in the middle.
      std::size_t bucket = *std::min_element(part_lowest_.begin(), part_lowest_.begin() + shares);
      std::size_t below = 0;
      for (; bucket < width_buckets; ++bucket) {
        for (std::size_t p = 0; p < shares; ++p) below += width_counts_[p * width_buckets + bucket];
        if (below > ordinary / 2) break;
      }
      large_width = 2 * width_bucket_end(bucket);
      planes_.resize(planes);
      bounds_.resize(ordinary);
    }
    // (single's barrier) This share's planes and other bounds in order.
    std::size_t plane_at = part_planes_[part], bound_at = first - part_planes_[part];
    std::vector<std::size_t>& large = part_large_[part].value;
    large.clear();
    real widest = 0;
    for (std::size_t at = first; at < end; ++at) {
      const bound& b = unplaced_[at];
      if (b.radius < 0) {
        planes_[plane_at++] = b.body;
        continue;
      }
      const real width = 2 * b.radius;
      if (width > large_width) {
        large.push_back(bound_at);
      } else {
        widest = std::max(widest, width);
      }
      bounds_[bound_at++] = b;
    }
    part_widest_[part] = widest;
    if (lowest <= highest) std::fill(counts + lowest, counts + highest + 1, 0);
  }
  large_.clear();
  cell_size_ = 0;
  for (std::size_t p = 0; p < most; ++p) {
    large_.insert(large_.end(), part_large_[p].value.begin(), part_large_[p].value.end());
    cell_size_ = std::max(cell_size_, part_widest_[p]);
  }
}

// Sorts the ordinary bounds by cell, in (x, y, z) order, and indexes the
// cells' runs: in a dense array over the occupied block of cells when it is
// not much larger than the number of bounds (a counting sort, and lookups
// by index), else in a hash table.
bool uniform_grid::sort_into_cells(int threads) {
  // Each ordinary bound's cell on its own (on the threads, for many), and
  // the block they occupy; then the large bounds' places taken out.
  const std::size_t count = bounds_.size();
  unsorted_.resize(count);
  large_marks_.assign(large_.empty() ? 0 : count, 0);
  for (const std::size_t i : large_) large_marks_[i] = 1;
  constexpr std::int64_t none = std::numeric_limits<std::int64_t>::max();
  std::int64_t low_x = none, low_y = none, low_z = none;
  std::int64_t high_x = -none, high_y = -none, high_z = -none;
  bool too_far = false;
  const int shares = threads_for(threads, count, 4096);
  const auto end = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for num_threads(shares) schedule(static) if (shares > 1)         \
    reduction(min                                                                     \
              : low_x, low_y, low_z) reduction(max                                    \
                                               : high_x, high_y, high_z) reduction(|| \
                                                                                   : too_far)
  for (std::ptrdiff_t k = 0; k < end; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (!large_marks_.empty() && large_marks_[i]) continue;
    const vector scaled = bounds_[i].centre / cell_size_;
    if (!(largest_magnitude(scaled) < largest_cell_coordinate)) {
      too_far = true;
      continue;
    }
    const entry e{static_cast<std::int64_t>(std::floor(scaled.e1())),
                  static_cast<std::int64_t>(std::floor(scaled.e2())),
                  static_cast<std::int64_t>(std::floor(scaled.e3())), i};
    unsorted_[i] = e;
    low_x = std::min(low_x, e.x), low_y = std::min(low_y, e.y), low_z = std::min(low_z, e.z);
    high_x = std::max(high_x, e.x), high_y = std::max(high_y, e.y), high_z = std::max(high_z, e.z);
  }
  if (too_far) return false;
  if (!large_.empty()) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < count; ++i) {
      if (!large_marks_[i]) unsorted_[kept++] = unsorted_[i];
    }
    unsorted_.resize(kept);
  }
  if (unsorted_.empty()) low_x = low_y = low_z = high_x = high_y = high_z = 0;
  const std::int64_t low[3] = {low_x, low_y, low_z}, high[3] = {high_x, high_y, high_z};
  // One empty cell more on each side: every neighbour of an occupied cell
  // is then inside the block, and the dense pairing finds it by index
  // without a bounds check (pair_cell_range).
  for (int axis = 0; axis < 3; ++axis) {
    origin_[axis] = low[axis] - 1;
    extent_[axis] = high[axis] - low[axis] + 3;
  }
  const double cells = double(extent_[0]) * double(extent_[1]) * double(extent_[2]);
  dense_ = cells <= 8.0 * double(unsorted_.size()) + 4096;
  if (dense_) {
    sort_dense(static_cast<std::size_t>(cells), threads);
  } else {
    sort_hashed();
  }
  return true;
}

std::size_t uniform_grid::dense_index(std::int64_t x, std::int64_t y, std::int64_t z) const {
  return static_cast<std::size_t>(((x - origin_[0]) * extent_[1] + (y - origin_[1])) * extent_[2] +
                                  (z - origin_[2]));
}

// A counting sort by cell index; within a cell the bounds keep their order.
// (On the threads for many bounds.)
void uniform_grid::sort_dense(std::size_t cells, int threads) {
  entries_.resize(unsorted_.size());
  const auto cell_of = [&](std::size_t i) {
    const entry& e = unsorted_[i];
    return dense_index(e.x, e.y, e.z);
  };
  sorted_bounds_.resize(unsorted_.size());
  counting_sort(threads, 4096, unsorted_.size(), cells, cell_of, cell_starts_, cell_fill_,
                [&](std::size_t i, std::size_t at) {
                  entries_[at] = unsorted_[i];
                  sorted_bounds_[at] = bounds_[unsorted_[i].bound];
                });
}

void uniform_grid::sort_hashed() {
  entries_ = unsorted_;
  std::sort(entries_.begin(), entries_.end(), [](const entry& a, const entry& b) {
    return std::tie(a.x, a.y, a.z, a.bound) < std::tie(b.x, b.y, b.z, b.bound);
  });
  sorted_bounds_.resize(entries_.size());
  for (std::size_t at = 0; at < entries_.size(); ++at)
    sorted_bounds_[at] = bounds_[entries_[at].bound];
  std::size_t size = 16;
  while (size < 2 * entries_.size()) size *= 2;
  table_.assign(size, cell{0, 0, 0, 0, 0});
  for (std::size_t begin = 0; begin < entries_.size();) {
    const entry& first = entries_[begin];
    std::size_t end = begin + 1;
    while (end < entries_.size() && entries_[end].x == first.x && entries_[end].y == first.y &&
           entries_[end].z == first.z) {
      ++end;
    }
    std::size_t slot = hash(first.x, first.y, first.z) & (size - 1);
    while (table_[slot].end != 0) slot = (slot + 1) & (size - 1);
    table_[slot] = cell{first.x, first.y, first.z, begin, end};
    begin = end;
  }
}

// The run of entries in cell (x, y, z); empty (begin == end) if none.
uniform_grid::run uniform_grid::find_cell(std::int64_t x, std::int64_t y, std::int64_t z) const {
  if (dense_) {
    if (x < origin_[0] || y < origin_[1] || z < origin_[2] || x >= origin_[0] + extent_[0] ||
        y >= origin_[1] + extent_[1] || z >= origin_[2] + extent_[2]) {
      return run{0, 0};
    }
    const std::size_t c = dense_index(x, y, z);
    return run{cell_starts_[c], cell_starts_[c + 1]};
  }
  const std::size_t mask = table_.size() - 1;
  for (std::size_t slot = hash(x, y, z) & mask; table_[slot].end != 0; slot = (slot + 1) & mask) {
    const cell& c = table_[slot];
    if (c.x == x && c.y == y && c.z == z) return run{c.begin, c.end};
  }
  return run{0, 0};
}

GAPHYS_ALWAYS_INLINE void uniform_grid::add_if_overlapping(const bound& a, const bound& b,
                                                           std::vector<index_pair>& pairs) const {
  if (!overlapping(a, b)) return;
  pairs.emplace_back(std::min(a.body, b.body), std::max(a.body, b.body));
}

// Each cell with itself and with the 13 neighbours that come after it in
// (x, y, z) order, so every two adjacent cells meet once.
// With several threads, each pairs the cells that start in its share of the
// sorted entries (a share's first cell may begin before it: that cell is
// the previous share's).
void uniform_grid::pair_cells(std::vector<index_pair>& pairs, int threads) {
  // (A few hundred bounds per thread: a box's cells take about 0.1 µs.)
  find_in_shares(entries_.size(), 256, threads, thread_pairs_, pairs,
                 [this](std::size_t begin, std::size_t end, std::vector<index_pair>& out) {
                   pair_cell_range(begin, end, out);
                 });
}

// The cells whose first entry lies in [begin, end) of the sorted entries.
void uniform_grid::pair_cell_range(std::size_t begin, std::size_t end,
                                   std::vector<index_pair>& pairs) const {
  static constexpr int forward[13][3] = {{1, -1, -1}, {1, -1, 0}, {1, -1, 1}, {1, 0, -1}, {1, 0, 0},
                                         {1, 0, 1},   {1, 1, -1}, {1, 1, 0},  {1, 1, 1},  {0, 1, -1},
                                         {0, 1, 0},   {0, 1, 1},  {0, 0, 1}};
  // Skip to the first cell that starts in the range.
  const auto same_cell = [](const entry& a, const entry& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
  };
  while (begin < end && begin > 0 && same_cell(entries_[begin - 1], entries_[begin])) ++begin;
  // A cell's bounds with each other, and with another cell's.
  const auto pair_within = [&](const run& here) {
    for (std::size_t i = here.begin; i < here.end; ++i) {
      for (std::size_t j = i + 1; j < here.end; ++j) {
        add_if_overlapping(sorted_bounds_[i], sorted_bounds_[j], pairs);
      }
    }
  };
  const auto pair_runs = [&](const run& here, const run& there) {
    for (std::size_t i = here.begin; i < here.end; ++i) {
      for (std::size_t j = there.begin; j < there.end; ++j) {
        add_if_overlapping(sorted_bounds_[i], sorted_bounds_[j], pairs);
      }
    }
  };
  if (dense_) {
    // A neighbour's index is the cell's plus a fixed step (the block has
    // an empty cell around the occupied ones), where find_cell's bounds
    // checks and index took a tenth of a sphere pile's step. And z is the
    // fastest index, so the 13 forward neighbours are 5 runs of consecutive
    // cells, whose entries are consecutive too: (1, -1, -1..1), (1, 0,
    // -1..1), (1, 1, -1..1), (0, 1, -1..1) and (0, 0, 1). (One cell at a
    // time, the pairing was 8% of a one-thread step of 10,000 spheres.)
    const std::ptrdiff_t along_y = extent_[2], along_x = extent_[1] * extent_[2];
    const std::ptrdiff_t spans[5][2] = {{along_x - along_y - 1, along_x - along_y + 1},
                                        {along_x - 1, along_x + 1},
                                        {along_x + along_y - 1, along_x + along_y + 1},
                                        {along_y - 1, along_y + 1},
                                        {1, 1}};  // first and last cell, from this one
    while (begin < end) {
      const entry& first = entries_[begin];
      const std::size_t cell = dense_index(first.x, first.y, first.z);
      const run here{cell_starts_[cell], cell_starts_[cell + 1]};
      pair_within(here);
      for (const auto& span : spans) {
        const auto at = static_cast<std::ptrdiff_t>(cell);
        pair_runs(here, run{cell_starts_[static_cast<std::size_t>(at + span[0])],
                            cell_starts_[static_cast<std::size_t>(at + span[1] + 1)]});
      }
      begin = here.end;
    }
    return;
  }
  while (begin < end) {
    const entry& first = entries_[begin];
    const run here = find_cell(first.x, first.y, first.z);
    pair_within(here);
    for (const auto& offset : forward) {
      pair_runs(here, find_cell(first.x + offset[0], first.y + offset[1], first.z + offset[2]));
    }
    begin = here.end;
  }
}

// Large bounds against every other bound (large ones once per pair).
void uniform_grid::pair_large(std::vector<index_pair>& pairs) const {
  for (std::size_t k = 0; k < large_.size(); ++k) {
    const bound& a = bounds_[large_[k]];
    for (std::size_t i = 0; i < bounds_.size(); ++i) {
      const bool other_large = std::binary_search(large_.begin(), large_.end(), i);
      if (other_large && i <= large_[k]) continue;
      add_if_overlapping(a, bounds_[i], pairs);
    }
  }
}

// Each plane's test (plane_test_of), in planes_' order.
void uniform_grid::find_plane_tests(const std::vector<body>& bodies) {
  plane_tests_.clear();
  for (std::size_t index : planes_)
    plane_tests_.push_back(plane_test_of(bodies[index], index, margin_));
}

// A plane against each dynamic bound, exactly (plane_test_of, reaches).
// (On the threads for many bounds, each taking shares of them.)
void uniform_grid::pair_planes(std::vector<index_pair>& pairs, int threads) {
  if (plane_tests_.empty()) return;
  const auto test = [&](std::size_t begin, std::size_t end, std::vector<index_pair>& out) {
    for (const plane_test& plane : plane_tests_) {
      for (std::size_t i = begin; i < end; ++i) {
        const bound& b = bounds_[i];
        if (reaches(plane, b))
          out.emplace_back(std::min(plane.body, b.body), std::max(plane.body, b.body));
      }
    }
  };
  find_in_shares(bounds_.size(), 4096, threads, thread_pairs_, pairs, test);
}

}  // namespace gaphys::detail
