// Table-driven bilinear products and linear maps on general multivectors:
// the generic path every variant falls back to, and the whole of the
// reference variant.
#pragma once

#include <cstdint>

namespace gaphys::ga {

// One term of the product of two basis blades: coefficient * blade.
struct product_term {
  std::uint8_t blade;
  double coefficient;
};

// terms[offsets[i * blade_count + j] .. offsets[i * blade_count + j + 1]) is
// the product of canonical blades i and j (several terms in a non-orthogonal basis).
struct product_table {
  const std::uint16_t* offsets;
  const product_term* terms;
};

// terms[offsets[i] .. offsets[i + 1]) is the image of canonical blade i.
struct linear_table {
  const std::uint16_t* offsets;
  const product_term* terms;
};

// Visits the set bits of a bitmap, lowest first.
template <class F>
constexpr void for_each_bit(std::uint32_t bits, F&& f) {
  while (bits != 0) {
    const int i = __builtin_ctz(bits);
    f(i);
    bits &= bits - 1;
  }
}

// Sums table terms over the (possibly) nonzero coefficients only.
template <class MV>
MV table_product(const product_table& table, const MV& a, const MV& b) {
  using T = typename MV::scalar_type;
  MV r;
  for_each_bit(a.bits, [&](int i) {
    for_each_bit(b.bits, [&](int j) {
      const int pair = i * MV::size + j;
      const T ab = a.c[i] * b.c[j];
      for (int t = table.offsets[pair]; t < table.offsets[pair + 1]; ++t) {
        const product_term& term = table.terms[t];
        r.c[term.blade] += T(term.coefficient) * ab;
        r.bits |= std::uint32_t(1) << term.blade;
      }
    });
  });
  return r;
}

template <class MV>
MV table_linear_map(const linear_table& table, const MV& a) {
  using T = typename MV::scalar_type;
  MV r;
  for_each_bit(a.bits, [&](int i) {
    for (int t = table.offsets[i]; t < table.offsets[i + 1]; ++t) {
      const product_term& term = table.terms[t];
      r.c[term.blade] += T(term.coefficient) * a.c[i];
      r.bits |= std::uint32_t(1) << term.blade;
    }
  });
  return r;
}

}  // namespace gaphys::ga
