"""Syntax: the lexer and parser accept the DSL and reject bad text with file:line:col."""

import unittest
from fractions import Fraction

from gaphys_gen.errors import SpecError
from gaphys_gen.parser import parse

from .support import E3_PRELUDE, SpecErrorAssertions


class SyntaxErrors(SpecErrorAssertions, unittest.TestCase):
    def test_missing_equals_in_type(self):
        self.assertSpecError(E3_PRELUDE + "type vector e1, e2\n", 4, 13, "expected '=', found 'e1'")

    def test_missing_equals_in_metric(self):
        self.assertSpecError("algebra t\nbasis e1\nmetric e1.e1 1\n", 3, 14, "expected '=', found '1'")

    def test_missing_dot_in_metric(self):
        self.assertSpecError("algebra t\nbasis e1\nmetric e1 e1 = 1\n", 3, 11, "expected '.'")

    def test_stray_character(self):
        self.assertSpecError(E3_PRELUDE + "type vector = e1, $e2\n", 4, 19, "unexpected character '$'")

    def test_stray_character_after_comment_line(self):
        # Comments are skipped; the column counts from the start of the line.
        self.assertSpecError("# header\nalgebra t;\n", 2, 10, "unexpected character ';'")

    def test_unexpected_end_of_line_in_type(self):
        self.assertSpecError(E3_PRELUDE + "type vector =\n", 4, 14, "expected a blade (`1` or `e1^e2`), found end of line")

    def test_unexpected_end_of_line_after_wedge(self):
        self.assertSpecError(E3_PRELUDE + "type bivector = e1^\n", 4, 20, "expected a basis vector name, found end of line")

    def test_unexpected_end_of_file_without_newline(self):
        # The last line has no '\n': the error is still placed just after its last character.
        self.assertSpecError(E3_PRELUDE + "function gp(", 4, 13, "expected an argument type, found end of line")

    def test_unexpected_end_of_file_after_a_continuing_comma(self):
        # The ',' continues the statement past the last '\n': the error is placed
        # just after it, on the last line, not on the empty line past the end.
        self.assertSpecError(E3_PRELUDE + "function gp(vector,\n", 4, 20, "expected an argument type")
        self.assertSpecError(E3_PRELUDE + "type vector = e1,\n\n# done\n", 4, 18, "expected a blade")

    def test_trailing_tokens(self):
        self.assertSpecError(E3_PRELUDE + "type vector = e1 e2\n", 4, 18, "expected end of line, found 'e2'")

    def test_unknown_statement(self):
        error = self.assertSpecError(E3_PRELUDE + "typo vector = e1\n", 4, 1, "unknown statement 'typo'")
        self.assertIn("function", error.message)  # lists what is expected

    def test_statement_starting_with_number(self):
        self.assertSpecError(E3_PRELUDE + "3 = e1\n", 4, 1, "expected a statement keyword, found '3'")

    def test_bad_scalar_type(self):
        self.assertSpecError(E3_PRELUDE + "scalar int\n", 4, 8, "scalar type must be float or double")

    def test_bad_representation(self):
        self.assertSpecError(E3_PRELUDE + "representation ipns\n", 4, 16, "representation must be direct or dual")

    def test_division_by_zero(self):
        self.assertSpecError("algebra t\nbasis e1\nmetric e1.e1 = 1/0\n", 3, 18, "division by zero")

    def test_number_out_of_range(self):
        # Numerators and denominators stay within 2^53, where double is exact.
        self.assertSpecError("algebra t\nbasis e1\nmetric e1.e1 = 9007199254740993\n", 3, 16, "out of range")
        self.assertSpecError("algebra t\nbasis e1\nmetric e1.e1 = 1e-9/9007199254740992\n", 3, 16,
                             "number 1e-9/9007199254740992 is out of range")

    def test_huge_exponent_is_refused_before_it_is_computed(self):
        self.assertSpecError("algebra t\nbasis e1\nmetric e1.e1 = 1e999999999\n", 3, 16, "out of range")

    def test_digits_are_ascii(self):
        self.assertSpecError("algebra t\nbasis e1\nmetric e1.e1 = \u0663\n", 3, 16, "unexpected character")

    def test_unclosed_parenthesis_reports_next_token(self):
        # Inside ( ) newlines continue the statement, so the error lands on the next line.
        self.assertSpecError(
            E3_PRELUDE + "type v = e1\nfunction gp(v, v\nfunction op(v, v)\n", 6, 1, "expected ')', found 'function'"
        )


