"""Exact product tables of basis blades, checked against independent truth.

Truth here is: literal textbook products, a second implementation for
orthogonal bases (support.orthogonal_blade_product, which sorts factor words
by hand), a change of basis from an orthogonal basis to the conformal null
basis, closed-form conformal geometry, and algebraic identities.
"""

import random
import unittest
from fractions import Fraction

from gaphys_gen.blades import PRODUCTS, BladeAlgebra, conjugate_sign, involute_sign, reverse_sign, wedge_blades

from .support import (
    CONFORMAL_MODEL,
    add_into,
    bilinear,
    bitmap_of,
    indices_of,
    orthogonal_blade_product,
    random_fraction,
    random_multivector,
)

F = Fraction


def diagonal_metric(*values):
    n = len(values)
    return tuple(tuple(F(values[i]) if i == j else F(0) for j in range(n)) for i in range(n))


# Conformal null basis: bit 0 = no, bits 1..3 = e1..e3, bit 4 = ni.
NO, E1, E2, E3, NI = 1, 2, 4, 8, 16
CONFORMAL = tuple(
    tuple(F(v) for v in row)
    for row in ((0, 0, 0, 0, -1), (0, 1, 0, 0, 0), (0, 0, 1, 0, 0), (0, 0, 0, 1, 0), (-1, 0, 0, 0, 0))
)
EUCLIDEAN3 = diagonal_metric(1, 1, 1)


def mv_product(algebra: BladeAlgebra, kind: str, a: dict, b: dict) -> dict:
    """The generator's table for `kind`, extended bilinearly to multivectors {bitmap: Fraction}."""
    return bilinear(lambda x, y: algebra.product(kind, x, y), a, b)


