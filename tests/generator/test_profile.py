"""Profiles: loading validates everything, merge adds counts, report and selection."""

import json
import os
import subprocess
import sys
import tempfile
import unittest

from gaphys_gen import expand, model, profile

from .support import GENERATOR_DIR, spec_path

E3 = model.load(spec_path("e3ga"))
C3 = model.load(spec_path("c3ga"))
VECTOR = 0b1110  # e1, e2, e3 in e3ga's canonical order
ROTOR = 0b1110001  # 1, e1^e2, e1^e3, e2^e3


def document(**changes) -> dict:
    data = {
        "format": "gaphys-profile", "version": 1, "algebra": "e3ga", "spec_hash": E3.spec_hash,
        "generator_version": "0.1.0",
        "entries": [{"function": "gp", "arguments": [VECTOR, VECTOR], "result": ROTOR, "count": 3}],
    }
    data.update(changes)
    return data


def entry(**changes) -> dict:
    value = {"function": "gp", "arguments": [VECTOR, VECTOR], "result": ROTOR, "count": 3}
    value.update(changes)
    return value


class Loading(unittest.TestCase):
    def assertRejected(self, data, fragment, text=None):
        with self.assertRaises(profile.ProfileError) as caught:
            profile.parse(text if text is not None else json.dumps(data), "p.json", E3)
        message = str(caught.exception)
        self.assertTrue(message.startswith("p.json"), message)
        self.assertIn(fragment, message)
        return message

    def test_valid_profile_loads(self):
        loaded = profile.parse(json.dumps(document()), "p.json", E3)
        self.assertEqual(loaded.entries, (profile.Entry("gp", (VECTOR, VECTOR), ROTOR, 3),))
        self.assertEqual(loaded.total_calls, 3)

    def test_malformed_json_names_line_and_column(self):
        message = self.assertRejected(None, "malformed JSON", text='{\n  "format": \n}')
        self.assertTrue(message.startswith("p.json:3:1:"), message)

    def test_wrong_algebra(self):
        self.assertRejected(document(algebra="c3ga"), 'algebra "c3ga", not "e3ga"')

    def test_wrong_spec_hash(self):
        self.assertRejected(document(spec_hash="0" * 64), "another version of the spec")

    def test_bits_outside_the_algebra(self):
        self.assertRejected(document(entries=[entry(arguments=[VECTOR, 1 << 8])]), "outside the algebra's 8 blades")
        self.assertRejected(document(entries=[entry(result=-1)]), "outside the algebra")

    def test_content_errors_name_the_line_and_column_of_the_value(self):
        # As `merge` writes them: one entry a line, entry n on line 8 + n.
        good = profile.Profile("e3ga", E3.spec_hash, "0.1.0",
                               tuple(profile.Entry("gp", (VECTOR, VECTOR), ROTOR, n) for n in (1, 2, 3)))
        lines = profile.dumps(good).splitlines()
        lines[9] = lines[9].replace('"count": 3', '"count": -3')
        message = self.assertRejected(None, "entry 2: count must be", text="\n".join(lines))
        self.assertTrue(message.startswith(f"p.json:10:{lines[9].index('-3') + 1}:"), message)
        lines = profile.dumps(good).splitlines()
        lines[8] = lines[8].replace('"gp"', '"cross"')
        message = self.assertRejected(None, 'entry 1: unknown function "cross"', text="\n".join(lines))
        self.assertTrue(message.startswith(f"p.json:9:{lines[8].index('cross')}:"), message)
        # A bitmap is found in its list; a count of 2^128 where it is written.
        lines = profile.dumps(good).splitlines()
        lines[8] = lines[8].replace(f"[{VECTOR}, {VECTOR}]", f"[{VECTOR}, 99999]")
        message = self.assertRejected(None, "arguments bitmap 99999 has bits outside", text="\n".join(lines))
        self.assertTrue(message.startswith(f"p.json:9:{lines[8].index('99999') + 1}:"), message)
        lines = profile.dumps(good).splitlines()
        lines[7] = lines[7].replace('"count": 1', f'"count": {2**128}')
        message = self.assertRejected(None, "entry 0: count of 2^128 or more", text="\n".join(lines))
        self.assertTrue(message.startswith(f"p.json:8:{lines[7].index(str(2**128)) + 1}:"), message)
        text = json.dumps(document(algebra="c3ga"), indent=1)
        line = next(n for n, row in enumerate(text.splitlines(), 1) if '"algebra"' in row)
        message = self.assertRejected(None, 'not "e3ga"', text=text)
        self.assertTrue(message.startswith(f"p.json:{line}:"), message)

    def test_negative_count(self):
        self.assertRejected(document(entries=[entry(count=-1)]), "count must be a non-negative integer")

    def test_non_integer_values(self):
        self.assertRejected(document(entries=[entry(count=1.5)]), "count must be")
        self.assertRejected(document(entries=[entry(count=True)]), "count must be")
        self.assertRejected(document(entries=[entry(arguments=[VECTOR, "14"])]), 'bitmap "14"')

    def test_unknown_function_and_wrong_arity(self):
        self.assertRejected(document(entries=[entry(function="cross")]), 'unknown function "cross"')
        self.assertRejected(document(entries=[entry(function="reverse")]), "reverse takes 1 bitmap")

    def test_structure(self):
        self.assertRejected([], "a profile is a JSON object")
        self.assertRejected(document(format="other"), "not a gaphys profile")
        self.assertRejected(document(version=2), "version 2 is not supported")
        self.assertRejected(document(entries={}), '"entries" must be a list')
        self.assertRejected(document(extra=1), "unknown key(s): extra")
        self.assertRejected(document(entries=[{"function": "gp"}]), "needs exactly the keys")

    def test_huge_counts_are_exact(self):
        loaded = profile.parse(json.dumps(document(entries=[entry(count=2**70)])), "p.json", E3)
        self.assertEqual(loaded.total_calls, 2**70)

    def test_json_that_python_cannot_hold(self):
        self.assertRejected(None, "p.json: malformed JSON: nested too deeply", text="[" * 100000)
        digits = json.dumps(document(entries=[entry(count=0)])).replace('"count": 0', '"count": ' + "9" * 5000)
        self.assertRejected(None, "p.json: malformed JSON: a number has too many digits", text=digits)

    def test_counts_stay_below_2_to_128_after_adding_duplicates(self):
        loaded = profile.parse(json.dumps(document(entries=[entry(count=2**128 - 1)])), "p.json", E3)
        self.assertEqual(loaded.total_calls, 2**128 - 1)
        self.assertRejected(document(entries=[entry(count=2**127), entry(count=2**127)]), "2^128 calls or more")

    def test_wrong_types_that_python_compares_equal(self):
        self.assertRejected(document(version=True), "version true is not supported")
        self.assertRejected(document(version=1.0), "version 1.0 is not supported")
        self.assertRejected(document(entries=[entry(function=["gp"])]), 'unknown function ["gp"]')
        self.assertRejected(document(entries=[entry(function={"gp": 1})]), 'unknown function {"gp": 1}')

    def test_duplicate_entries_add_up(self):
        loaded = profile.parse(json.dumps(document(entries=[entry(count=2), entry(count=5)])), "p.json", E3)
        self.assertEqual([e.count for e in loaded.entries], [7])


