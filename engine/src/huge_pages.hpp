// The large buffers a step fills (the contact lists, the solver's rows,
// the sweeps' records), backed by huge pages where the system gives them on
// request (Linux's transparent huge pages in their "madvise" mode).
//
// A list that grows with a pile writes pages it never wrote before, and the
// first write of each 4 KiB page is a page fault: on this project's virtual
// machine about 9 us each (its page tables are shadowed by the host), and 15
// to 300 of them a step at 10,000 spheres while the pile filled up, several
// on one thread while the others waited (the contact list made longer by
// std::vector's resize, 0.1-0.2 ms a step). A 2 MiB page costs one fault
// for 512 of them. Elsewhere the request costs a system call per buffer
// grown; it changes no value the buffer holds.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace gaphys::detail {

// Asks for huge pages over the whole 2 MiB pages inside [data, data +
// bytes) (none for a buffer too small to hold one). A hint: where it is not
// taken, nothing changes.
inline void advise_huge_pages(const void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t huge = std::uintptr_t{1} << 21;
  const auto at = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t begin = (at + huge - 1) & ~(huge - 1), end = (at + bytes) & ~(huge - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)data, (void)bytes;
#endif
}

// The room a buffer of `capacity` elements gets when `count` outgrow it: a
// quarter more than `count` and at least twice what it had (a pile's lists
// grow a little most steps, and each new room is written anew).
inline std::size_t grown_room(std::size_t count, std::size_t capacity) {
  return std::max(count + count / 4, 2 * capacity);
}

// Makes room in `v` for at least `count` elements: where it has less,
// grown_room in huge pages. What `v` holds is kept, moved over once the new
// room is asked for in huge pages (moved first, its pages would be small
// ones already).
template <class T>
void reserve_in_huge_pages(std::vector<T>& v, std::size_t count) {
  if (v.capacity() >= count) return;
  std::vector<T> room;
  room.reserve(grown_room(count, v.capacity()));
  advise_huge_pages(room.data(), room.capacity() * sizeof(T));
  room.insert(room.end(), std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
  v.swap(room);
}

// The same for a list written over before it is read: where it must grow,
// what it holds is dropped first instead of moved.
template <class T>
void reserve_over_in_huge_pages(std::vector<T>& v, std::size_t count) {
  if (v.capacity() >= count) return;
  v.clear();
  reserve_in_huge_pages(v, count);
}

// v.resize(count), its room made by reserve_in_huge_pages.
template <class T>
void resize_in_huge_pages(std::vector<T>& v, std::size_t count) {
  reserve_in_huge_pages(v, count);
  v.resize(count);
}

}  // namespace gaphys::detail
