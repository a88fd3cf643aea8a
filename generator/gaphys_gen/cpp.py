"""Printing exact polynomials and numbers as C++ expressions (in scalar type T)."""

from fractions import Fraction

from .expand import cost
from .symbolic import Poly


def number(value: Fraction) -> str:
    """An exact C++ literal of type T for a rational, or the nearest double when its
    numerator or denominator needs over 53 bits (products of spec numbers can): no
    C++ integer literal holds 2^64, and T cannot be exact there anyway."""
    if abs(value.numerator) > 2**53 or value.denominator > 2**53:
        return f"T({float(value)!r})"
    if value.denominator == 1:
        return f"T({value.numerator})"
    denominator = value.denominator
    if denominator & (denominator - 1) == 0:  # a power of two: exact in binary floating point
        return f"T({float(value)!r})"
    return f"(T({value.numerator}) / T({denominator}))"


def variable(name: str) -> str:
    """a3 -> a.c[3] (argument coordinates); locals (s, c, k, f, t0, ...) stay as they are."""
    if name[0] in "ab" and name[1:].isdigit():
        return f"{name[0]}.c[{name[1:]}]"
    return name


def expression(poly: Poly) -> str:
    if poly.is_zero():
        return "T(0)"
    parts = []
    for index, (monomial, coefficient) in enumerate(poly.sorted_terms()):
        factors = [variable(v) for v in monomial]
        magnitude = abs(coefficient)
        if magnitude != 1 or not factors:
            factors.insert(0, number(magnitude))
        term = " * ".join(factors)
        if index == 0:
            parts.append(("-" if coefficient < 0 else "") + term)
        else:
            parts.append(("- " if coefficient < 0 else "+ ") + term)
    return " ".join(parts)


def count(polys: list[Poly]) -> tuple[int, int]:
    muls = adds = 0
    for poly in polys:
        m, a = cost(poly)
        muls += m
        adds += a
    return muls, adds