class MergeAndWrite(unittest.TestCase):
    def test_merge_adds_counts(self):
        a = profile.parse(json.dumps(document()), "a", E3)
        b = profile.parse(json.dumps(document(entries=[entry(count=4), entry(function="add", result=VECTOR,
                                                                          count=1)])), "b", E3)
        merged = profile.merge([("a", a), ("b", b)])
        self.assertEqual({(e.function, e.count) for e in merged.entries}, {("gp", 7), ("add", 1)})

    def test_merge_names_the_profile_that_reaches_2_to_128(self):
        half = profile.parse(json.dumps(document(entries=[entry(count=2**127)])), "a", E3)
        with self.assertRaises(profile.ProfileError) as caught:
            profile.merge([("a", half), ("b", half)])
        self.assertEqual(str(caught.exception), f"b: gp [{VECTOR}, {VECTOR}]: 2^128 calls or more")

    def test_merge_refuses_other_specs(self):
        a = profile.parse(json.dumps(document()), "a", E3)
        other = profile.Profile("c3ga", C3.spec_hash, "0.1.0", ())
        with self.assertRaises(profile.ProfileError):
            profile.merge([("a", a), ("b", other)])

    def test_dumps_round_trips_and_is_deterministic(self):
        loaded = profile.parse(json.dumps(document(entries=[entry(function="add", result=VECTOR), entry()])), "p", E3)
        text = profile.dumps(loaded)
        self.assertEqual(profile.parse(text, "p", E3), loaded)
        self.assertEqual(profile.dumps(profile.parse(text, "p", E3)), text)


class SelectionAndReport(unittest.TestCase):
    PROFILE = profile.Profile("e3ga", E3.spec_hash, "0.1.0", (
        profile.Entry("lc", (VECTOR, VECTOR), 1, 1),
        profile.Entry("gp", (ROTOR, ROTOR), ROTOR, 900),
        profile.Entry("gp", (VECTOR, VECTOR), ROTOR, 99),
    ))

    def test_select_covers_the_requested_share_hottest_first(self):
        self.assertEqual([c[:2] for c in profile.select(self.PROFILE, 0.9)], [("gp", (ROTOR, ROTOR))])
        self.assertEqual(len(profile.select(self.PROFILE, 0.99)), 2)
        self.assertEqual(len(profile.select(self.PROFILE, 1.0)), 3)

    def test_report_names_blades_and_fallback_share(self):
        text = profile.report(self.PROFILE, E3, 0.99)
        self.assertIn("generic fallback: 1 calls (0.100%)", text)  # lc: no kernel serves it
        self.assertIn("{1, e1^e2, e1^e3, e2^e3} x {1, e1^e2, e1^e3, e2^e3}", text)

    def test_sums_get_kernels_only_where_the_dense_sum_is_longer(self):
        # e3ga's dense generic sum of 8 coefficients beats a dispatch; c3ga's 32 do not.
        self.assertEqual(expand.expand_profile(E3, [("add", (VECTOR, VECTOR), 10), ("sub", (VECTOR, VECTOR), 5)]), [])
        self.assertEqual(len(expand.expand_profile(E3, [("gp", (VECTOR, VECTOR), 10)])), 1)
        c3_vector = 0x3e  # no, e1, e2, e3, ni
        self.assertEqual([k.function for k in expand.expand_profile(C3, [("add", (c3_vector, c3_vector), 10)])],
                         ["add"])
        text = profile.report(profile.Profile("e3ga", E3.spec_hash, "0.1.0", (
            profile.Entry("add", (VECTOR, VECTOR), VECTOR, 7),
            profile.Entry("gp", (VECTOR, VECTOR), ROTOR, 3),
        )), E3, 1.0)
        self.assertIn("dense generic sums (no sum kernel pays in this algebra): 7 calls", text)
        self.assertIn("generic fallback: 0 calls", text)


