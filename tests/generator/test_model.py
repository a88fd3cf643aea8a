"""Validation: every semantic error in a spec, and the shipped specs as documented."""

import itertools
import os
import re
import tempfile
import unittest
from fractions import Fraction

from gaphys_gen.errors import SpecError
from gaphys_gen.model import load

from .support import C3_PRELUDE, E3_PRELUDE, SpecErrorAssertions, load_text, spec_path


class BladeErrors(SpecErrorAssertions, unittest.TestCase):
    def test_unknown_basis_vector_in_type(self):
        error = self.assertSpecError(E3_PRELUDE + "type bivector = e1^e4\n", 4, 20, "unknown basis vector 'e4'")
        self.assertIn("basis: e1 e2 e3", error.message)

    def test_unknown_basis_vector_in_constant(self):
        self.assertSpecError(E3_PRELUDE + "constant c = e1 + 2*x\n", 4, 21, "unknown basis vector 'x'")

    def test_repeated_basis_vector_in_blade(self):
        self.assertSpecError(E3_PRELUDE + "type t = e1^e2^e1\n", 4, 16, "basis vector 'e1' repeated in blade")

    def test_same_blade_twice_in_type(self):
        # e2^e1 is the blade e1^e2 (with a sign): still a duplicate coordinate.
        self.assertSpecError(E3_PRELUDE + "type t = e1^e2, e3, e2^e1\n", 4, 21, "blade e1^e2 appears twice in type 't'")

    def test_type_with_only_constants(self):
        self.assertSpecError(E3_PRELUDE + "type t = e1 = 1, e2 = 0\n", 4, 6, "type 't' has no stored coordinate")


class MetricErrors(SpecErrorAssertions, unittest.TestCase):
    def test_asymmetric_metric_in_two_statements(self):
        text = C3_PRELUDE + "metric no.ni = -1\nmetric ni.no = 1\n"
        error = self.assertSpecError(text, 5, 8, "metric is not symmetric")
        self.assertIn("ni.no = 1", error.message)

    def test_asymmetric_metric_in_one_statement(self):
        self.assertSpecError(C3_PRELUDE + "metric no.ni = -1, ni.no = 1\n", 4, 20, "metric is not symmetric")

    def test_asymmetric_metric_names_both_entries_as_written(self):
        # Issue 16, defect 5: the second entry was printed in the order of the first.
        self.assertSpecError(E3_PRELUDE + "metric e1.e2 = 1, e2.e1 = 2\n", 4, 19,
                             "metric is not symmetric: e2.e1 = 2 but e1.e2 = 1")
        self.assertSpecError(C3_PRELUDE + "metric no.ni = -1\nmetric ni.no = 1\n", 5, 8,
                             "metric is not symmetric: ni.no = 1 but no.ni = -1")

    def test_symmetric_repetition_is_accepted(self):
        algebra = load_text(C3_PRELUDE + "metric no.ni = -1, ni.no = -1\n")
        self.assertEqual(algebra.metric[0][4], -1)
        self.assertEqual(algebra.metric[4][0], -1)

    def test_unknown_basis_vector_on_left(self):
        self.assertSpecError(E3_PRELUDE + "metric e4.e1 = 1\n", 4, 8, "unknown basis vector 'e4' in metric")

    def test_unknown_basis_vector_on_right(self):
        # The caret should be under the unknown name, not under the entry's first name.
        self.assertSpecError(E3_PRELUDE + "metric e1.e4 = 1\n", 4, 11, "unknown basis vector 'e4' in metric")


