// The world's spatial queries: ray casts and overlaps, through query_index.
#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "gaphys/world.hpp"
#include "pose_changes.hpp"
#include "query_index.hpp"
#include "ray_shape.hpp"
#include "validate.hpp"

namespace gaphys {

namespace detail {

void query_index::build(const std::vector<body>& bodies, version_type version) {
  placed_.clear();
  owner_.clear();
  std::vector<query_grid::bound> bounds;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const body& x = bodies[b];
    for (std::size_t s = 0; s < x.shapes().size(); ++s) {
      const attached_shape& a = x.shapes()[s];
      if (a.shape.is_sensor()) continue;  // queries pass through sensors
      const rotor attitude = e3ga::gp(x.attitude(), a.attitude);
      const vector centre = x.to_world(a.offset);
      placed_.push_back(place(a.shape, centre, attitude));
      owner_.push_back({b, s});
      bounds.push_back({centre, a.shape.bounding_radius()});
    }
  }
  grid_.build(bounds);
  marks_.assign(placed_.size(), 0);
  mark_ = 0;
  version_ = version;
}

std::uint32_t query_index::new_mark() const {
  if (++mark_ == 0) {  // wrapped: forget every old mark
    std::fill(marks_.begin(), marks_.end(), 0);
    mark_ = 1;
  }
  return mark_;
}

bool query_index::first_visit(std::size_t i, std::uint32_t mark) const {
  if (marks_[i] == mark) return false;
  marks_[i] = mark;
  return true;
}

}  // namespace detail

namespace {

struct ray {
  vector origin, direction;  // direction unit
  real max_distance;
};

// A query's point: finite, and near enough for its squared distances to
// real numbers (every shape's test squares them: from 1e160 m a ray "hit" a
// sphere at an infinite distance, at a NaN point).
void require_within_reach(const vector& point, const char* what) {
  detail::require_finite(point, what);
  if (!std::isfinite(e3ga::norm2(point))) {
    detail::reject(what, " is too far out for its squared distances to be real numbers (got ",
                   e3ga::basic_mv<real>(point), ")");
  }
}

ray validated_ray(const vector& origin, const vector& direction, real max_distance) {
  require_within_reach(origin, "ray origin");
  const vector unit = detail::unit_multiple(direction, "ray direction", " must be nonzero");
  if (std::isnan(max_distance) || max_distance < 0) {
    detail::reject("ray max_distance must be >= 0 (got ", max_distance, ")");
  }
  return {origin, unit, max_distance};
}

// Orders hits by distance, then body, then shape: the same order whatever
// order the cells were visited in.
bool nearer(const ray_hit& a, const ray_hit& b) {
  return std::tie(a.distance, a.body, a.shape) < std::tie(b.distance, b.body, b.shape);
}

}  // namespace

namespace {

// The index, rebuilt when a step, a new body or a body setter (through any
// reference) came after it.
const detail::query_index& current(std::unique_ptr<detail::query_index>& index,
                                   const std::vector<body>& bodies, std::uint64_t world_version) {
  const detail::query_index::version_type version{world_version, detail::pose_changes()};
  if (!index) index = std::make_unique<detail::query_index>();
  if (index->version() != version || index->size() == 0) index->build(bodies, version);
  return *index;
}

// Tests shape i of the index against the ray, once per query.
template <class Found>
void test_shape(const detail::query_index& index, std::size_t i, std::uint32_t mark, const ray& r,
                real within, Found&& found) {
  // (The hit names the body by index; the world turns it into its id.)
  if (!index.first_visit(i, mark)) return;
  const std::optional<detail::shape_hit> hit =
      detail::cast_ray(index.shape(i), r.origin, r.direction, within);
  if (!hit) return;
  found(ray_hit{index.body_of(i), index.shape_of(i), r.origin + hit->distance * r.direction,
                hit->normal, hit->distance});
}

}  // namespace

