// query_grid's traversals (templates, so they are here and not in the .cpp).
#pragma once

#include <algorithm>
#include <cmath>

#include "precision.hpp"
#include "query_grid.hpp"

namespace gaphys::detail {

// Amanatides and Woo's walk: from the cell holding the segment's first point
// within the occupied block, step to whichever neighbour the segment reaches
// first, keeping for each axis the t of its next cell boundary.
template <class Visit>
void query_grid::along(const vector& origin, const vector& direction, real max_distance,
                       Visit&& visit) const {
  if (high_[0] < low_[0]) return;  // no cells
  const real o[3] = {origin.e1(), origin.e2(), origin.e3()};
  const real d[3] = {direction.e1(), direction.e2(), direction.e3()};
  // Clip the segment to the occupied block of cells.
  real start = 0, end = max_distance;
  for (int axis = 0; axis < 3; ++axis) {
    const real lo = low_[axis] * cell_size_, hi = (high_[axis] + 1) * cell_size_;
    if (d[axis] == 0) {
      if (o[axis] < lo || o[axis] > hi) return;
      continue;
    }
    real t0 = (lo - o[axis]) / d[axis], t1 = (hi - o[axis]) / d[axis];
    if (t0 > t1) std::swap(t0, t1);
    start = std::max(start, t0);
    end = std::min(end, t1);
  }
  if (!(start <= end)) return;
  std::int64_t at[3], step[3];
  real next[3], delta[3];
  for (int axis = 0; axis < 3; ++axis) {
    const real x = o[axis] + start * d[axis];
    at[axis] =
        std::clamp(static_cast<std::int64_t>(std::floor(x / cell_size_)), low_[axis], high_[axis]);
    if (d[axis] > 0) {
      step[axis] = 1;
      next[axis] = ((at[axis] + 1) * cell_size_ - o[axis]) / d[axis];
      delta[axis] = cell_size_ / d[axis];
    } else if (d[axis] < 0) {
      step[axis] = -1;
      next[axis] = (at[axis] * cell_size_ - o[axis]) / d[axis];
      delta[axis] = -cell_size_ / d[axis];
    } else {
      step[axis] = 0;
      next[axis] = infinity;
      delta[axis] = infinity;
    }
  }
  for (;;) {
    const int axis =
        next[0] <= next[1] ? (next[0] <= next[2] ? 0 : 2) : (next[1] <= next[2] ? 1 : 2);
    const real leaves = std::min(next[axis], end);
    if (const std::optional<cell_shapes> shapes = cell(at[0], at[1], at[2])) {
      if (!visit(*shapes, leaves)) return;
    }
    if (!(next[axis] < end)) return;
    at[axis] += step[axis];
    if (at[axis] < low_[axis] || at[axis] > high_[axis]) return;
    next[axis] += delta[axis];
  }
}

template <class Visit>
void query_grid::within(const vector& low, const vector& high, Visit&& visit) const {
  if (high_[0] < low_[0]) return;
  const real lo[3] = {low.e1(), low.e2(), low.e3()}, hi[3] = {high.e1(), high.e2(), high.e3()};
  std::int64_t from[3], to[3];
  for (int axis = 0; axis < 3; ++axis) {
    const real first = std::floor(lo[axis] / cell_size_), last = std::floor(hi[axis] / cell_size_);
    if (!(last >= static_cast<real>(low_[axis]) && first <= static_cast<real>(high_[axis]))) return;
    from[axis] = static_cast<std::int64_t>(std::max(first, real(low_[axis])));
    to[axis] = static_cast<std::int64_t>(std::min(last, real(high_[axis])));
  }
  // A sparse block's cells are hashed: a box of more cells than are
  // occupied visits the occupied ones instead of looking every cell up (a
  // 2 m sphere among 1 mm balls strewn over 100 m made 10^10 lookups, a
  // minute). (A dense block's cells number at most 8 per entry.)
  if (!dense_) {
    real probes = 1;
    for (int axis = 0; axis < 3; ++axis) probes *= static_cast<real>(to[axis] - from[axis] + 1);
    if (probes > static_cast<real>(cells_.size())) {
      for (const auto& [k, run] : cells_) {
        bool inside = true;
        for (int axis = 0; axis < 3; ++axis) {
          const std::int64_t at = coordinate_of(k, axis);
          inside = inside && at >= from[axis] && at <= to[axis];
        }
        if (inside) visit(cell_shapes{shapes_.data() + run.first, shapes_.data() + run.second});
      }
      return;
    }
  }
  for (std::int64_t x = from[0]; x <= to[0]; ++x)
    for (std::int64_t y = from[1]; y <= to[1]; ++y)
      for (std::int64_t z = from[2]; z <= to[2]; ++z)
        if (const std::optional<cell_shapes> shapes = cell(x, y, z)) visit(*shapes);
}

}  // namespace gaphys::detail
