// Table-driven bilinear products and linear maps on general multivectors:
// the generic path every variant falls back to, and the whole of the
// reference variant.
#pragma once

#include <cstdint>
#include <cstring>

#include "compiler.hpp"
#include "mv_algorithms.hpp"
#include "uninitialized.hpp"

namespace gaphys::ga {

// One term of the product of two basis blades: coefficient * blade.
struct product_term {
  std::uint8_t blade;
  double coefficient;
};

// terms[offsets[i] .. offsets[i + 1]) is the image of canonical blade i.
struct linear_table {
  const std::uint16_t* offsets;
  const product_term* terms;
};

// A change of coordinates: coefficient i goes to coefficient to[i] times
// scale[i] (`to` a permutation), plus extra_count terms
// (extra_from -> extra_to, times extra_scale).
struct basis_change {
  const std::uint8_t* to;
  const double* scale;
  int extra_count;
  const std::uint8_t* extra_from;
  const std::uint8_t* extra_to;
  const double* extra_scale;
};

// A basis f_0 .. f_{n-1} that the metric makes orthogonal (c3ga: no + ni and
// (ni - no) / 2 for no and ni; an algebra whose basis is orthogonal already:
// its own), and the changes of coordinates to and from it. Blades of the
// orthogonal basis are numbered by bitmap (bit k: f_k), so that the product
// of blades i and j is the single blade i ^ j (XOR).
struct orthogonal_basis {
  basis_change to_left;   // canonical index -> orthogonal bitmap, times (-1)^(|ih| |il|)
  basis_change to_right;  // canonical index -> orthogonal bitmap
  basis_change from;      // orthogonal bitmap -> canonical index
};

// A product in the orthogonal basis, a signed XOR permutation: blades i and j
// (i = 4 ih + il, j = 4 jh + jl) multiply to S(i, j) times blade i ^ j, where
//   S(i, j) = S(ih, jh) (-1)^(|ih| |jl|) S(il, jl).
// The generator checks that every product of every algebra it makes factors
// so (generator/gaphys_gen/orthogonal.py) and leaves `dense` null otherwise.
struct dense_product {
  const orthogonal_basis* basis;
  const double* lanes;   // [u][v] = S(u, u ^ v), 4 x 4
  const double* blocks;  // [ih][jh][v] = S(ih, jh) (-1)^(|ih| |v|), (size / 4)^2 x 4
  // The canonical blades the product of blade i with any blade can reach, and
  // of any blade with blade j: the bits of a product with a full argument.
  const std::uint32_t* reach_rows;
  const std::uint32_t* reach_columns;
};

// terms[offsets[i * blade_count + j] .. offsets[i * blade_count + j + 1]) is
// the product of canonical blades i and j (several terms in a non-orthogonal
// basis). `dense`, where the generator made it, computes products with a full
// argument (and another not too sparse) in the orthogonal basis.
struct product_table {
  const std::uint16_t* offsets;
  const product_term* terms;
  const dense_product* dense = nullptr;
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

namespace detail {

// Native 16-byte vectors (SSE2, NEON) of float or double, by GCC and Clang
// vector extensions; other scalars and compilers keep the sparse path. A
// block of 4 coefficients is 4 / lanes such vectors.
template <class T>
struct simd16 {
  static constexpr bool available = false;
};
#if defined(__GNUC__) || defined(__clang__)
template <>
struct simd16<double> {
  static constexpr bool available = true;
  typedef double type __attribute__((vector_size(16)));
};
template <>
struct simd16<float> {
  static constexpr bool available = true;
  typedef float type __attribute__((vector_size(16)));
};
#endif

// out = map(x), every coefficient of out written.
template <int n, class T>
GAPHYS_ALWAYS_INLINE void change_basis(const basis_change& map, const T* x, T* out) {
  for (int i = 0; i < n; ++i) out[map.to[i]] = T(map.scale[i]) * x[i];
  for (int t = 0; t < map.extra_count; ++t)
    out[map.extra_to[t]] += T(map.extra_scale[t]) * x[map.extra_from[t]];
}

// A bilinear product of two multivectors in the orthogonal basis: for each
// block pair (ih, jh), the 4 x 4 products of a's block ih with b's block jh
// go to the result's block ih ^ jh, lane v = il ^ jl. b's blocks, permuted
// by XOR u and times S(u, u ^ v), are made once; each block pair then costs
// four 4-lane multiply-adds and a 4-lane factor: size^2 multiplications in
// all, in vectors, with no scatter. The coefficients go in and out through
// the changes of basis (a few terms per blade).
template <class MV>
MV dense_table_product(const dense_product& d, const MV& a, const MV& b, std::uint32_t bits) {
  using T = typename MV::scalar_type;
  using V = typename simd16<T>::type;
  constexpr int n = MV::size;
  constexpr int blocks = n / 4;
  constexpr int lanes = int(sizeof(V) / sizeof(T));
  constexpr int per_block = 4 / lanes;  // vectors per block of 4
  alignas(16) T x[n];
  alignas(16) T y[n];
  change_basis<n>(d.basis->to_left, a.c.data(), x);
  change_basis<n>(d.basis->to_right, b.c.data(), y);

  // p[jh][u][v] = S(u, u ^ v) y[4 jh + (u ^ v)]
  alignas(16) T p[blocks][4][4];
  for (int jh = 0; jh < blocks; ++jh)
    for (int u = 0; u < 4; ++u)
      for (int v = 0; v < 4; ++v) p[jh][u][v] = T(d.lanes[4 * u + v]) * y[4 * jh + (u ^ v)];
  // x, each coefficient in every lane
  V xs[n];
  for (int i = 0; i < n; ++i)
    for (int l = 0; l < lanes; ++l) xs[i][l] = x[i];

  alignas(16) T z[n];
  for (int kh = 0; kh < blocks; ++kh) {
    V acc[per_block] = {};
    for (int ih = 0; ih < blocks; ++ih) {
      const int jh = ih ^ kh;
      const double* f = d.blocks + 4 * (ih * blocks + jh);
      for (int h = 0; h < per_block; ++h) {
        V pv[4], fv;
        for (int u = 0; u < 4; ++u) std::memcpy(&pv[u], &p[jh][u][h * lanes], sizeof(V));
        for (int l = 0; l < lanes; ++l) fv[l] = T(f[h * lanes + l]);
        const V* xi = xs + 4 * ih;
        acc[h] += fv * (xi[0] * pv[0] + xi[1] * pv[1] + xi[2] * pv[2] + xi[3] * pv[3]);
      }
    }
    std::memcpy(z + 4 * kh, acc, sizeof acc);
  }

  MV r(uninitialized);
  change_basis<n>(d.basis->from, z, r.c.data());
  r.bits = bits;
  return r;
}

// Whether the dense path is the faster for arguments with these bits, and the
// result's bits if so. It costs about as much as the sparse path's loop over
// a sixth of the pairs of a full product (sparse: a few ns per pair of set
// bits, even where the pair's product is zero; bench/bench_full_product.cpp
// and docs/benchmarks.md). One argument must be full: the result's bits are
// then exactly the sparse path's (the blades the other argument's blades
// reach), without a visit of every pair.
template <class MV>
bool dense_bits(const dense_product& d, std::uint32_t a_bits, std::uint32_t b_bits,
                std::uint32_t& bits) {
  constexpr std::uint32_t full =
      MV::size == 32 ? ~std::uint32_t(0) : (std::uint32_t(1) << MV::size) - 1;
  const bool a_full = a_bits == full;
  if (!a_full && b_bits != full) return false;
  const std::uint32_t other = a_full ? b_bits : a_bits;
  if (6 * MV::size * bit_count(other) < MV::size * MV::size) return false;
  const std::uint32_t* reach = a_full ? d.reach_columns : d.reach_rows;
  bits = 0;
  for (int i = 0; i < MV::size; ++i) bits |= reach[i] & (0u - (other >> i & 1u));
  return true;
}

}  // namespace detail

// Sums table terms over the (possibly) nonzero coefficients only; products
// with a full argument go through the orthogonal basis where the table has
// one (detail::dense_bits).
template <class MV>
MV table_product(const product_table& table, const MV& a, const MV& b) {
  using T = typename MV::scalar_type;
  if constexpr (detail::simd16<T>::available && MV::size >= 8 && MV::size <= 32) {
    std::uint32_t bits;
    if (table.dense != nullptr && detail::dense_bits<MV>(*table.dense, a.bits, b.bits, bits))
      return detail::dense_table_product(*table.dense, a, b, bits);
  }
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
