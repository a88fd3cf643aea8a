// The broad phase behind space (space.hpp), not an API of its own: candidate
// pairs from a uniform grid of cells, so a step costs O(N) for bodies of
// similar size at a bounded density instead of the O(N^2) of all pairs.
//
// Each body is bounded by a sphere about its centre of mass (reaching its
// shapes' farthest point, widened by a rounding margin) and lands in the
// cell of its centre. Cells are as wide as
// the widest ordinary bound, so two bounds that overlap have their centres
// in the same or adjacent cells: each cell is compared with itself and its
// 13 "forward" neighbours, and every two bounds that overlap make a
// candidate. Bounds wider than twice the median (rounded up by at most
// an eighth) would make the cells coarse, so they are "large" and tested
// against every bound directly. Planes
// (static, unbounded) are tested exactly against each bound: a sphere
// reaches the half-space n . x <= d when n . c - r <= d.
//
// The result is a superset of the pairs whose shapes touch, sorted like all
// pairs', so the narrow phase finds exactly the contacts all pairs finds, in
// the same order: the two broad phases give bit-identical simulations.
//
// Kept candidates: the grid pairs bounds grown by a skin (a quarter of a
// cell) and keeps that list; while no body has moved its bound beyond the
// skin since (nor changed how it moves, nor a plane), every pair that
// overlaps now is in the list, and the steps that follow test only the
// listed pairs, with the same test, for the same pairs in the same order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "gaphys/body.hpp"
#include "gaphys/detail/cache_padded.hpp"

namespace gaphys::detail {

using index_pair = std::pair<std::size_t, std::size_t>;

class uniform_grid {
 public:
  // Appends to `pairs` (cleared first) every candidate among `shaped`
  // (indices into bodies) that may_meet (body.hpp: not both static, kinematic
  // or asleep, but for a moving one waking a sleeping one), as (a, b) with
  // a < b, sorted;
  // each bound reaches lookahead (|v| + |Ω| r) + margin / 2 further, for
  // speculative contacts.
  // Returns false, adding nothing, when coordinates are too far out for
  // integer cells (|x| / cell > 2^50); the caller then uses all pairs.
  // With `threads` > 1 (0: every core) the cells are paired on that many
  // threads; the sorted pairs are the same.
  bool find_pairs(const std::vector<body>& bodies, const std::vector<std::size_t>& shaped,
                  real lookahead, real margin, std::vector<index_pair>& pairs, int threads = 1);

  struct bound {  // a bounding sphere
    vector centre;
    real radius;
    std::size_t body;
    motion moves;  // a pair is a candidate only where may_meet(moves, moves)
  };
  // Body `index`'s bound, a plane's marked by a radius < 0.
  static bound bound_of(const body& b, std::size_t index, real lookahead, real margin);
  // Whether find_pairs pairs the bodies of bounds a and b (bound_of): the
  // test every candidate passes, for a broad phase that tests every two
  // bodies (space's all pairs), so that it finds the same pairs.
  static bool pairs_bounds(const bound& a, const bound& b, const body& body_a, const body& body_b,
                           real margin);
  // Whether the last find_pairs tested the kept candidates (above) instead
  // of the cells.
  bool used_kept_pairs() const { return used_kept_; }

 private:
  struct entry {  // an ordinary bound in its cell
    std::int64_t x, y, z;
    std::size_t bound;
  };
  struct run {  // entries [begin, end) of the sorted list
    std::size_t begin, end;
  };
  struct cell {  // a hash table slot; empty when end == 0
    std::int64_t x, y, z;
    std::size_t begin, end;
  };