class CommandLine(unittest.TestCase):
    def run_cli(self, *args):
        return subprocess.run([sys.executable, os.path.join(GENERATOR_DIR, "gaphys-gen"), *args],
                              capture_output=True, text=True)

    def test_merge_writes_nothing_on_a_bad_input(self):
        with tempfile.TemporaryDirectory() as folder:
            good, bad = os.path.join(folder, "good.json"), os.path.join(folder, "bad.json")
            with open(good, "w") as handle:
                json.dump(document(), handle)
            with open(bad, "w") as handle:
                json.dump(document(entries=[entry(count=-3)]), handle)
            out = os.path.join(folder, "out.json")
            result = self.run_cli("merge", "--spec", spec_path("e3ga"), "--out", out, good, bad)
            self.assertEqual(result.returncode, 1)
            self.assertRegex(result.stderr, r"bad\.json:\d+:\d+: entry 0: count must be")
            self.assertFalse(os.path.exists(out))
            result = self.run_cli("merge", "--spec", spec_path("e3ga"), "--out", out, good, good)
            self.assertEqual(result.returncode, 0, result.stderr)
            with open(out) as handle:
                self.assertEqual(json.load(handle)["entries"][0]["count"], 6)
            report = self.run_cli("report", out, "--spec", spec_path("e3ga"))
            self.assertEqual(report.returncode, 0, report.stderr)
            self.assertIn("| 6 | 100.00% | gp | {e1, e2, e3} x {e1, e2, e3} |", report.stdout)


class SupersetKernels(unittest.TestCase):
    """Kernels made for one bitmap serve the subsets of it the profile never showed."""

    def kernel(self, function, *bits):
        from gaphys_gen.expand import expand_profile

        (made,) = expand_profile(E3, [(function, bits, 1)])
        return made

    def test_a_kernel_serves_subsets_of_its_bitmaps_only(self):
        rotors = self.kernel("gp", ROTOR, ROTOR)
        self.assertTrue(rotors.serves((ROTOR, ROTOR)))
        self.assertTrue(rotors.serves((0b0000001, ROTOR)))  # a scalar times a rotor
        self.assertTrue(rotors.serves((0b0110000, 0b1000001)))  # parts of rotors
        self.assertFalse(rotors.serves((VECTOR, ROTOR)))  # e1 is no rotor coefficient

    def test_a_kernel_much_larger_than_the_arguments_leaves_them_to_the_generic_path(self):
        full = self.kernel("gp", 0xFF, 0xFF)
        self.assertEqual(full.operations, 120)  # 64 mul, 56 add
        self.assertTrue(full.serves((VECTOR | ROTOR, ROTOR)))  # 28 generic terms: 120 <= 8 * 28
        self.assertFalse(full.serves((VECTOR, ROTOR)))  # 12 generic terms: 120 > 8 * 12

    def test_kernels_that_divide_serve_no_subsets(self):
        apply = self.kernel("apply", ROTOR, VECTOR)
        self.assertIsNotNone(apply.kernel.divisor)
        self.assertFalse(apply.serves((0b0000001, VECTOR)))
        self.assertFalse(apply.serves((ROTOR, VECTOR)))  # exactly its bitmaps: the switch's case, not this

    def test_report_counts_calls_served_by_a_superset_kernel(self):
        data = profile.Profile("e3ga", E3.spec_hash, "0.1.0", (
            profile.Entry("gp", (ROTOR, ROTOR), ROTOR, 900),
            profile.Entry("gp", (0b0000001, ROTOR), ROTOR, 60),  # served by gp on rotors
            profile.Entry("op", (VECTOR, VECTOR), 0b1110000, 40),  # no kernel for op
        ))
        text = profile.report(data, E3, 0.9)
        self.assertIn("specialized at coverage 0.9: 1 combinations, 900 calls", text)
        self.assertIn("served by a superset's kernel: 60 calls", text)
        self.assertIn("generic fallback: 40 calls (4.000%)", text)


if __name__ == "__main__":
    unittest.main()
