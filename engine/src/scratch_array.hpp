// An array rebuilt from scratch at each use: every element read is first
// written in the same use. Made longer, it keeps none of what it held and
// sets none of its new elements, where std::vector's resize copies the old
// elements across and zeroes the new ones, every page of them. (The
// sweeps' plain records are one per slot, of which about an eighth are
// written at 10,000 spheres: as a vector that grew with the pile, the step
// that outgrew it copied and zeroed up to 13 MB on one thread while the
// others waited, and a quarter of a pile's page faults were its pages.)
#pragma once

#include <cstddef>
#include <memory>
#include <type_traits>

#include "huge_pages.hpp"

namespace gaphys::detail {

template <class T>
class scratch_array {
  static_assert(std::is_trivially_default_constructible_v<T> && std::is_trivially_destructible_v<T>);

 public:
  using value_type = T;

  // Room for at least `count` elements, their values unspecified.
  void reset(std::size_t count) {
    if (count > capacity_) {
      // (The old elements freed first: nothing of them is kept.)
      const std::size_t room = grown_room(count, capacity_);
      elements_.reset();
      capacity_ = 0;
      elements_.reset(new T[room]);
      capacity_ = room;
      advise_huge_pages(elements_.get(), capacity_ * sizeof(T));
    }
  }
  T* data() { return elements_.get(); }
  T& operator[](std::size_t i) { return elements_[i]; }
  const T& operator[](std::size_t i) const { return elements_[i]; }

 private:
  std::unique_ptr<T[]> elements_;
  std::size_t capacity_ = 0;
};

}  // namespace gaphys::detail
