// The index behind the world's spatial queries (world::ray_cast,
// overlap_sphere, overlap_box): every shape's bounding sphere in the cells
// of a uniform grid it overlaps, so that a ray visits only the cells along
// it and an overlap only the cells of its bounds. The step's broad phase
// (uniform_grid.hpp) bounds bodies where they were when the step began; a
// query must see them where they are now, so this index is built from the
// bodies' present poses when a query finds it out of date.
//
// Cells are twice the median bounding radius wide. Shapes whose bound is
// wider than four cells, planes, and shapes too far out for integer cells
// are kept apart as "unbounded" and tested by every query.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "gaphys/algebra.hpp"

namespace gaphys::detail {

class query_grid {
 public:
  struct bound {
    vector centre;
    real radius;  // infinite for a plane
  };

  void build(const std::vector<bound>& bounds);

  // The shapes of one cell.
  struct cell_shapes {
    const std::size_t* first;
    const std::size_t* last;
    const std::size_t* begin() const { return first; }
    const std::size_t* end() const { return last; }
  };

  // The shapes tested by every query.
  const std::vector<std::size_t>& unbounded() const { return unbounded_; }

  // Visits the cells the segment origin + t direction, t in [0, max_distance]
  // (unit direction; max_distance may be infinite), passes through, in order
  // along it: visit(cell_shapes, t where the segment leaves the cell)
  // returns false to stop. A shape may lie in several cells.
  template <class Visit>
  void along(const vector& origin, const vector& direction, real max_distance, Visit&& visit) const;

  // Visits the shapes of every cell that the box [low, high] overlaps (a
  // shape once per cell it lies in).
  template <class Visit>
  void within(const vector& low, const vector& high, Visit&& visit) const;

 private:
  using key = std::uint64_t;
  static constexpr std::int64_t coordinate_limit = (std::int64_t{1} << 20) - 1;
  static key key_of(std::int64_t x, std::int64_t y, std::int64_t z);
  // key_of's inverse, one axis (0: x, 1: y, 2: z) at a time.
  static std::int64_t coordinate_of(key k, int axis) {
    return static_cast<std::int64_t>((k >> (21 * axis)) & 0x1fffff) - coordinate_limit;
  }
  std::optional<cell_shapes> cell(std::int64_t x, std::int64_t y, std::int64_t z) const;
  std::size_t dense_index(std::int64_t x, std::int64_t y, std::int64_t z) const;

  real cell_size_ = 1;
  std::int64_t low_[3] = {0, 0, 0}, high_[3] = {-1, -1, -1};  // the occupied cells
  // Every (cell, shape) sorted by cell, the shapes in one array, and each
  // occupied cell's run of it.
  std::vector<std::pair<key, std::size_t>> entries_;
  std::vector<std::size_t> shapes_;
  std::unordered_map<key, std::pair<std::size_t, std::size_t>> cells_;  // sparse
  bool dense_ = false;
  std::vector<std::size_t> starts_,
      fill_;  // dense: cell i's shapes are [starts_[i], starts_[i + 1])
  std::vector<std::size_t> unbounded_;
};

}  // namespace gaphys::detail

#include "query_grid_traversal.hpp"
