// The general multivector of an algebra too large for a dense one: more than
// 5 basis vectors (more than 32 blades, the width of a dense mv's bitmap), up
// to 16. Its coefficients are a sorted list of (blade, value) terms on the
// heap, and its products loop over pairs of terms with bitwise blade
// arithmetic in an orthogonal basis: no 2^n x 2^n table exists anywhere (the
// 15-D quadric conformal algebra has 32,768 blades).
//
// A blade here is a bitmap over the spec's basis vectors (bit i: vector i;
// factors in ascending order). The user-facing index of a blade is its
// canonical index (by grade, then lexicographically by basis order), as in
// the dense mv; canonical_index and blade_of_index convert between the two.
//
// A generated sparse basic_mv has `terms` (sorted by blade, no repeats) and
// `bits`, whose bit k is set when grade k may be present: the bits that
// grade_mask(k) == 1 << k select, so the algorithms written for the dense mv
// (keep_grades, `x.bits & grade_mask(2)`) read the same on both.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace gaphys::ga {

// True for a generated basic_mv that stores its terms sparsely.
template <class MV, class = void>
struct is_sparse : std::false_type {};
template <class MV>
struct is_sparse<MV, std::enable_if_t<MV::sparse>> : std::true_type {};
template <class MV>
inline constexpr bool is_sparse_v = is_sparse<MV>::value;

template <class T>
struct blade_term {
  std::uint32_t blade;
  T value;
};

