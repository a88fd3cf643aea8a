"""Printing numbers as C++ literals of T: exact where C++ can be, always compilable."""

import unittest
from fractions import Fraction

from gaphys_gen.cpp import number


class Numbers(unittest.TestCase):
    def test_exact_literals(self):
        self.assertEqual(number(Fraction(-3)), "T(-3)")
        self.assertEqual(number(Fraction(1, 4)), "T(0.25)")
        self.assertEqual(number(Fraction(1, 3)), "(T(1) / T(3))")
        self.assertEqual(number(Fraction(2**53)), "T(9007199254740992)")

    def test_parts_over_53_bits_print_the_nearest_double(self):
        # No C++ integer literal holds 2^106; `T(81129638414606681695789005144064)` does not compile.
        self.assertEqual(number(Fraction(2**106)), "T(8.112963841460668e+31)")
        self.assertEqual(number(Fraction(-1, 3 * 2**60)), f"T({-1 / (3 * 2**60)!r})")


if __name__ == "__main__":
    unittest.main()
