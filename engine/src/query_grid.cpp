#include "query_grid.hpp"

#include <algorithm>
#include <cmath>

namespace gaphys::detail {

query_grid::key query_grid::key_of(std::int64_t x, std::int64_t y, std::int64_t z) {
  const auto field = [](std::int64_t v) {
    return static_cast<key>(v + coordinate_limit) & 0x1fffff;
  };
  return field(x) | (field(y) << 21) | (field(z) << 42);
}

std::optional<query_grid::cell_shapes> query_grid::cell(std::int64_t x, std::int64_t y,
                                                        std::int64_t z) const {
  std::size_t begin, end;
  if (dense_) {
    const std::size_t index = dense_index(x, y, z);
    begin = starts_[index], end = starts_[index + 1];
  } else {
    const auto found = cells_.find(key_of(x, y, z));
    if (found == cells_.end()) return std::nullopt;
    begin = found->second.first, end = found->second.second;
  }
  if (begin == end) return std::nullopt;
  return cell_shapes{shapes_.data() + begin, shapes_.data() + end};
}

std::size_t query_grid::dense_index(std::int64_t x, std::int64_t y, std::int64_t z) const {
  const auto span = [&](int axis) {
    return static_cast<std::size_t>(high_[axis] - low_[axis] + 1);
  };
  return (static_cast<std::size_t>(x - low_[0]) * span(1) + static_cast<std::size_t>(y - low_[1])) *
             span(2) +
         static_cast<std::size_t>(z - low_[2]);
}

void query_grid::build(const std::vector<bound>& bounds) {
  cells_.clear();
  dense_ = false;
  entries_.clear();
  shapes_.clear();
  unbounded_.clear();
  low_[0] = low_[1] = low_[2] = 0;
  high_[0] = high_[1] = high_[2] = -1;
  std::vector<real> radii;
  for (const bound& b : bounds) {
    if (std::isfinite(b.radius)) radii.push_back(b.radius);
  }
  if (radii.empty()) {
    for (std::size_t i = 0; i < bounds.size(); ++i) unbounded_.push_back(i);
    return;
  }
  std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
  cell_size_ = std::max(2 * radii[radii.size() / 2], real(1e-9));
  bool first = true;
  for (std::size_t i = 0; i < bounds.size(); ++i) {
    const bound& b = bounds[i];
    const real c[3] = {b.centre.e1(), b.centre.e2(), b.centre.e3()};
    std::int64_t from[3], to[3];
    bool placed = std::isfinite(b.radius) && b.radius <= 2 * cell_size_;
    for (int axis = 0; placed && axis < 3; ++axis) {
      const real lo = std::floor((c[axis] - b.radius) / cell_size_);
      const real hi = std::floor((c[axis] + b.radius) / cell_size_);
      if (!(std::fabs(lo) < coordinate_limit && std::fabs(hi) < coordinate_limit)) {
        placed = false;
        break;
      }
      from[axis] = static_cast<std::int64_t>(lo);
      to[axis] = static_cast<std::int64_t>(hi);
    }
    if (!placed) {
      unbounded_.push_back(i);
      continue;
    }
    for (int axis = 0; axis < 3; ++axis) {
      low_[axis] = first ? from[axis] : std::min(low_[axis], from[axis]);
      high_[axis] = first ? to[axis] : std::max(high_[axis], to[axis]);
    }
    first = false;
    for (std::int64_t x = from[0]; x <= to[0]; ++x)
      for (std::int64_t y = from[1]; y <= to[1]; ++y)
        for (std::int64_t z = from[2]; z <= to[2]; ++z) entries_.emplace_back(key_of(x, y, z), i);
  }
  if (first) return;  // nothing placed
  // A block of few enough cells is an array of runs, filled by counting (no
  // sort, no hash table); else the entries are sorted by cell and hashed.
  std::size_t cells = 1;
  for (int axis = 0; axis < 3; ++axis) {
    const auto span = static_cast<std::size_t>(high_[axis] - low_[axis] + 1);
    cells = cells > (std::size_t{1} << 40) / span ? (std::size_t{1} << 40) : cells * span;
  }
  dense_ = cells <= 8 * entries_.size() + 4096;
  if (dense_) {
    starts_.assign(cells + 1, 0);
    for (const auto& [k, shape] : entries_) {
      ++starts_[dense_index(coordinate_of(k, 0), coordinate_of(k, 1), coordinate_of(k, 2)) + 1];
    }
    for (std::size_t i = 0; i < cells; ++i) starts_[i + 1] += starts_[i];
    fill_.assign(starts_.begin(), starts_.end() - 1);
    shapes_.resize(entries_.size());
    for (const auto& [k, shape] : entries_) {
      shapes_[fill_[dense_index(coordinate_of(k, 0), coordinate_of(k, 1), coordinate_of(k, 2))]++] =
          shape;
    }
    return;
  }
  std::sort(entries_.begin(), entries_.end());
  shapes_.reserve(entries_.size());
  cells_.reserve(entries_.size());
  for (const auto& entry : entries_) shapes_.push_back(entry.second);
  for (std::size_t begin = 0, end = 0; begin < entries_.size(); begin = end) {
    while (end < entries_.size() && entries_[end].first == entries_[begin].first) ++end;
    cells_.emplace(entries_[begin].first, std::make_pair(begin, end));
  }
}

}  // namespace gaphys::detail
