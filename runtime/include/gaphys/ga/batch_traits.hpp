// What a generated kernel needs to know of its scalar type T to run on a
// batch (W values of a named type at once, each coordinate a pack of W
// lanes; gaphys/ga/batch.hpp): whether T is a pack at all. Kept apart from
// batch.hpp so that the kernels can ask without bringing <experimental/simd>
// into every translation unit.
#pragma once

namespace gaphys::ga {

// Specialized by gaphys/ga/batch.hpp for its packs, with
//   scalar, lanes: the lanes' type and number;
//   lanewise<R>(f, x...): R whose lane i is f(lane i of each x), for the
//     kernels that cannot run on packs (branches, the general mv path).
template <class T>
struct batch_traits {
  static constexpr bool is_batch = false;
};

template <class T>
inline constexpr bool is_batch_v = batch_traits<T>::is_batch;

}  // namespace gaphys::ga