  void collect(const std::vector<body>& bodies, const std::vector<std::size_t>& shaped,
               real lookahead, real margin, int threads, bool bounds_made);
  bool sort_into_cells(int threads);
  void sort_dense(std::size_t cells, int threads);
  void sort_hashed();
  std::size_t dense_index(std::int64_t x, std::int64_t y, std::int64_t z) const;
  run find_cell(std::int64_t x, std::int64_t y, std::int64_t z) const;
  void pair_cells(std::vector<index_pair>& pairs, int threads);
  void pair_cell_range(std::size_t begin, std::size_t end, std::vector<index_pair>& pairs) const;
  void pair_large(std::vector<index_pair>& pairs) const;
  void pair_planes(std::vector<index_pair>& pairs, int threads);
  void add_if_overlapping(const bound& a, const bound& b, std::vector<index_pair>& pairs) const;
  struct plane_test;
  // The two tests every candidate passes (find_pairs and pairs_bounds).
  static bool overlapping(const bound& a, const bound& b);
  static plane_test plane_test_of(const body& p, std::size_t index, real margin);
  static bool reaches(const plane_test& plane, const bound& b);
  void sort_pairs(std::size_t body_count, std::vector<index_pair>& pairs, int threads);
  void find_plane_tests(const std::vector<body>& bodies);
  // The kept candidates: whether they still hold every pair that may
  // overlap, keeping them (from pairs found with bounds grown by the skin),
  // and the pairs among them that overlap now.
  bool kept_still_cover(const std::vector<body>& bodies, const std::vector<std::size_t>& shaped,
                        real lookahead, real margin, int threads);
  void keep(const std::vector<index_pair>& grown_pairs, const std::vector<std::size_t>& shaped,
            std::size_t body_count, real skin);
  void pair_kept(std::vector<index_pair>& pairs, int threads);
  real next_skin();

  // Scratch, kept between steps so a step allocates nothing once warm.
  std::vector<bound> bounds_;
  std::vector<std::size_t> large_, planes_;
  std::vector<char> large_marks_;  // per bound, whether it is large (when some are)
  std::vector<entry> unsorted_, entries_;
  // entries_' bounds in their order: the pairing reads them front to back
  // (through entries_, each was a scattered read).
  std::vector<bound> sorted_bounds_;
  bool dense_ = true;
  std::int64_t origin_[3] = {0, 0, 0}, extent_[3] = {0, 0, 0};  // the occupied block of cells
  std::vector<std::size_t> cell_starts_, cell_fill_;  // dense: runs by cell index, scratch
  std::vector<cell> table_;  // sparse: open addressing, power-of-two size
  // collect's: the bounds before the planes are taken out; per share of
  // the bodies, a histogram of widths (width_buckets each, all zero between
  // calls), its planes (a running count from [1]), its lowest bucket, its
  // large bounds and its widest other bound.
  std::vector<bound> unplaced_;
  static constexpr std::size_t width_buckets = std::size_t{1} << (sizeof(real) == 8 ? 14 : 11);
  std::vector<std::uint32_t> width_counts_;
  std::vector<std::size_t> part_planes_, part_lowest_;
  std::vector<cache_padded<std::vector<std::size_t>>> part_large_;
  std::vector<real> part_widest_;
  std::vector<std::size_t> starts_, fill_;
  std::vector<index_pair> sorted_;
  // The shares of pair_cells, pair_planes.
  std::vector<cache_padded<std::vector<index_pair>>> thread_pairs_;
  struct plane_test {  // a plane: a bound reaches it where normal . c - r <= reach
    vector normal;
    real reach;
    std::size_t body;
    motion moves;
  };
  std::vector<plane_test> plane_tests_;
  // The kept candidates (above): each pair as its bodies' places in
  // `shaped` (a first); the bounds and plane tests they were found with,
  // `shaped` then, and for each place how far its bound's radius may reach
  // before a pair may be missing (its radius then, plus the skin, less a
  // rounding margin). A plane's place holds its plane test's index.
  struct kept_pair {
    std::uint32_t a, b;
  };
  std::vector<kept_pair> kept_;
  std::vector<bound> kept_bounds_;
  std::vector<real> kept_reach_;
  std::vector<std::size_t> kept_shaped_;
  std::vector<plane_test> kept_planes_;
  std::vector<std::uint32_t> plane_of_;
  std::vector<std::uint32_t> place_of_;  // keep()'s scratch: each body's place in `shaped`
  bool kept_valid_ = false, used_kept_ = false;
  // How many find_pairs the kept list has served; lists that served only
  // the step that made them, in a row; steps left on the plain grid after
  // two such (bodies too fast for the skin: growing the bounds only costs).
  int kept_uses_ = 0, short_lists_ = 0, plain_steps_left_ = 0;
  real cell_size_ = 1;
  real margin_ = 0;  // the contact margin: bounds hold half of it, plane tests the other half
};

}  // namespace gaphys::detail