class DeclarationErrors(SpecErrorAssertions, unittest.TestCase):
    def test_duplicate_basis_vector(self):
        self.assertSpecError("algebra t\nbasis e1 e2 e1\n", 2, 13, "basis vector 'e1' declared twice")

    def test_too_many_basis_vectors(self):
        names = " ".join(f"v{i}" for i in range(17))
        self.assertSpecError(f"algebra t\nbasis {names}\n", 2, 61, "at most 16 basis vectors")

    def test_sixteen_basis_vectors_are_allowed(self):
        names = " ".join(f"v{i}" for i in range(16))
        algebra = load_text(f"algebra t\nbasis {names}\n")
        self.assertEqual(algebra.blade_count, 1 << 16)
        self.assertTrue(algebra.sparse)

    def test_five_basis_vectors_are_dense(self):
        algebra = load_text("algebra t\nbasis a b c d e\n")
        self.assertEqual(algebra.blade_count, 32)
        self.assertFalse(algebra.sparse)

    def test_missing_algebra_statement(self):
        self.assertSpecError("basis e1 e2\n", 1, 1, "missing 'algebra' statement", shows_source=False)

    def test_missing_basis_statement(self):
        self.assertSpecError("algebra t\n", 1, 1, "missing 'basis' statement", shows_source=False)

    def test_empty_file(self):
        self.assertSpecError("", 1, 1, "missing 'algebra' statement", shows_source=False)

    def test_second_algebra_statement(self):
        self.assertSpecError("algebra t\nbasis e1\nalgebra u\n", 3, 1, "second 'algebra' statement (first at line 1)")

    def test_second_scalar_statement(self):
        self.assertSpecError(E3_PRELUDE + "scalar float\nscalar double\n", 5, 1, "second 'scalar' statement")

    def test_second_representation_statement(self):
        self.assertSpecError(E3_PRELUDE + "representation dual\nrepresentation direct\n", 5, 1,
                             "second 'representation' statement")

    def test_duplicate_type(self):
        self.assertSpecError(E3_PRELUDE + "type v = e1\ntype v = e2\n", 5, 6, "type 'v' declared twice (first at line 4)")

    def test_alias_with_type_name(self):
        self.assertSpecError(E3_PRELUDE + "type v = e1\nalias v = v\n", 5, 7, "name 'v' already declared")

    def test_duplicate_alias(self):
        self.assertSpecError(E3_PRELUDE + "type v = e1\nalias w = v\nalias w = v\n", 6, 7, "name 'w' already declared")

    def test_alias_of_unknown_type(self):
        self.assertSpecError(E3_PRELUDE + "alias w = v\n", 4, 11, "unknown type 'v'")

    def test_duplicate_constant(self):
        self.assertSpecError(E3_PRELUDE + "constant c = e1\nconstant c = e2\n", 5, 10, "name 'c' already declared")

    def test_constant_with_type_name(self):
        self.assertSpecError(E3_PRELUDE + "type v = e1\nconstant v = e1\n", 5, 10, "name 'v' already declared")

    def test_constant_with_alias_name(self):
        self.assertSpecError(E3_PRELUDE + "type v = e1\nalias w = v\nconstant w = e1\n", 6, 10, "name 'w' already declared")


