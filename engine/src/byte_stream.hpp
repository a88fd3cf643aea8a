// Little-endian bytes for snapshots (snapshot.cpp): integers by their value,
// reals by their bit patterns, so what is read back equals what was written
// to the bit. The reader never reads past its end: each read checks the
// bytes left first, and a count is checked against them before anything is
// allocated for it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "gaphys/algebra.hpp"
#include "validate.hpp"

namespace gaphys::detail {

// FNV-1a, 64 bits, as world::state_hash uses it.
inline std::uint64_t fnv1a(const std::uint8_t* bytes, std::size_t size) {
  std::uint64_t hash = 14695981039346656037ull;
  for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
  return hash;
}

static_assert(sizeof(real) == 4 || sizeof(real) == 8, "reals are binary32 or binary64");

class byte_writer {
 public:
  void u8(std::uint8_t x) { bytes_.push_back(x); }
  void boolean(bool x) { u8(x ? 1 : 0); }
  void u32(std::uint32_t x) { little_endian(x, 4); }
  void u64(std::uint64_t x) { little_endian(x, 8); }
  void i32(std::int32_t x) { u32(static_cast<std::uint32_t>(x)); }
  void raw(const char* text, std::size_t size) { bytes_.insert(bytes_.end(), text, text + size); }
  void number(real x) {
    if constexpr (sizeof(real) == 8) {
      std::uint64_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      u64(bits);
    } else {
      std::uint32_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      u32(bits);
    }
  }
  template <class Named>
  void numbers(const Named& value) {
    for (real x : value.c) number(x);
  }
  // A double whatever the engine's scalar (the world's clock).
  void float64(double x) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    u64(bits);
  }
  // Overwrites 8 bytes written earlier (a size known only later).
  void patch_u64(std::size_t at, std::uint64_t x) {
    for (int i = 0; i < 8; ++i) bytes_[at + i] = static_cast<std::uint8_t>(x >> (8 * i));
  }

  std::size_t size() const { return bytes_.size(); }
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  std::vector<std::uint8_t> take() { return std::move(bytes_); }

 private:
  void little_endian(std::uint64_t x, int count) {
    for (int i = 0; i < count; ++i) bytes_.push_back(static_cast<std::uint8_t>(x >> (8 * i)));
  }

  std::vector<std::uint8_t> bytes_;
};

// Reads bytes [offset, end) of a buffer. Every error is invalid_input naming
// the byte offset of the value at fault and what was being read, in the
// words of the caller's `what` and the item set by `within` ("body 3").
class byte_reader {
 public:
  byte_reader(const std::uint8_t* data, std::size_t offset, std::size_t end)
      : data_(data), at_(offset), last_(offset), end_(end) {}

  std::size_t offset() const { return at_; }
  std::size_t left() const { return end_ - at_; }
  // The offset of the last value read (where a complaint about it points).
  std::size_t last_offset() const { return last_; }

  // Names what the next reads belong to: a list ("contacts"), one of its
  // items ("body", 3), or nothing (nullptr).
  void within(const char* list) {
    item_ = list;
    indexed_ = false;
  }
  void within(const char* item, std::size_t index) {
    item_ = item;
    item_index_ = index;
    indexed_ = true;
  }

  std::uint8_t u8(const char* what) {
    need(1, what);
    return data_[at_++];
  }
  bool boolean(const char* what) {
    const std::uint8_t x = u8(what);
    if (x > 1) fail(what, " must be 0 or 1 (got ", int(x), ")");
    return x == 1;
  }
  std::uint32_t u32(const char* what) { return static_cast<std::uint32_t>(little_endian(4, what)); }
  std::uint64_t u64(const char* what) { return little_endian(8, what); }
  std::int32_t i32(const char* what) { return static_cast<std::int32_t>(u32(what)); }
  real number(const char* what) {
    real x;
    if constexpr (sizeof(real) == 8) {
      const std::uint64_t bits = u64(what);
      std::memcpy(&x, &bits, sizeof x);
    } else {
      const std::uint32_t bits = u32(what);
      std::memcpy(&x, &bits, sizeof x);
    }
    return x;
  }
  double float64(const char* what) {
    const std::uint64_t bits = u64(what);
    double x;
    std::memcpy(&x, &bits, sizeof x);
    return x;
  }
  // A vector, bivector or rotor, coordinate by coordinate.
  template <class Named>
  Named numbers(const char* what) {
    const std::size_t start = at_;
    Named value;
    for (real& x : value.c) x = number(what);
    last_ = start;
    return value;
  }
  // A count of items of at least `item_bytes` bytes each, which must all
  // fit in the bytes left: checked before the caller allocates for them.
  std::size_t count(const char* what, std::size_t item_bytes) {
    const std::uint64_t n = u64(what);
    if (n > left() / item_bytes) {
      fail(what, " is ", n, ", more than the ", left(), " bytes left can hold");
    }
    return static_cast<std::size_t>(n);
  }

  // invalid_input about the last value read.
  template <class... Parts>
  [[noreturn]] void fail(const Parts&... parts) const {
    fail_at(last_, parts...);
  }
  template <class... Parts>
  [[noreturn]] void fail_at(std::size_t offset, const Parts&... parts) const {
    if (item_ && indexed_) {
      reject("snapshot: ", item_, " ", item_index_, ": ", parts..., " (at byte ", offset, ")");
    }
    if (item_) reject("snapshot: ", item_, ": ", parts..., " (at byte ", offset, ")");
    reject("snapshot: ", parts..., " (at byte ", offset, ")");
  }

 private:
  void need(std::size_t size, const char* what) {
    last_ = at_;
    if (left() < size) {
      if (item_ && indexed_) {
        reject("snapshot: truncated at byte ", end_, " reading ", what, " of ", item_, " ",
               item_index_);
      }
      if (item_) reject("snapshot: truncated at byte ", end_, " reading ", what, " of ", item_);
      reject("snapshot: truncated at byte ", end_, " reading ", what);
    }
  }
  std::uint64_t little_endian(int size, const char* what) {
    need(static_cast<std::size_t>(size), what);
    std::uint64_t x = 0;
    for (int i = 0; i < size; ++i) x |= std::uint64_t(data_[at_ + i]) << (8 * i);
    at_ += static_cast<std::size_t>(size);
    return x;
  }

  const std::uint8_t* data_;
  std::size_t at_, last_, end_;
  const char* item_ = nullptr;
  std::size_t item_index_ = 0;
  bool indexed_ = false;
};

}  // namespace gaphys::detail