namespace bitwise {

// How many factors a blade has: sums of bit pairs, nibbles, then bytes,
// inline on every target (__builtin_popcount without -mpopcnt is a library
// call, which took 29% of a sparse product's time).
inline int grade(std::uint32_t blade) {
  blade = blade - ((blade >> 1) & 0x55555555u);
  blade = (blade & 0x33333333u) + ((blade >> 2) & 0x33333333u);
  blade = (blade + (blade >> 4)) & 0x0f0f0f0fu;
  return static_cast<int>((blade * 0x01010101u) >> 24);
}

// The sign of a b for basis blades a, b of an orthogonal basis, before the
// squares of their common factors: (-1)^(swaps to sort b's factors into a's).
inline int reorder_sign(std::uint32_t a, std::uint32_t b) {
  int swaps = 0;
  for (a >>= 1; a != 0; a >>= 1) swaps += grade(a & b);
  return swaps & 1 ? -1 : 1;
}

// The index of the lowest set bit of a nonzero bitmap.
inline int lowest(std::uint32_t bits) {
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_ctz(bits);
#else
  int i = 0;
  while (!(bits >> i & 1)) ++i;
  return i;
#endif
}

inline long binomial(int n, int k) {
  if (k < 0 || k > n) return 0;
  long r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

}  // namespace bitwise

// The canonical index of a blade of an n-vector basis: the blades of lower
// grade first, then those of its grade before it in lexicographic order of
// their factor lists.
inline int canonical_index(int n, std::uint32_t blade) {
  const int k = bitwise::grade(blade);
  long index = 0;
  for (int g = 0; g < k; ++g) index += bitwise::binomial(n, g);
  int next = 0;  // the smallest vector the j-th factor may be
  int j = 0;
  for (int v = 0; v < n; ++v) {
    if (!(blade >> v & 1)) continue;
    // Sets with the same first j factors and a smaller (j+1)-th come first.
    for (int w = next; w < v; ++w) index += bitwise::binomial(n - 1 - w, k - j - 1);
    next = v + 1;
    ++j;
  }
  return int(index);
}

// The blade of canonical index `index` of an n-vector basis.
inline std::uint32_t blade_of_index(int n, int index) {
  if (index < 0 || index >= (1 << n)) throw std::out_of_range("blade index out of range");
  int k = 0;
  long rest = index;
  while (rest >= bitwise::binomial(n, k)) rest -= bitwise::binomial(n, k++);
  std::uint32_t blade = 0;
  int v = 0;
  for (int j = 0; j < k; ++j) {
    for (;; ++v) {
      const long with_v = bitwise::binomial(n - 1 - v, k - j - 1);
      if (rest < with_v) break;
      rest -= with_v;
    }
    blade |= std::uint32_t(1) << v++;
  }
  return blade;
}

// "e1^e2", or "1" for the scalar, from the basis vectors' names.
inline std::string blade_name(const char* const* basis, std::uint32_t blade) {
  std::string name;
  for (int v = 0; blade >> v != 0; ++v) {
    if (!(blade >> v & 1)) continue;
    if (!name.empty()) name += '^';
    name += basis[v];
  }
  return name.empty() ? "1" : name;
}

// A change of basis, vector by vector: vector i goes to
// sum over t in [offsets[i], offsets[i + 1]) of coefficients[t] * vectors[t].
struct vector_map {
  const std::uint8_t* offsets;
  const std::uint8_t* vectors;
  const double* coefficients;
};

// A basis f_0 .. f_{n-1} that the metric makes orthogonal (f_k . f_k =
// squares[k]), and the changes between it and the spec's basis. `identity`
// when the spec's basis is orthogonal already.
struct sparse_orthogonal_basis {
  int dimension;
  bool identity;
  const double* squares;
  vector_map to_orthogonal;    // e_i in terms of the f_k
  vector_map from_orthogonal;  // f_k in terms of the e_i
};

enum class product_kind { gp, op, lc, rc, scp };

// A bilinear product of a sparse algebra, as its descriptor names it
// (gp_table, ...): the sparse counterpart of product_table.
struct bitwise_product {
  product_kind kind;
  const sparse_orthogonal_basis* basis;
};

enum class linear_kind { dual, undual, right_complement, left_complement };

// dual and undual are x I^-1 and x I where I^2 != 0, and the right and left
// complements in a degenerate metric; `pseudoscalar_square` is I^2.
struct bitwise_linear_map {
  linear_kind kind;
  const sparse_orthogonal_basis* basis;
  double pseudoscalar_square;
};

enum class grade_sign_kind { reverse, involute, conjugate };

// The signs of reverse, involute and conjugate, by grade.
struct grade_signs {
  grade_sign_kind kind;
  int operator()(int k) const {
    const int reverse = (k * (k - 1) / 2) & 1 ? -1 : 1;
    const int involute = k & 1 ? -1 : 1;
    switch (kind) {
      case grade_sign_kind::reverse:
        return reverse;
      case grade_sign_kind::involute:
        return involute;
      default:
        return reverse * involute;
    }
  }
};

namespace sparse {

template <class T>
using terms = std::vector<blade_term<T>>;

// Bit k set for each grade k that x has.
template <class T>
std::uint32_t grade_bits(const terms<T>& x) {
  std::uint32_t bits = 0;
  for (const auto& t : x) bits |= std::uint32_t(1) << bitwise::grade(t.blade);
  return bits;
}

// Sorts by blade, adds repeats, drops exact zeros.
template <class T>
void normalize(terms<T>& x) {
  std::sort(x.begin(), x.end(),
            [](const blade_term<T>& p, const blade_term<T>& q) { return p.blade < q.blade; });
  std::size_t out = 0;
  for (std::size_t i = 0; i < x.size();) {
    const std::uint32_t blade = x[i].blade;
    T sum = 0;
    for (; i < x.size() && x[i].blade == blade; ++i) sum += x[i].value;
    if (sum != T(0)) x[out++] = {blade, sum};
  }
  x.resize(out);
}

// Sums terms into a dense array over every blade, without sorting them
// first: 2^n entries, zero between uses, and the list of those touched. One
// per thread and scalar type, grown to the largest algebra used.
template <class T>
class accumulator {
 public:
  static accumulator& scratch(int dimension) {
    thread_local accumulator instance;
    const std::size_t size = std::size_t(1) << dimension;
    if (instance.sums_.size() < size) {
      instance.sums_.resize(size, T(0));
      instance.seen_.resize(size, 0);
    }
    return instance;
  }
  void add(std::uint32_t blade, T value) {
    if (!seen_[blade]) {
      seen_[blade] = 1;
      touched_.push_back(blade);
    }
    sums_[blade] += value;
  }
  // The sums, sorted by blade and without exact zeros; leaves the array zero.
  terms<T> take() {
    std::sort(touched_.begin(), touched_.end());
    terms<T> out;
    out.reserve(touched_.size());
    for (std::uint32_t blade : touched_) {
      if (sums_[blade] != T(0)) out.push_back({blade, sums_[blade]});
      sums_[blade] = T(0);
      seen_[blade] = 0;
    }
    touched_.clear();
    return out;
  }

 private:
  std::vector<T> sums_;
  std::vector<unsigned char> seen_;
  std::vector<std::uint32_t> touched_;
};

template <class MV>
MV from_sorted(terms<typename MV::scalar_type> x) {
  MV r;
  r.bits = grade_bits(x);
  r.terms = std::move(x);
  return r;
}

template <class MV>
MV from_unsorted(terms<typename MV::scalar_type> x) {
  normalize(x);
  return from_sorted<MV>(std::move(x));
}

// The images of blades under the outermorphism of a vector map (each
// blade's factors mapped and wedged in ascending order), made on first use
// and kept: one cache per map and thread, so no locking, grown to the blades
// met (at most 2^16).
class blade_images {
 public:
  static blade_images& of(const vector_map& map, int dimension) {
    // unique_ptr: a reference handed out stays valid when the list grows.
    thread_local std::vector<std::pair<const vector_map*, std::unique_ptr<blade_images>>> caches;
    for (auto& [key, images] : caches)
      if (key == &map) return *images;
    caches.emplace_back(&map, std::unique_ptr<blade_images>(new blade_images(map, dimension)));
    return *caches.back().second;
  }

