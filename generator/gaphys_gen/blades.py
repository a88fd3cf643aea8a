"""Exact products of basis blades under any symmetric bilinear form.

A basis blade is a bitmap over the spec's basis vectors (bit i = vector i);
the blade e_i ^ e_j ^ ... has its factors in ascending index order. A
multivector is a dict {bitmap: Fraction}. The metric need not be diagonal
(conformal: no.ni = -1), so the geometric product of two basis blades can be
a sum of several blades (no ni = -1 + no^ni). We compute it with Chevalley's
recursion, which needs no change of basis and stays exact:

    e_i X       = e_i _| X + e_i ^ X                   (vector times multivector)
    e_i _| (b1^...^bk) = sum_m (-1)^m (e_i . b_m) b1^..(no b_m)..^bk
    (e_i ^ A') B = e_i (A' B) - (e_i _| A') B          (e_i the lowest factor of A)

Contractions and the scalar product are grade selections of the geometric
product, which is valid for blades in any basis:
    A _| B = <A B>_{gB-gA},  A |_ B = <A B>_{gA-gB},  A * B = <A B>_0.
"""

from fractions import Fraction
from functools import lru_cache

Multivector = dict[int, Fraction]


def grade(bitmap: int) -> int:
    return bin(bitmap).count("1")


def reorder_sign(a: int, b: int) -> int:
    """Sign of moving the factors of blade b past those of blade a into ascending order."""
    a >>= 1
    swaps = 0
    while a:
        swaps += grade(a & b)
        a >>= 1
    return -1 if swaps & 1 else 1


def wedge_blades(a: int, b: int) -> Multivector:
    if a & b:
        return {}
    return {a | b: Fraction(reorder_sign(a, b))}


def _add_into(target: Multivector, source: Multivector, scale: Fraction) -> None:
    for blade, value in source.items():
        total = target.get(blade, Fraction(0)) + scale * value
        if total:
            target[blade] = total
        else:
            target.pop(blade, None)


class BladeAlgebra:
    """Product tables of one algebra: n basis vectors and their metric matrix (exact)."""

    def __init__(self, metric: tuple[tuple[Fraction, ...], ...]):
        self.metric = metric
        self.dimension = len(metric)
        self._gp = lru_cache(maxsize=None)(self._gp_uncached)

    # e_i _| basis blade, per the alternating sum above.
    def vector_lc(self, i: int, blade: int) -> Multivector:
        result: Multivector = {}
        position = 0
        for j in range(self.dimension):
            if blade >> j & 1:
                g = self.metric[i][j]
                if g:
                    sign = -1 if position & 1 else 1
                    _add_into(result, {blade & ~(1 << j): Fraction(sign)}, g)
                position += 1
        return result

    def vector_gp(self, i: int, x: Multivector) -> Multivector:
        result: Multivector = {}
        for blade, value in x.items():
            _add_into(result, self.vector_lc(i, blade), value)
            _add_into(result, wedge_blades(1 << i, blade), value)
        return result

    def _gp_uncached(self, a: int, b: int) -> tuple[tuple[int, Fraction], ...]:
        if a == 0:
            return ((b, Fraction(1)),)
        i = (a & -a).bit_length() - 1  # the lowest factor of a
        rest = a & ~(1 << i)
        result: Multivector = {}
        # e_i (A' B)
        _add_into(result, self.vector_gp(i, dict(self._gp(rest, b))), Fraction(1))
        # - (e_i _| A') B
        for blade, value in self.vector_lc(i, rest).items():
            _add_into(result, dict(self._gp(blade, b)), -value)
        return tuple(sorted(result.items()))

    def gp(self, a: int, b: int) -> Multivector:
        return dict(self._gp(a, b))

    def op(self, a: int, b: int) -> Multivector:
        return wedge_blades(a, b)

    def _grade_part(self, a: int, b: int, k: int) -> Multivector:
        if k < 0:
            return {}
        return {blade: v for blade, v in self._gp(a, b) if grade(blade) == k}

    def lc(self, a: int, b: int) -> Multivector:
        return self._grade_part(a, b, grade(b) - grade(a))

    def rc(self, a: int, b: int) -> Multivector:
        return self._grade_part(a, b, grade(a) - grade(b))

    def scp(self, a: int, b: int) -> Multivector:
        return self._grade_part(a, b, 0)

    def product(self, kind: str, a: int, b: int) -> Multivector:
        return getattr(self, kind)(a, b)


PRODUCTS = ("gp", "op", "lc", "rc", "scp")


def right_complement(bitmap: int, full: int) -> tuple[int, int]:
    """(complement, sign) with blade ^ (sign * complement) = the pseudoscalar
    `full` (all basis vectors in spec order): metric-free, so it exists in a
    degenerate metric too, where x I^-1 does not."""
    complement = full & ~bitmap
    return complement, reorder_sign(bitmap, complement)


def left_complement(bitmap: int, full: int) -> tuple[int, int]:
    """(complement, sign) with (sign * complement) ^ blade = `full`: the inverse
    of right_complement."""
    complement = full & ~bitmap
    return complement, reorder_sign(complement, bitmap)


def reverse_sign(bitmap: int) -> int:
    k = grade(bitmap)
    return -1 if (k * (k - 1) // 2) & 1 else 1


def involute_sign(bitmap: int) -> int:
    return -1 if grade(bitmap) & 1 else 1


def conjugate_sign(bitmap: int) -> int:
    return reverse_sign(bitmap) * involute_sign(bitmap)