class ReservedNames(SpecErrorAssertions, unittest.TestCase):
    def test_cpp_keyword_as_type(self):
        self.assertSpecError(E3_PRELUDE + "type class = e1\n", 4, 6, "type name 'class' is reserved")

    def test_cpp_keyword_as_algebra(self):
        self.assertSpecError("algebra namespace\nbasis e1\n", 1, 9, "algebra name 'namespace' is reserved")

    def test_cpp_keyword_as_basis_vector(self):
        self.assertSpecError("algebra t\nbasis e1 int\n", 2, 10, "basis vector name 'int' is reserved")

    def test_library_type_names_are_reserved(self):
        self.assertSpecError(E3_PRELUDE + "type mv = e1\n", 4, 6, "type name 'mv' is reserved")
        self.assertSpecError(E3_PRELUDE + "type basic_rotor = 1\n", 4, 6, "type name 'basic_rotor' is reserved")
        self.assertSpecError(E3_PRELUDE + "type a__b = e1\n", 4, 6, "is reserved")

    def test_names_the_generated_cpp_uses_are_reserved(self):
        self.assertSpecError(E3_PRELUDE + "type detail = e1\n", 4, 6, "type name 'detail' is reserved")
        self.assertSpecError(E3_PRELUDE + "type grade_masks = e1\n", 4, 6, "is reserved")

    def test_a_coordinate_named_like_a_member_of_its_class(self):
        # `basis a b c`: the accessor c() of a type holding c clashed with its array c.
        self.assertSpecError("algebra t\nbasis a b c\ntype v = a, b, c\n", 3, 16,
                             "would be named 'c' in C++, which its class uses")
        self.assertSpecError("algebra t\nbasis e1 T\ntype v = e1, T\n", 3, 14, "would be named 'T'")

    def test_algebra_named_like_one_of_its_types(self):
        self.assertSpecError("algebra v\nbasis e1 e2\ntype v = e1, e2\n", 1, 9, "also the name of a type")

    def test_alias_and_constant_keywords(self):
        self.assertSpecError(E3_PRELUDE + "type v = e1\nalias auto = v\n", 5, 7, "alias name 'auto' is reserved")
        self.assertSpecError(E3_PRELUDE + "constant this = e1\n", 4, 10, "constant name 'this' is reserved")

    def test_type_named_like_a_library_function(self):
        self.assertSpecError(E3_PRELUDE + "type norm = e1\n", 4, 6, "clashes with a name the generated library declares")

    def test_constant_named_like_a_library_function(self):
        self.assertSpecError(E3_PRELUDE + "constant unit = e1\n", 4, 10, "already declared")

    def test_alias_named_like_a_library_function(self):
        # `alias gp = vector` would emit a type `gp` next to the function gp().
        self.assertSpecError(E3_PRELUDE + "type vector = e1, e2, e3\nalias gp = vector\n", 5, 7, "gp")

    def test_names_of_the_batch_header_and_of_the_templates_are_taken(self):
        # Each compiled to a redeclaration (or a shadowed template parameter) in the headers.
        for name in ("smul", "to_mv", "flush_profile", "native_lanes", "batch_of_t", "gather", "lane",
                     "set_lane", "T"):
            self.assertSpecError(E3_PRELUDE + f"type {name} = e1\n", 4, 6, "the generated library declares")
            self.assertSpecError(E3_PRELUDE + f"constant {name} = e1\n", 4, 10, "already declared")
        self.assertSpecError(E3_PRELUDE + "type vector = e1, e2\ntype vector_batch = e3\n", 5, 6,
                             "'vector_batch' is the batch type batch.hpp makes of 'vector'")
        self.assertSpecError(E3_PRELUDE + "type v = e1\nalias w = v\nconstant w_batch = e2\n", 6, 10,
                             "batch type batch.hpp makes of 'w'")

    def test_names_spelled_like_macros_are_reserved(self):
        # A header's macro replaces them (EOF, NULL, M_PI, W_OK, errno), and C++ keeps _X and __x.
        for name in ("EOF", "NULL", "INFINITY", "M_PI", "M_PIf", "W_OK", "INT8_MAX", "E2BIG", "errno",
                     "assert", "_Pragma", "_Complex", "_v"):
            self.assertSpecError(E3_PRELUDE + f"type {name} = e1\n", 4, 6, f"type name '{name}' is reserved")
        for name in ("I3", "I", "PS", "Ps", "v_X"):  # a pseudoscalar's usual names stay free
            with self.subTest(name=name):
                load_text(E3_PRELUDE + f"constant {name} = e1^e2^e3\n")

    def test_an_algebra_named_like_a_generated_header(self):
        self.assertSpecError("algebra tables\nbasis e1\n", 1, 9, "generated headers")