  // The image of `blade`: count terms from first.
  struct span {
    const blade_term<double>* first;
    std::size_t count;
  };
  span image(std::uint32_t blade) {
    if (begin_[blade] == unmade) make(blade);
    return {terms_.data() + begin_[blade], std::size_t(end_[blade] - begin_[blade])};
  }

 private:
  static constexpr std::uint32_t unmade = ~std::uint32_t(0);

  blade_images(const vector_map& map, int dimension)
      : map_(map),
        begin_(std::size_t(1) << dimension, unmade),
        end_(std::size_t(1) << dimension, 0) {}

  void make(std::uint32_t blade) {
    std::vector<blade_term<double>> image{{0u, 1.0}}, next;
    for (int i = 0; blade >> i != 0; ++i) {
      if (!(blade >> i & 1)) continue;
      next.clear();
      for (const auto& part : image)
        for (int t = map_.offsets[i]; t < map_.offsets[i + 1]; ++t) {
          const std::uint32_t bit = std::uint32_t(1) << map_.vectors[t];
          if (part.blade & bit) continue;
          // Wedged on the right, the new factor passes those above it.
          const double sign = bitwise::grade(part.blade & ~(2 * bit - 1)) & 1 ? -1.0 : 1.0;
          next.push_back({part.blade | bit, sign * map_.coefficients[t] * part.value});
        }
      image.swap(next);
    }
    begin_[blade] = std::uint32_t(terms_.size());
    terms_.insert(terms_.end(), image.begin(), image.end());
    end_[blade] = std::uint32_t(terms_.size());
  }

