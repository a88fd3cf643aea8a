// The world's index for spatial queries: every shape placed where its body
// is now, which body and shape it is, and the grid of their bounds.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "gaphys/body.hpp"
#include "gaphys/contact.hpp"
#include "gaphys/queries.hpp"
#include "query_grid.hpp"

namespace gaphys::detail {

class query_index {
 public:
  // `version`: what the world and the body setters have changed, as
  // (the world's count, detail::pose_changes()) when it is built.
  using version_type = std::pair<std::uint64_t, std::uint64_t>;
  void build(const std::vector<body>& bodies, version_type version);
  version_type version() const { return version_; }

  std::size_t size() const { return placed_.size(); }
  const placed_shape& shape(std::size_t i) const { return placed_[i]; }
  body_id body_of(std::size_t i) const { return owner_[i].body; }
  std::size_t shape_of(std::size_t i) const { return owner_[i].shape; }
  const query_grid& grid() const { return grid_; }

  // A fresh mark for a query to tell the shapes it has tested from the rest
  // (a shape lies in several cells): first_visit(i, mark) is true once.
  std::uint32_t new_mark() const;
  bool first_visit(std::size_t i, std::uint32_t mark) const;

 private:
  struct owner {
    body_id body;
    std::size_t shape;
  };
  std::vector<placed_shape> placed_;
  std::vector<owner> owner_;
  query_grid grid_;
  version_type version_{};
  mutable std::vector<std::uint32_t> marks_;
  mutable std::uint32_t mark_ = 0;
};

}  // namespace gaphys::detail
