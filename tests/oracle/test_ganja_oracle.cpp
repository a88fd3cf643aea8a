// Compares the generated library on `mv` with results computed by ganja.js
// (an independent GA implementation), read from a case file written by
// ganja_oracle.mjs. Built once per algebra and variant; the algebra is chosen
// by GAPHYS_ORACLE_ALGEBRA (its name and namespace, e.g. pga3d) and
// GAPHYS_ORACLE_HEADER (e.g. "pga3d/pga3d.hpp").
//
// Usage: test_ganja_oracle_<alg>_<variant> [gtest flags] CASE_FILE
//        (or set GAPHYS_ORACLE_CASES=CASE_FILE)

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "case_file.hpp"

#if !defined(GAPHYS_ORACLE_ALGEBRA) || !defined(GAPHYS_ORACLE_HEADER)
#error "define GAPHYS_ORACLE_ALGEBRA (e.g. pga3d) and GAPHYS_ORACLE_HEADER"
#endif
#include GAPHYS_ORACLE_HEADER
namespace alg = GAPHYS_ORACLE_ALGEBRA;
#define GAPHYS_ORACLE_STRING2(x) #x
#define GAPHYS_ORACLE_STRING(x) GAPHYS_ORACLE_STRING2(x)
static const char* const kAlgebra = GAPHYS_ORACLE_STRING(GAPHYS_ORACLE_ALGEBRA);

namespace {

using gaphys_oracle::CaseFile;
using gaphys_oracle::OracleCase;

// The library counts blades with int; containers here use size_t.
constexpr std::size_t kBladeCount = static_cast<std::size_t>(alg::blade_count);

std::string g_case_path;  // from argv, else GAPHYS_ORACLE_CASES

// Loads the case file once; on failure every test reports the reason.
struct Loaded {
  CaseFile file;
  std::string error;
};

const Loaded& loaded() {
  static const Loaded result = [] {
    Loaded l;
    std::string path = g_case_path;
    if (path.empty()) {
      const char* env = std::getenv("GAPHYS_ORACLE_CASES");
      path = env ? env : "";
    }
    if (path.empty()) {
      l.error = "no case file: pass its path as an argument or set GAPHYS_ORACLE_CASES";
      return l;
    }
    try {
      l.file = gaphys_oracle::read_case_file(path);
    } catch (const std::exception& e) {
      l.error = e.what();
    }
    return l;
  }();
  return result;
}

// Relative tolerance: float rounding of a result grows with its largest
// coefficient, not with each coefficient (small ones come from cancellation),
// so |got - want| <= tol * max(1, max_j |want_j|).
template <typename T>
constexpr double kTolerance = 0;
template <>
constexpr double kTolerance<float> = 1e-5;
template <>
constexpr double kTolerance<double> = 1e-12;

// Through basis blades, which both the dense and the sparse mv (algebras of
// more than 5 dimensions) build by canonical index.
template <typename T>
alg::basic_mv<T> to_mv(const std::vector<double>& xs) {
  alg::basic_mv<T> m;
  for (std::size_t i = 0; i < kBladeCount; ++i)
    if (xs.at(i) != 0)
      m = m + alg::basic_mv<T>::basis_blade(static_cast<int>(i), static_cast<T>(xs[i]));
  return m;
}

std::string blade_name(std::size_t i) { return alg::mv::blade_name(static_cast<int>(i)); }

template <typename T>
alg::basic_mv<T> input(const OracleCase& c, const char* key) {
  return to_mv<T>(c.at(key));
}

template <typename T>
std::vector<double> coefficients(const alg::basic_mv<T>& m) {
  std::vector<double> xs(kBladeCount);
  for (std::size_t i = 0; i < xs.size(); ++i) xs[i] = static_cast<double>(m[static_cast<int>(i)]);
  return xs;
}

// Collects mismatches over all cases and reports the first few, and the
// largest relative error seen (|diff| / scale, compared against tol).
class Mismatches {
 public:
  void compare(const OracleCase& c, const std::string& op, const std::vector<double>& got,
               const std::vector<double>& want, double tol) {
    double scale = 1;
    for (double w : want) scale = std::max(scale, std::abs(w));
    for (std::size_t i = 0; i < want.size(); ++i) {
      const double err = std::abs(got.at(i) - want[i]);
      if (!(err / scale <= max_relative_)) max_relative_ = err / scale;  // NaN sticks
      if (err <= tol * scale) continue;                                  // also rejects NaN
      if (++count_ <= kShown) {
        std::ostringstream s;
        s.precision(17);
        s << c.label() << " " << op << " [" << (want.size() == 1 ? "scalar" : blade_name(i))
          << "]: got " << got[i] << ", ganja " << want[i] << ", |diff| " << err << " > "
          << tol * scale;
        report_ += s.str() + "\n";
      }
    }
  }
  void expect_none() const { EXPECT_EQ(count_, 0) << report_ << (count_ > kShown ? "...\n" : ""); }
  double max_relative() const { return max_relative_; }

 private:
  static constexpr int kShown = 10;
  int count_ = 0;
  double max_relative_ = 0;
  std::string report_;
};

template <typename T>
class GanjaOracle : public ::testing::Test {
 protected:
  void SetUp() override {
    const Loaded& l = loaded();
    ASSERT_TRUE(l.error.empty()) << l.error;
    ASSERT_EQ(l.file.algebra, kAlgebra) << "case file is for another algebra";
    ASSERT_FALSE(l.file.cases.empty());
  }