class FunctionErrors(SpecErrorAssertions, unittest.TestCase):
    PRELUDE = E3_PRELUDE + "type vector = e1, e2, e3\nalias vec = vector\n"

    def test_log_of_an_odd_type(self):
        self.assertSpecError(self.PRELUDE + "function log(vector)\n", 6, 14, "log needs an even type")

    def test_unknown_function(self):
        error = self.assertSpecError(self.PRELUDE + "function cross(vector, vector)\n", 6, 10, "unknown function 'cross'")
        self.assertIn("gp", error.message)  # lists the known ones

    def test_unknown_argument_type(self):
        self.assertSpecError(self.PRELUDE + "function gp(vector, rotor)\n", 6, 21, "unknown type 'rotor'")

    def test_too_many_arguments(self):
        text = self.PRELUDE + "function reverse(vector, vector)\n"
        self.assertSpecError(text, 6, 10, "reverse takes 1 argument(s), not 2")

    def test_too_few_arguments(self):
        self.assertSpecError(self.PRELUDE + "function gp(vector)\n", 6, 10, "gp takes 2 argument(s), not 1")

    def test_duplicate_request_through_alias(self):
        text = self.PRELUDE + "function op(vector, vector)\nfunction op(vec, vector)\n"
        self.assertSpecError(text, 7, 10, "function op(vector, vector) declared twice (first at line 6)")

    def test_alias_resolves_to_its_type(self):
        algebra = load_text(self.PRELUDE + "function gp(vec, vector)\n")
        self.assertEqual([t.name for t in algebra.functions[0].arguments], ["vector", "vector"])
        self.assertEqual(algebra.aliases, {"vec": "vector"})


class ResolvedModel(SpecErrorAssertions, unittest.TestCase):
    def test_coordinate_signs_follow_permutation_parity(self):
        # Sign of the permutation that sorts the factors: e2e1 one swap, e3e1e2 cyclic (even),
        # e2e1e3 one swap, e3e2e1 three swaps, e1e3 already sorted.
        cases = {"e2^e1": ("e1^e2", -1), "e3^e1^e2": ("e1^e2^e3", 1), "e2^e1^e3": ("e1^e2^e3", -1),
                 "e3^e2^e1": ("e1^e2^e3", -1), "e1^e3": ("e1^e3", 1), "e3^e2": ("e2^e3", -1)}
        for written, (canonical, sign) in cases.items():
            coordinate = load_text(E3_PRELUDE + f"type u = {written}\n").types[0].coordinates[0]
            self.assertEqual((coordinate.blade.name, coordinate.sign), (canonical, sign), written)

    def test_duplicate_blade_check_uses_canonical_blade(self):
        # e3^e1^e2 and e1^e2^e3 are the same blade.
        self.assertSpecError(E3_PRELUDE + "type t = e3^e1^e2, e1^e2^e3\n", 4, 20, "blade e1^e2^e3 appears twice")

    def test_constant_values(self):
        algebra = load_text(C3_PRELUDE + "metric no.ni = -1\nconstant c = 2*ni^no - no^ni + 0.5*1 + e2^e1\n")
        value = algebra.constants[0].value
        no_ni = 0b10001
        self.assertEqual(value, {no_ni: Fraction(-3), 0: Fraction(1, 2), 0b110: Fraction(-1)})

    def test_metric_defaults_to_zero_off_diagonal(self):
        algebra = load_text(C3_PRELUDE + "metric no.ni = -1\n")
        expected = [[0, 0, 0, 0, -1], [0, 1, 0, 0, 0], [0, 0, 1, 0, 0], [0, 0, 0, 1, 0], [-1, 0, 0, 0, 0]]
        self.assertEqual([list(row) for row in algebra.metric], expected)

    def test_default_scalar_is_double(self):
        self.assertEqual(load_text(E3_PRELUDE).scalar, "double")
        self.assertEqual(load_text(E3_PRELUDE + "scalar float\n").scalar, "float")

    def test_accessor_names_are_unique(self):
        # A basis vector named e12 next to e1, e2 would give a type holding
        # both it and e1^e2 two `e12()` accessors; the basis alone is fine.
        load_text("algebra t\nbasis e1 e2 e12\n")
        with self.assertRaises(SpecError):
            load_text("algebra t\nbasis e1 e2 e12\ntype v = e1^e2, e12\n")

    def test_coordinates_are_named_as_declared(self):
        # Issue 16, defect 8: e3^e1 is the coordinate e31 (of -e1^e3), not e13.
        algebra = load_text("algebra t\nbasis e0 e1 e2 e3 ni\n"
                            "type u = e3^e1, e0^e2^e1 = 1, e1^e2, 1, ni^e1, e2^e0^ni\n")
        coordinates = algebra.types[0].coordinates
        self.assertEqual([c.accessor for c in coordinates], ["e31", "e021", "e12", "scalar", "ni_e1", "e20_ni"])
        self.assertEqual([c.blade.name for c in coordinates], ["e1^e3", "e0^e1^e2", "e1^e2", "1", "e1^ni", "e0^e2^ni"])
        self.assertEqual([c.sign for c in coordinates], [-1, -1, 1, 1, -1, -1])

    def test_coordinate_names_are_unique_in_a_type(self):
        # e2^e1 is named e21, as is the basis vector e21.
        self.assertSpecError("algebra t\nbasis e1 e2 e21\ntype t = e2^e1, e21\n", 3, 17,
                             "coordinates e2^e1 and e21 of type 't' would both be named 'e21' in C++")


    def test_twelve_basis_vectors_named_e1_to_e12(self):
        # e1^e2 and e12 share the C++ name e12: only a type holding both is an error.
        basis = " ".join(f"e{i}" for i in range(1, 13))
        algebra = load_text(f"algebra t\nbasis {basis}\ntype v = e1, e12\ntype b = e1^e2, e3^e4\n")
        self.assertEqual([c.accessor for c in algebra.types[0].coordinates], ["e1", "e12"])
        self.assertSpecError(f"algebra t\nbasis {basis}\ntype v = e1^e2, e12\n", 3, 17,
                             "would both be named 'e12' in C++")