std::optional<ray_hit> world::ray_cast(const vector& origin, const vector& direction,
                                       real max_distance) const {
  const ray r = validated_ray(origin, direction, max_distance);
  const detail::query_index& index = current(queries_, bodies_, geometry_version_);
  std::optional<ray_hit> best;
  const auto keep = [&](const ray_hit& hit) {
    if (!best || nearer(hit, *best)) best = hit;
  };
  const std::uint32_t mark = index.new_mark();
  for (const std::size_t i : index.grid().unbounded())
    test_shape(index, i, mark, r, r.max_distance, keep);
  // A hit inside a cell lies at most where the ray leaves it: once the best
  // hit is nearer than that, no later cell holds a nearer one.
  index.grid().along(r.origin, r.direction, r.max_distance,
                     [&](const detail::query_grid::cell_shapes& shapes, real leaves) {
                       for (const std::size_t i : shapes) {
                         test_shape(index, i, mark, r, best ? best->distance : r.max_distance,
                                    keep);
                       }
                       return !(best && best->distance <= leaves);
                     });
  if (best) best->body = id_of(best->body);
  return best;
}

std::vector<ray_hit> world::ray_cast_all(const vector& origin, const vector& direction,
                                         real max_distance) const {
  const ray r = validated_ray(origin, direction, max_distance);
  const detail::query_index& index = current(queries_, bodies_, geometry_version_);
  std::vector<ray_hit> hits;
  const auto keep = [&](const ray_hit& hit) { hits.push_back(hit); };
  const std::uint32_t mark = index.new_mark();
  for (const std::size_t i : index.grid().unbounded())
    test_shape(index, i, mark, r, r.max_distance, keep);
  index.grid().along(r.origin, r.direction, r.max_distance,
                     [&](const detail::query_grid::cell_shapes& shapes, real) {
                       for (const std::size_t i : shapes)
                         test_shape(index, i, mark, r, r.max_distance, keep);
                       return true;
                     });
  std::sort(hits.begin(), hits.end(), nearer);
  for (ray_hit& hit : hits) hit.body = id_of(hit.body);
  return hits;
}

namespace {

// The bodies with a shape the query shape overlaps or touches, through the
// narrow phase (touching()), by index in increasing order.
std::vector<body_id> overlapping(const detail::query_index& index, const placed_shape& query,
                                 real reach) {
  std::vector<body_id> found;
  const std::uint32_t mark = index.new_mark();
  contact_manifold manifold;
  const auto test = [&](std::size_t i) {
    if (index.first_visit(i, mark) && touching(query, index.shape(i), manifold)) {
      found.push_back(index.body_of(i));
    }
  };
  for (const std::size_t i : index.grid().unbounded()) test(i);
  const vector extent{reach, reach, reach};
  index.grid().within(query.center - extent, query.center + extent,
                      [&](const detail::query_grid::cell_shapes& shapes) {
                        for (const std::size_t i : shapes) test(i);
                      });
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());
  return found;
}

}  // namespace

std::vector<body_id> world::overlap_sphere(const vector& centre, real radius) const {
  require_within_reach(centre, "overlap sphere centre");
  detail::require_length(radius, "overlap sphere radius");
  const detail::query_index& index = current(queries_, bodies_, geometry_version_);
  std::vector<body_id> found =
      overlapping(index, place(shape::sphere(radius), centre, rotor{1, 0, 0, 0}), radius);
  for (body_id& b : found) b = id_of(b);
  return found;
}

std::vector<body_id> world::overlap_box(const vector& centre, const vector& half_extents,
                                        const rotor& attitude) const {
  require_within_reach(centre, "overlap box centre");
  const shape box = shape::box(half_extents);  // validates the half extents
  const rotor unit = detail::unit_rotor(attitude, "overlap box attitude");
  const detail::query_index& index = current(queries_, bodies_, geometry_version_);
  std::vector<body_id> found =
      overlapping(index, place(box, centre, unit), e3ga::norm(half_extents));
  for (body_id& b : found) b = id_of(b);
  return found;
}

}  // namespace gaphys