  // Runs fn(case) -> coefficients for every case and checks them against `op`.
  template <typename Fn>
  void check(const std::string& op, Fn fn) {
    Mismatches m;
    for (const OracleCase& c : loaded().file.cases)
      m.compare(c, op, fn(c), c.at(op), kTolerance<T>);
    m.expect_none();
    ::testing::Test::RecordProperty("max_relative_error", std::to_string(m.max_relative()));
    std::printf("%s %s: max |ours - ganja| / scale = %.3g (tolerance %.0e)\n", kAlgebra, op.c_str(),
                m.max_relative(), kTolerance<T>);
  }
};

// Names the suites GanjaOracle/0, /1 like gtest's default (which ctest's test
// discovery turns into Dual<float>); spelled out because omitting the argument
// trips -pedantic in TYPED_TEST_SUITE.
struct ScalarNames {
  template <typename T>
  static std::string GetName(int index) {
    return std::to_string(index);
  }
};

using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(GanjaOracle, Scalars, ScalarNames);

TYPED_TEST(GanjaOracle, BladeOrderMatches) {
  const auto& names = loaded().file.blade_names;
  ASSERT_EQ(names.size(), kBladeCount);
  for (std::size_t i = 1; i < names.size(); ++i)
    EXPECT_EQ(blade_name(i), names[i]) << "index " << i;
}

TYPED_TEST(GanjaOracle, GeometricProduct) {
  using T = TypeParam;
  this->check("gp", [](const OracleCase& c) {
    return coefficients(alg::gp(input<T>(c, "a"), input<T>(c, "b")));
  });
}

TYPED_TEST(GanjaOracle, OuterProduct) {
  using T = TypeParam;
  this->check("op", [](const OracleCase& c) {
    return coefficients(alg::op(input<T>(c, "a"), input<T>(c, "b")));
  });
}

TYPED_TEST(GanjaOracle, LeftContraction) {
  using T = TypeParam;
  this->check("lc", [](const OracleCase& c) {
    return coefficients(alg::lc(input<T>(c, "a"), input<T>(c, "b")));
  });
}

TYPED_TEST(GanjaOracle, ScalarProduct) {
  using T = TypeParam;
  this->check("scp", [](const OracleCase& c) {
    const T s = alg::scp(input<T>(c, "a"), input<T>(c, "b"));
    return std::vector<double>{static_cast<double>(s)};
  });
}

TYPED_TEST(GanjaOracle, Reverse) {
  using T = TypeParam;
  this->check("reverse",
              [](const OracleCase& c) { return coefficients(alg::reverse(input<T>(c, "a"))); });
}

TYPED_TEST(GanjaOracle, Dual) {
  using T = TypeParam;
  this->check("dual",
              [](const OracleCase& c) { return coefficients(alg::dual(input<T>(c, "a"))); });
}

TYPED_TEST(GanjaOracle, Undual) {
  using T = TypeParam;
  this->check("undual",
              [](const OracleCase& c) { return coefficients(alg::undual(input<T>(c, "a"))); });
}

TYPED_TEST(GanjaOracle, Meet) {
  using T = TypeParam;
  this->check("meet", [](const OracleCase& c) {
    return coefficients(alg::meet(input<T>(c, "a"), input<T>(c, "b")));
  });
}

TYPED_TEST(GanjaOracle, Join) {
  using T = TypeParam;
  this->check("join", [](const OracleCase& c) {
    return coefficients(alg::join(input<T>(c, "a"), input<T>(c, "b")));
  });
}

TYPED_TEST(GanjaOracle, ApplyVersor) {
  using T = TypeParam;
  this->check("apply", [](const OracleCase& c) {
    return coefficients(alg::apply(input<T>(c, "v"), input<T>(c, "a")));
  });
}

// The documented `mv` invariant: a clear bit means an exactly zero
// coefficient (dense), or a grade without terms (sparse).
template <typename MV>
void expect_bits_cover(const MV& r, const std::string& label) {
  if constexpr (gaphys::ga::is_sparse_v<MV>) {
    for (const auto& t : r.terms) {
      int grade = 0;
      for (std::uint32_t b = t.blade; b != 0; b &= b - 1) ++grade;
      ASSERT_TRUE((r.bits >> grade) & 1u) << label << " blade bitmap " << t.blade;
    }
  } else {
    for (std::size_t i = 0; i < kBladeCount; ++i) {
      if (!((r.bits >> i) & 1u)) {
        ASSERT_EQ(r.c[i], 0) << label << " blade " << blade_name(i);
      }
    }
  }
}

TYPED_TEST(GanjaOracle, ResultBitsInvariant) {
  using T = TypeParam;
  for (const OracleCase& c : loaded().file.cases) {
    const auto a = input<T>(c, "a");
    const auto b = input<T>(c, "b");
    const alg::basic_mv<T> results[] = {
        alg::gp(a, b),   alg::op(a, b),   alg::lc(a, b),
        alg::reverse(a), alg::dual(a),    alg::undual(a),
        alg::meet(a, b), alg::join(a, b), alg::apply(input<T>(c, "v"), a)};
    for (const auto& r : results) expect_bits_cover(r, c.label());
  }
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);  // removes the gtest flags
  if (argc > 2) {
    std::fprintf(stderr, "usage: %s [gtest flags] [CASE_FILE]\n", argv[0]);
    return 2;
  }
  if (argc == 2) g_case_path = argv[1];
  return RUN_ALL_TESTS();
}