  const vector_map& map_;
  std::vector<std::uint32_t> begin_, end_;
  std::vector<blade_term<double>> terms_;
};

// The image of x under the outermorphism of a vector map.
template <class T>
terms<T> outermorphism(const vector_map& map, const terms<T>& x, int dimension) {
  accumulator<T>& out = accumulator<T>::scratch(dimension);
  blade_images& images = blade_images::of(map, dimension);
  for (const auto& term : x) {
    const blade_images::span image = images.image(term.blade);
    for (std::size_t k = 0; k < image.count; ++k)
      out.add(image.first[k].blade, T(image.first[k].value) * term.value);
  }
  return out.take();
}

inline bool kept(product_kind kind, std::uint32_t a, std::uint32_t b) {
  switch (kind) {
    case product_kind::gp:
      return true;
    case product_kind::op:
      return (a & b) == 0;
    case product_kind::lc:  // grade |b| - |a|: a's factors all in b
      return (a & b) == a;
    case product_kind::rc:
      return (a & b) == b;
    default:  // scp
      return a == b;
  }
}

// The product of blades a and b of the orthogonal basis, times its kind's
// grade filter: a single blade a ^ b (XOR) times this number.
inline double blade_factor(const sparse_orthogonal_basis& basis, product_kind kind, std::uint32_t a,
                           std::uint32_t b) {
  if (!kept(kind, a, b)) return 0;
  double f = bitwise::reorder_sign(a, b);
  for (std::uint32_t common = a & b; common != 0; common &= common - 1)
    f *= basis.squares[bitwise::lowest(common)];
  return f;
}

template <class T>
terms<T> product_terms(const sparse_orthogonal_basis& basis, product_kind kind, const terms<T>& a,
                       const terms<T>& b) {
  accumulator<T>& out = accumulator<T>::scratch(basis.dimension);
  for (const auto& x : a)
    for (const auto& y : b) {
      const double f = blade_factor(basis, kind, x.blade, y.blade);
      if (f != 0) out.add(x.blade ^ y.blade, T(f) * x.value * y.value);
    }
  return out.take();
}

// A bilinear product: in the orthogonal basis (one blade per pair of terms),
// except the outer product, which needs no metric.
template <class MV>
MV product(const bitwise_product& p, const MV& a, const MV& b) {
  using T = typename MV::scalar_type;
  const sparse_orthogonal_basis& basis = *p.basis;
  // The outer product reads no square (its blades share no factor).
  if (p.kind == product_kind::op || basis.identity)
    return from_sorted<MV>(product_terms(basis, p.kind, a.terms, b.terms));
  const int n = basis.dimension;
  const terms<T> x = outermorphism(basis.to_orthogonal, a.terms, n);
  const terms<T> y = outermorphism(basis.to_orthogonal, b.terms, n);
  const terms<T> z = product_terms(basis, p.kind, x, y);
  return from_sorted<MV>(outermorphism(basis.from_orthogonal, z, n));
}

// The metric-free complements: blade ^ (sign * complement) = I (right), or
// (sign * complement) ^ blade = I (left), I the pseudoscalar.
template <class MV>
MV complement(const MV& a, int dimension, bool right) {
  using T = typename MV::scalar_type;
  const std::uint32_t full = (std::uint32_t(1) << dimension) - 1;
  terms<T> out;
  out.reserve(a.terms.size());
  for (const auto& t : a.terms) {
    const std::uint32_t c = full & ~t.blade;
    const int sign = right ? bitwise::reorder_sign(t.blade, c) : bitwise::reorder_sign(c, t.blade);
    out.push_back({c, T(sign) * t.value});
  }
  return from_unsorted<MV>(std::move(out));
}

template <class MV>
MV linear_map(const bitwise_linear_map& m, const MV& a) {
  using T = typename MV::scalar_type;
  const int n = m.basis->dimension;
  const std::uint32_t full = (std::uint32_t(1) << n) - 1;
  const bool degenerate = m.pseudoscalar_square == 0;
  switch (m.kind) {
    case linear_kind::right_complement:
      return complement(a, n, true);
    case linear_kind::left_complement:
      return complement(a, n, false);
    case linear_kind::dual: {  // x I^-1 = x I / I^2
      if (degenerate) return complement(a, n, true);
      MV inverse;
      inverse.terms = {{full, T(1 / m.pseudoscalar_square)}};
      inverse.bits = std::uint32_t(1) << n;
      return product(bitwise_product{product_kind::gp, m.basis}, a, inverse);
    }
    default: {  // undual: x I
      if (degenerate) return complement(a, n, false);
      MV pseudoscalar;
      pseudoscalar.terms = {{full, T(1)}};
      pseudoscalar.bits = std::uint32_t(1) << n;
      return product(bitwise_product{product_kind::gp, m.basis}, a, pseudoscalar);
    }
  }
}

template <class MV>
typename MV::scalar_type coefficient(const MV& x, std::uint32_t blade) {
  const auto it = std::lower_bound(x.terms.begin(), x.terms.end(), blade,
                                   [](const auto& t, std::uint32_t b) { return t.blade < b; });
  return it != x.terms.end() && it->blade == blade ? it->value : typename MV::scalar_type(0);
}

template <class MV>
MV keep_grades(const MV& x, std::uint32_t grades) {
  MV r;
  for (const auto& t : x.terms)
    if (grades >> bitwise::grade(t.blade) & 1) r.terms.push_back(t);
  r.bits = x.bits & grades;
  return r;
}

template <class MV>
MV linear_combination(typename MV::scalar_type a, const MV& x, typename MV::scalar_type b,
                      const MV& y) {
  MV r;
  r.terms.reserve(x.terms.size() + y.terms.size());
  std::size_t i = 0, j = 0;
  // A merge of two sorted lists; zeros are kept, as the dense mv keeps its bits.
  while (i < x.terms.size() || j < y.terms.size()) {
    if (j == y.terms.size() || (i < x.terms.size() && x.terms[i].blade < y.terms[j].blade)) {
      r.terms.push_back({x.terms[i].blade, a * x.terms[i].value});
      ++i;
    } else if (i == x.terms.size() || y.terms[j].blade < x.terms[i].blade) {
      r.terms.push_back({y.terms[j].blade, b * y.terms[j].value});
      ++j;
    } else {
      r.terms.push_back({x.terms[i].blade, a * x.terms[i].value + b * y.terms[j].value});
      ++i;
      ++j;
    }
  }
  r.bits = x.bits | y.bits;
  return r;
}

template <class MV>
MV plus_scalar(const MV& x, typename MV::scalar_type s) {
  MV scalar;
  scalar.terms = {{0u, s}};
  scalar.bits = 1;
  return linear_combination(typename MV::scalar_type(1), x, typename MV::scalar_type(1), scalar);
}

}  // namespace sparse

// A sparse algebra's products and linear maps, under the names the dense
// ones have (table_product.hpp), so that the functions on mv read the same.
template <class MV>
MV table_product(const bitwise_product& p, const MV& a, const MV& b) {
  return sparse::product(p, a, b);
}
template <class MV>
MV table_linear_map(const bitwise_linear_map& m, const MV& a) {
  return sparse::linear_map(m, a);
}

}  // namespace gaphys::ga