def _count_statements(path: str, keyword: str) -> int:
    """Count statements by a plain line match, independent of the parser."""
    with open(path, encoding="utf-8") as handle:
        return sum(1 for line in handle if re.match(rf"\s*{keyword}\s", line))


def _canonical_names(basis: list[str]) -> list[str]:
    """Canonical order from its definition: by grade, then lexicographic in basis order."""
    names = []
    for k in range(len(basis) + 1):
        names += ["^".join(c) or "1" for c in itertools.combinations(basis, k)]
    return names


class ShippedSpecs(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.e3ga = load(spec_path("e3ga"), "specs/e3ga.ga")
        cls.c3ga = load(spec_path("c3ga"), "specs/c3ga.ga")

    def test_counts_match_the_spec_files(self):
        for name, algebra in (("e3ga", self.e3ga), ("c3ga", self.c3ga)):
            path = spec_path(name)
            self.assertEqual(len(algebra.types), _count_statements(path, "type"), name)
            self.assertEqual(len(algebra.functions), _count_statements(path, "function"), name)
            self.assertEqual(len(algebra.constants), _count_statements(path, "constant"), name)
            self.assertEqual(len(algebra.aliases), _count_statements(path, "alias"), name)

    def test_e3ga_basics(self):
        a = self.e3ga
        self.assertEqual((a.name, a.basis, a.scalar, a.blade_count), ("e3ga", ("e1", "e2", "e3"), "double", 8))
        self.assertEqual([list(r) for r in a.metric], [[1, 0, 0], [0, 1, 0], [0, 0, 1]])

    def test_c3ga_basics(self):
        a = self.c3ga
        self.assertEqual((a.name, a.basis, a.scalar, a.blade_count), ("c3ga", ("no", "e1", "e2", "e3", "ni"), "double", 32))
        self.assertEqual(a.metric[0][4], -1)
        self.assertEqual(a.metric[4][0], -1)
        self.assertEqual((a.metric[0][0], a.metric[4][4]), (0, 0))
        self.assertEqual(a.aliases, {"point": "dual_sphere"})

    def test_e3ga_blade_order_from_the_api_doc(self):
        self.assertEqual([b.name for b in self.e3ga.blades], ["1", "e1", "e2", "e3", "e1^e2", "e1^e3", "e2^e3", "e1^e2^e3"])
        self.assertEqual([b.grade for b in self.e3ga.blades], [0, 1, 1, 1, 2, 2, 2, 3])

    def test_c3ga_blade_order_from_the_api_doc(self):
        documented = ["1", "no", "e1", "e2", "e3", "ni", "no^e1", "no^e2", "no^e3", "no^ni", "e1^e2", "e1^e3",
                      "e1^ni", "e2^e3", "e2^ni", "e3^ni", "no^e1^e2"]
        names = [b.name for b in self.c3ga.blades]
        self.assertEqual(names[: len(documented)], documented)
        self.assertEqual(names[-1], "no^e1^e2^e3^ni")
        self.assertEqual(names, _canonical_names(["no", "e1", "e2", "e3", "ni"]))

    def test_blade_indices_bitmaps_and_grades_agree(self):
        for algebra in (self.e3ga, self.c3ga):
            for i, blade in enumerate(algebra.blades):
                self.assertEqual(blade.index, i)
                factors = [algebra.basis[k] for k in range(len(algebra.basis)) if blade.bitmap >> k & 1]
                self.assertEqual(blade.name, "^".join(factors) or "1")
                self.assertEqual(blade.grade, len(factors))
                self.assertIs(algebra.blade_by_bitmap(blade.bitmap), blade)

    def test_accessor_names(self):
        e3 = {b.name: b.accessor for b in self.e3ga.blades}
        c3 = {b.name: b.accessor for b in self.c3ga.blades}
        self.assertEqual(e3["1"], "scalar")
        self.assertEqual(e3["e1^e2"], "e12")
        self.assertEqual(e3["e1^e2^e3"], "e123")
        self.assertEqual(c3["no^ni"], "no_ni")
        self.assertEqual(c3["e1^e2^e3^ni"], "e123_ni")
        self.assertEqual(c3["no^e1^ni"], "no_e1_ni")
        self.assertEqual(c3["no^e1^e2^e3^ni"], "no_e123_ni")
        self.assertEqual(len(set(c3.values())), 32)

    def test_normalized_point_has_constant_origin(self):
        types = {t.name: t for t in self.c3ga.types}
        point = types["normalized_point"]
        self.assertEqual([c.blade.name for c in point.coordinates], ["no", "e1", "e2", "e3", "ni"])
        self.assertEqual([c.constant for c in point.coordinates], [1, None, None, None, None])
        self.assertEqual([c.blade.name for c in point.stored], ["e1", "e2", "e3", "ni"])

    def test_type_grades(self):
        expected = {"rotor": {0, 2}, "translator": {0, 2}, "motor": {0, 2, 4}, "line": {3}, "circle": {3},
                    "sphere": {4}, "plane": {4}, "pseudoscalar": {5}, "flat_point": {2}, "dual_line": {2}}
        types = {t.name: t for t in self.c3ga.types}
        for name, grades in expected.items():
            self.assertEqual({c.blade.grade for c in types[name].coordinates}, grades, name)

    def test_requested_functions(self):
        requested = {(f.name, tuple(t.name for t in f.arguments)) for f in self.e3ga.functions}
        self.assertIn(("gp", ("rotor", "rotor")), requested)
        self.assertIn(("apply", ("rotor", "vector")), requested)
        self.assertIn(("exp", ("bivector",)), requested)

    def test_constants(self):
        constants = {c.name: c.value for c in self.c3ga.constants}
        self.assertEqual(constants["I5"], {0b11111: 1})
        self.assertEqual(constants["ni"], {0b10000: 1})
        self.assertEqual(constants["I3"], {0b01110: 1})

    def test_spec_hash_is_sha256_of_the_text(self):
        import hashlib

        with open(spec_path("e3ga"), "rb") as handle:
            self.assertEqual(self.e3ga.spec_hash, hashlib.sha256(handle.read()).hexdigest())

    def test_display_path_is_used_in_errors(self):
        self.assertEqual(self.e3ga.path, "specs/e3ga.ga")
        self.assertTrue(os.path.isfile(spec_path("e3ga")))


class Reading(unittest.TestCase):
    def test_bytes_that_are_not_utf8_are_located(self):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "bad.ga")
            with open(path, "wb") as handle:
                handle.write(b"algebra t\r\nbasis e1 \xff\n")
            with self.assertRaises(SpecError) as caught:
                load(path)
        self.assertEqual(str(caught.exception).split("\n")[0], f"{path}:2:10: error: not UTF-8 text (byte 0xff)")


if __name__ == "__main__":
    unittest.main()