def blade_reverse(a: dict) -> dict:
    # Reversing k factors takes k(k-1)/2 swaps.
    return {b: v * (-1) ** (bin(b).count("1") * (bin(b).count("1") - 1) // 2) for b, v in a.items()}


def blade_involute(a: dict) -> dict:
    return {b: v * (-1) ** bin(b).count("1") for b, v in a.items()}


def grade_part(a: dict, k: int) -> dict:
    return {b: v for b, v in a.items() if bin(b).count("1") == k}


def add(*terms) -> dict:
    result: dict = {}
    for term in terms:
        add_into(result, term)
    return result


def scaled(a: dict, s) -> dict:
    return {b: v * s for b, v in a.items() if v * s}


class EuclideanTable(unittest.TestCase):
    def setUp(self):
        self.e3 = BladeAlgebra(EUCLIDEAN3)

    def test_literal_products(self):
        e1, e2, e3, e12, e13, e23, e123 = 1, 2, 4, 3, 5, 6, 7
        gp = self.e3.gp
        self.assertEqual(gp(e1, e1), {0: 1})
        self.assertEqual(gp(e1, e2), {e12: 1})
        self.assertEqual(gp(e2, e1), {e12: -1})
        self.assertEqual(gp(e12, e12), {0: -1})
        self.assertEqual(gp(e123, e123), {0: -1})
        self.assertEqual(gp(e12, e23), {e13: 1})
        self.assertEqual(gp(e23, e12), {e13: -1})
        self.assertEqual(gp(e1, e23), {e123: 1})
        self.assertEqual(gp(e2, e13), {e123: -1})
        self.assertEqual(gp(e12, e2), {e1: 1})
        self.assertEqual(gp(e2, e12), {e1: -1})
        self.assertEqual(gp(e123, e1), {e23: 1})
        self.assertEqual(gp(0, e123), {e123: 1})
        self.assertEqual(self.e3.op(e1, e1), {})
        self.assertEqual(self.e3.op(e2, e1), {e12: -1})
        self.assertEqual(self.e3.lc(e1, e12), {e2: 1})
        self.assertEqual(self.e3.lc(e2, e12), {e1: -1})
        self.assertEqual(self.e3.lc(e12, e1), {})
        self.assertEqual(self.e3.rc(e12, e2), {e1: 1})
        self.assertEqual(self.e3.rc(e1, e12), {})
        self.assertEqual(self.e3.scp(e12, e12), {0: -1})
        self.assertEqual(self.e3.scp(e1, e2), {})
        self.assertEqual(self.e3.lc(0, e12), {e12: 1})

    def check_full_tables(self, diagonal):
        algebra = BladeAlgebra(diagonal_metric(*diagonal))
        n = len(diagonal)
        for kind in PRODUCTS:
            for a in range(1 << n):
                for b in range(1 << n):
                    expected = orthogonal_blade_product(kind, indices_of(a), indices_of(b), [F(v) for v in diagonal])
                    expected = {bitmap_of(k): v for k, v in expected.items()}
                    self.assertEqual(algebra.product(kind, a, b), expected, (kind, diagonal, a, b))

    def test_full_cl30_tables(self):
        self.check_full_tables((1, 1, 1))

    def test_full_tables_mixed_signature_and_degenerate(self):
        # Cl(1,3)-like with a non-unit square, and a degenerate (PGA-like) direction.
        self.check_full_tables((1, -1, -1, -1))
        self.check_full_tables((0, 1, 1, 1))
        self.check_full_tables((2, -3, F(1, 2), 1, -1))


class SignHelpers(unittest.TestCase):
    def test_wedge_sign_matches_word_sorting(self):
        for a in range(32):
            for b in range(32):
                expected = orthogonal_blade_product("op", indices_of(a), indices_of(b), [1] * 5)
                self.assertEqual(wedge_blades(a, b), {bitmap_of(k): v for k, v in expected.items()})

    def test_reverse_involute_conjugate(self):
        for bitmap in range(32):
            k = bin(bitmap).count("1")
            # Reversing a blade's word and sorting it back gives the reverse sign.
            word_sign = _sorting_sign(list(reversed(indices_of(bitmap))))
            self.assertEqual(reverse_sign(bitmap), word_sign)
            self.assertEqual(involute_sign(bitmap), (-1) ** k)
            self.assertEqual(conjugate_sign(bitmap), word_sign * (-1) ** k)


def _sorting_sign(word: list[int]) -> int:
    """Parity of the permutation that sorts a word of distinct indices (count inversions)."""
    inversions = sum(1 for i in range(len(word)) for j in range(i + 1, len(word)) if word[i] > word[j])
    return -1 if inversions % 2 else 1


class ConformalTable(unittest.TestCase):
    def setUp(self):
        self.c3 = BladeAlgebra(CONFORMAL)

    def test_null_basis_metric(self):
        self.assertEqual(self.c3.scp(NO, NI), {0: -1})
        self.assertEqual(self.c3.scp(NI, NO), {0: -1})
        self.assertEqual(self.c3.gp(NO, NO), {})
        self.assertEqual(self.c3.gp(NI, NI), {})
        self.assertEqual(self.c3.gp(E1, E1), {0: 1})

    def test_no_ni_products(self):
        self.assertEqual(self.c3.gp(NO, NI), {0: -1, NO | NI: 1})
        self.assertEqual(self.c3.gp(NI, NO), {0: -1, NO | NI: -1})
        self.assertEqual(self.c3.op(NI, NO), {NO | NI: -1})
        self.assertEqual(self.c3.lc(NO, NI), {0: -1})

    def test_flat_point_basis(self):
        # E = no^ni squares to +1 (it is the Minkowski plane's unit pseudoscalar).
        self.assertEqual(self.c3.gp(NO | NI, NO | NI), {0: 1})
        # no^ni = no ni + 1, and ni no ni = (2 ni.no - no ni) ni = -2 ni (ni^2 = 0), so
        # ni (no^ni) = -2 ni + ni = -ni and (no^ni) ni = ni; likewise no (no^ni) = no, (no^ni) no = -no.
        self.assertEqual(self.c3.gp(NI, NO | NI), {NI: -1})
        self.assertEqual(self.c3.gp(NO | NI, NI), {NI: 1})
        self.assertEqual(self.c3.gp(NO, NO | NI), {NO: 1})
        self.assertEqual(self.c3.gp(NO | NI, NO), {NO: -1})

    def test_pseudoscalar_squares_to_minus_one(self):
        self.assertEqual(self.c3.gp(31, 31), {0: -1})
        self.assertEqual(self.c3.gp(E1 | E2 | E3, E1 | E2 | E3), {0: -1})

    def test_euclidean_pseudoscalar_commutes_with_everything(self):
        # I5 is central in odd dimension: I5 x = x I5 for every basis blade x.
        for x in range(32):
            self.assertEqual(self.c3.gp(31, x), self.c3.gp(x, 31), x)


class ConformalByChangeOfBasis(unittest.TestCase):
    """The non-diagonal recursion must agree with the trivial diagonal one after a change of basis."""

    def test_maps_are_inverse(self):
        for bitmap in range(32):
            self.assertEqual(CONFORMAL_MODEL.from_orthogonal(CONFORMAL_MODEL.to_orthogonal({bitmap: F(1)})), {bitmap: 1})

    def test_change_of_basis_preserves_the_metric(self):
        # The images of no, e1, e2, e3, ni have the conformal inner products.
        for i in range(5):
            for j in range(5):
                dot = CONFORMAL_MODEL.product("scp", {1 << i: F(1)}, {1 << j: F(1)})
                self.assertEqual(dot.get(0, 0), CONFORMAL[i][j], (i, j))

    def test_all_products_agree(self):
        c3 = BladeAlgebra(CONFORMAL)
        for kind in PRODUCTS:
            for a in range(32):
                for b in range(32):
                    expected = CONFORMAL_MODEL.product(kind, {a: F(1)}, {b: F(1)})
                    self.assertEqual(c3.product(kind, a, b), expected, (kind, a, b))


def _point(x) -> dict:
    """Normalized conformal point no + x + x^2/2 ni."""
    return {b: v for b, v in {NO: F(1), E1: x[0], E2: x[1], E3: x[2], NI: sum(c * c for c in x) / 2}.items() if v}


class ConformalGeometry(unittest.TestCase):
    def setUp(self):
        self.c3 = BladeAlgebra(CONFORMAL)
        self.rng = random.Random(1234)

    def random_vector(self):
        return [random_fraction(self.rng) for _ in range(3)]

    def test_points_are_null_and_normalized(self):
        for _ in range(20):
            p = _point(self.random_vector())
            self.assertEqual(mv_product(self.c3, "gp", p, p), {})
            self.assertEqual(mv_product(self.c3, "scp", p, {NI: F(1)}), {0: -1})

    def test_point_distance(self):
        for _ in range(20):
            x, y = self.random_vector(), self.random_vector()
            d2 = sum((a - b) ** 2 for a, b in zip(x, y))
            expected = {0: -d2 / 2} if d2 else {}
            p, q = _point(x), _point(y)
            self.assertEqual(mv_product(self.c3, "scp", p, q), expected)
            self.assertEqual(mv_product(self.c3, "lc", p, q), expected)
            # p q = p.q + p^q for vectors.
            self.assertEqual(mv_product(self.c3, "gp", p, q), add(expected, mv_product(self.c3, "op", p, q)))

    def test_point_inside_dual_sphere(self):
        # sigma = c - r^2/2 ni; p . sigma = (r^2 - |x - c|^2) / 2: positive inside, zero on, negative outside.
        for _ in range(20):
            x, c, r = self.random_vector(), self.random_vector(), random_fraction(self.rng)
            sigma = add(_point(c), {NI: -r * r / 2})
            expected = (r * r - sum((a - b) ** 2 for a, b in zip(x, c))) / 2
            self.assertEqual(mv_product(self.c3, "scp", _point(x), sigma), {0: expected} if expected else {})


class Identities(unittest.TestCase):
    """Identities that hold for any symmetric bilinear form, on random rational multivectors."""

    METRICS = {
        "e3ga": EUCLIDEAN3,
        "c3ga": CONFORMAL,
        # A dense, indefinite, non-diagonal form.
        "dense4": tuple(
            tuple(F(v) for v in row)
            for row in ((2, 1, 0, -1), (1, 0, 3, 1), (0, 3, -1, F(1, 2)), (-1, 1, F(1, 2), 1))
        ),
        # Degenerate: a null direction orthogonal to everything.
        "degenerate3": tuple(tuple(F(v) for v in row) for row in ((0, 0, 0), (0, 1, 2), (0, 2, -1))),
    }

    def setUp(self):
        self.rng = random.Random(42)

    def cases(self, trials=4):
        for name, metric in self.METRICS.items():
            algebra = BladeAlgebra(metric)
            for _ in range(trials):
                yield name, metric, algebra

    def random(self, metric, grades=None):
        return random_multivector(self.rng, len(metric), grades)

    def test_associativity(self):
        for name, metric, algebra in self.cases(3):
            a, b, c = self.random(metric), self.random(metric), self.random(metric)
            for kind in ("gp", "op"):
                left = mv_product(algebra, kind, mv_product(algebra, kind, a, b), c)
                right = mv_product(algebra, kind, a, mv_product(algebra, kind, b, c))
                self.assertEqual(left, right, (name, kind))

    def test_vector_products(self):
        for name, metric, algebra in self.cases():
            n = len(metric)
            a, b = self.random(metric, {1}), self.random(metric, {1})
            dot = sum(a.get(1 << i, 0) * b.get(1 << j, 0) * metric[i][j] for i in range(n) for j in range(n))
            dot_mv = {0: dot} if dot else {}
            self.assertEqual(mv_product(algebra, "lc", a, b), dot_mv, name)
            self.assertEqual(mv_product(algebra, "rc", a, b), dot_mv, name)
            self.assertEqual(mv_product(algebra, "scp", a, b), dot_mv, name)
            self.assertEqual(mv_product(algebra, "gp", a, b), add(dot_mv, mv_product(algebra, "op", a, b)), name)
            # ab + ba = 2 a.b
            self.assertEqual(add(mv_product(algebra, "gp", a, b), mv_product(algebra, "gp", b, a)), scaled(dot_mv, 2), name)
            self.assertEqual(mv_product(algebra, "op", a, a), {}, name)

    def test_vector_times_multivector(self):
        for name, metric, algebra in self.cases():
            x, m = self.random(metric, {1}), self.random(metric)
            x_m = add(mv_product(algebra, "lc", x, m), mv_product(algebra, "op", x, m))
            m_x = add(mv_product(algebra, "rc", m, x), mv_product(algebra, "op", m, x))
            self.assertEqual(mv_product(algebra, "gp", x, m), x_m, name)
            self.assertEqual(mv_product(algebra, "gp", m, x), m_x, name)

    def test_contraction_is_a_derivation(self):
        # x _| (A ^ B) = (x _| A) ^ B + involute(A) ^ (x _| B)
        for name, metric, algebra in self.cases():
            x, a, b = self.random(metric, {1}), self.random(metric), self.random(metric)
            left = mv_product(algebra, "lc", x, mv_product(algebra, "op", a, b))
            right = add(
                mv_product(algebra, "op", mv_product(algebra, "lc", x, a), b),
                mv_product(algebra, "op", blade_involute(a), mv_product(algebra, "lc", x, b)),
            )
            self.assertEqual(left, right, name)

    def test_outer_then_contract(self):
        # (A ^ B) _| C = A _| (B _| C) and C |_ (B ^ A) = (C |_ B) |_ A
        for name, metric, algebra in self.cases():
            a, b, c = self.random(metric), self.random(metric), self.random(metric)
            self.assertEqual(
                mv_product(algebra, "lc", mv_product(algebra, "op", a, b), c),
                mv_product(algebra, "lc", a, mv_product(algebra, "lc", b, c)),
                name,
            )
            self.assertEqual(
                mv_product(algebra, "rc", c, mv_product(algebra, "op", b, a)),
                mv_product(algebra, "rc", mv_product(algebra, "rc", c, b), a),
                name,
            )

    def test_contraction_reverse_duality_and_scalar_product(self):
        for name, metric, algebra in self.cases():
            a, b = self.random(metric), self.random(metric)
            # A |_ B = ~(~B _| ~A)
            swapped = mv_product(algebra, "lc", blade_reverse(b), blade_reverse(a))
            self.assertEqual(mv_product(algebra, "rc", a, b), blade_reverse(swapped), name)
            scp = mv_product(algebra, "scp", a, b)
            self.assertEqual(scp, grade_part(mv_product(algebra, "gp", a, b), 0), name)
            self.assertEqual(scp, mv_product(algebra, "scp", b, a), name)
            self.assertEqual(scp, grade_part(mv_product(algebra, "lc", a, b), 0), name)
            self.assertEqual(scp, grade_part(mv_product(algebra, "rc", a, b), 0), name)

    def test_homogeneous_contraction_grades(self):
        for name, metric, algebra in self.cases(2):
            n = len(metric)
            for ga in range(n + 1):
                for gb in range(n + 1):
                    a, b = self.random(metric, {ga}), self.random(metric, {gb})
                    lc = mv_product(algebra, "lc", a, b)
                    self.assertEqual(lc, grade_part(mv_product(algebra, "gp", a, b), gb - ga) if gb >= ga else {}, name)

    def test_reverse_and_involution_of_products(self):
        for name, metric, algebra in self.cases():
            a, b = self.random(metric), self.random(metric)
            for kind in ("gp", "op"):
                ab = mv_product(algebra, kind, a, b)
                reversed_product = mv_product(algebra, kind, blade_reverse(b), blade_reverse(a))
                involuted_product = mv_product(algebra, kind, blade_involute(a), blade_involute(b))
                self.assertEqual(blade_reverse(ab), reversed_product, (name, kind))
                self.assertEqual(blade_involute(ab), involuted_product, (name, kind))

    def test_scalar_is_identity(self):
        for name, metric, algebra in self.cases(1):
            for kind in ("gp", "op", "lc"):
                for x in range(1 << len(metric)):
                    self.assertEqual(algebra.product(kind, 0, x), {x: 1}, (name, kind))
            for x in range(1 << len(metric)):
                self.assertEqual(algebra.product("rc", x, 0), {x: 1}, name)

    def test_bitwise_products_of_the_sparse_runtime(self):
        # Algebras of more than 5 basis vectors multiply in an orthogonal basis,
        # one blade per pair of terms (gaphys/ga/sparse_mv.hpp); the same
        # algorithm, exact, against Chevalley's recursion in the spec's basis.
        from gaphys_gen.orthogonal import bitwise_product

        for name, metric, algebra in self.cases(3):
            a, b = self.random(metric), self.random(metric)
            for kind in PRODUCTS:
                self.assertEqual(bitwise_product(metric, kind, a, b), mv_product(algebra, kind, a, b), (name, kind))


if __name__ == "__main__":
    unittest.main()