class SyntaxTree(unittest.TestCase):
    def test_statements_and_locations(self):
        text = "algebra t\nbasis no  e1 ni\nmetric no.ni = -1, e1.e1 = 1/2\n"
        tree = parse(text, "x.ga")
        self.assertEqual([s.keyword for s in tree.statements], ["algebra", "basis", "metric"])
        basis = tree.statements[1]
        self.assertEqual(basis.names, ("no", "e1", "ni"))
        self.assertEqual([(l.line, l.column) for l in basis.name_locations], [(2, 7), (2, 11), (2, 14)])
        entries = tree.statements[2].entries
        self.assertEqual([(e.left, e.right, e.value) for e in entries], [("no", "ni", -1), ("e1", "e1", Fraction(1, 2))])
        self.assertEqual((entries[1].location.line, entries[1].location.column), (3, 20))

    def test_comma_continues_statement_on_next_line(self):
        text = "algebra t\nbasis e1 e2\ntype v = e1,\n         e2 # comment\n"
        tree = parse(text, "x.ga")
        coordinates = tree.statements[2].coordinates
        self.assertEqual([c.blade.factors for c in coordinates], [("e1",), ("e2",)])
        self.assertEqual((coordinates[1].blade.location.line, coordinates[1].blade.location.column), (4, 10))

    def test_parentheses_continue_statement(self):
        tree = parse("function gp(a,\n  b\n)\n", "x.ga")
        self.assertEqual(tree.statements[0].arguments, ("a", "b"))

    def test_type_constants_and_scalar_blade(self):
        tree = parse("type p = no = 1, e1, 1, ni = -3/4\n", "x.ga")
        coordinates = tree.statements[0].coordinates
        self.assertEqual([c.blade.factors for c in coordinates], [("no",), ("e1",), (), ("ni",)])
        self.assertEqual([c.constant for c in coordinates], [1, None, None, Fraction(-3, 4)])

    def test_numbers_decimal_and_exponent(self):
        tree = parse("metric a.a = 2.5, b.b = 1e-2, c.c = -0.25\n", "x.ga")
        self.assertEqual([e.value for e in tree.statements[0].entries], [Fraction(5, 2), Fraction(1, 100), Fraction(-1, 4)])

    def test_constant_terms(self):
        tree = parse("constant c = -e1 + 2*e1^e2 - 0.5*ni\n", "x.ga")
        terms = tree.statements[0].terms
        expected = [(-1, ("e1",)), (2, ("e1", "e2")), (Fraction(-1, 2), ("ni",))]
        self.assertEqual([(t.coefficient, t.blade.factors) for t in terms], expected)

    def test_constant_rational_coefficient(self):
        # Numbers elsewhere accept `a/b`; a constant's coefficient should too (`1/2*ni`).
        tree = parse("constant h = 1/2*ni\n", "x.ga")
        terms = tree.statements[0].terms
        self.assertEqual([(t.coefficient, t.blade.factors) for t in terms], [(Fraction(1, 2), ("ni",))])

    def test_constant_bare_numbers_are_scalar_multiples(self):
        tree = parse("constant h = 2 + e1 - 3/4\n", "x.ga")
        terms = tree.statements[0].terms
        self.assertEqual([(t.coefficient, t.blade.factors) for t in terms],
                         [(2, ()), (1, ("e1",)), (Fraction(-3, 4), ())])

    def test_crlf_line_endings(self):
        tree = parse("algebra t\r\nbasis e1 e2\r\n", "x.ga")
        self.assertEqual(tree.statements[1].names, ("e1", "e2"))

    def test_error_display_of_crlf_file_has_no_carriage_return(self):
        with self.assertRaises(SpecError) as caught:
            parse("algebra t\r\nbasis e1 $\r\n", "x.ga")
        self.assertNotIn("\r", str(caught.exception))


if __name__ == "__main__":
    unittest.main()
