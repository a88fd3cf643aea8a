"""The command line (python3 -m gaphys_gen): bad input fails loudly and writes nothing."""

import os
import subprocess
import sys
import tempfile
import unittest

from gaphys_gen import output

from .support import GENERATOR_DIR, spec_path

HAS_CLI = os.path.isfile(os.path.join(GENERATOR_DIR, "gaphys_gen", "__main__.py"))

BAD_SPEC = "algebra bad\nbasis e1 e2\ntype vector = e1, e3\n"  # e3 is not a basis vector: 3:19


def run_cli(*arguments: str) -> subprocess.CompletedProcess:
    environment = dict(os.environ, PYTHONPATH=GENERATOR_DIR)
    return subprocess.run(
        [sys.executable, "-m", "gaphys_gen", *arguments], capture_output=True, text=True, env=environment, timeout=300
    )


def files_under(root: str) -> list[str]:
    return sorted(os.path.relpath(os.path.join(d, f), root) for d, _, names in os.walk(root) for f in names)


@unittest.skipUnless(HAS_CLI, "generator/gaphys_gen/__main__.py not written yet")
class CommandLine(unittest.TestCase):
    def setUp(self):
        self.work = tempfile.TemporaryDirectory()
        self.addCleanup(self.work.cleanup)
        self.out = os.path.join(self.work.name, "out")
        os.mkdir(self.out)

    def write_spec(self, text: str) -> str:
        path = os.path.join(self.work.name, "bad.ga")
        with open(path, "w", encoding="utf-8") as handle:
            handle.write(text)
        return path

    def test_bad_spec_fails_with_location_and_writes_nothing(self):
        path = self.write_spec(BAD_SPEC)
        for variant in ("reference", "optimized"):
            result = run_cli("generate", path, "--variant", variant, "--out", self.out, "--no-format")
            self.assertNotEqual(result.returncode, 0)
            self.assertIn(f"{path}:3:19: error: unknown basis vector 'e3'", result.stderr)
            self.assertIn("type vector = e1, e3\n" + " " * 18 + "^", result.stderr)
            self.assertEqual(files_under(self.out), [])

    def test_spec_error_found_during_expansion_writes_nothing(self):
        # Valid syntax and names, but the requested product is zero for every input.
        path = self.write_spec(
            "algebra bad\nbasis e1 e2\nmetric e1.e1 = 1, e2.e2 = 1\ntype vector = e1, e2\ntype pseudo = e1^e2\n"
            "function op(vector, pseudo)\n"
        )
        result = run_cli("generate", path, "--variant", "optimized", "--out", self.out, "--no-format")
        self.assertNotEqual(result.returncode, 0)
        self.assertIn(f"{path}:6:10: error:", result.stderr)
        self.assertEqual(files_under(self.out), [])

    def test_missing_spec_file(self):
        missing = os.path.join(self.work.name, "missing.ga")
        result = run_cli("generate", missing, "--variant", "reference", "--out", self.out, "--no-format")
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("missing.ga", result.stderr)
        self.assertNotIn("Traceback", result.stderr)
        self.assertEqual(files_under(self.out), [])

    def test_bad_namespace(self):
        result = run_cli("generate", spec_path("e3ga"), "--variant", "reference", "--out", self.out,
                         "--namespace", "not-an-identifier", "--no-format")
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("namespace", result.stderr)
        self.assertEqual(files_under(self.out), [])

    def test_reserved_namespace(self):
        # A C++ keyword is an identifier to Python but not to the compiler.
        result = run_cli("generate", spec_path("e3ga"), "--variant", "reference", "--out", self.out,
                         "--namespace", "int", "--no-format")
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("namespace", result.stderr)
        self.assertEqual(files_under(self.out), [])

    def test_an_out_that_cannot_be_written_is_an_error_not_a_traceback(self):
        not_a_folder = os.path.join(self.work.name, "a_file")
        with open(not_a_folder, "w", encoding="utf-8"):
            pass
        result = run_cli("generate", spec_path("e3ga"), "--variant", "reference", "--out", not_a_folder,
                         "--no-format")
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("cannot write", result.stderr)
        self.assertNotIn("Traceback", result.stderr)

    def test_unknown_variant_is_a_usage_error(self):
        result = run_cli("generate", spec_path("e3ga"), "--variant", "fastest", "--out", self.out)
        self.assertNotEqual(result.returncode, 0)
        self.assertEqual(files_under(self.out), [])

    def test_generate_then_check(self):
        arguments = (spec_path("e3ga"), "--variant", "optimized", "--out", self.out,
                     "--namespace", "e3ga_test", "--no-format")
        result = run_cli("generate", *arguments)
        self.assertEqual(result.returncode, 0, result.stderr)
        written = files_under(self.out)
        self.assertIn(os.path.join("e3ga_test", "e3ga_test.hpp"), written)
        self.assertEqual(run_cli("check", *arguments).returncode, 0)
        # Generating again is byte-identical (no timestamps) and check notices a hand edit.
        header = os.path.join(self.out, "e3ga_test", "e3ga_test.hpp")
        with open(header, encoding="utf-8") as handle:
            first = handle.read()
        self.assertEqual(run_cli("generate", *arguments).returncode, 0)
        with open(header, encoding="utf-8") as handle:
            self.assertEqual(handle.read(), first)
        with open(header, "a", encoding="utf-8") as handle:
            handle.write("// edited\n")
        stale = run_cli("check", *arguments)
        self.assertEqual(stale.returncode, 1)
        self.assertIn("e3ga_test.hpp", stale.stderr)


class AtomicOutput(unittest.TestCase):
    def test_failure_leaves_the_folder_untouched(self):
        with tempfile.TemporaryDirectory() as root:
            # "b" is a file, so b/y.hpp cannot be written; a/x.hpp (staged first) must not appear either.
            with open(os.path.join(root, "b"), "w", encoding="utf-8") as handle:
                handle.write("in the way")
            with self.assertRaises(OSError):
                output.write_all(root, {"a/x.hpp": "x\n", "b/y.hpp": "y\n"})
            self.assertFalse(os.path.exists(os.path.join(root, "a", "x.hpp")))
            leftovers = [f for f in files_under(root) if os.path.basename(f).startswith(".gaphys-")]
            self.assertEqual(leftovers, [])

    def test_failure_creates_no_folders(self):
        # "as it was" includes not leaving behind the empty folder made for a/x.hpp.
        with tempfile.TemporaryDirectory() as root:
            with open(os.path.join(root, "b"), "w", encoding="utf-8") as handle:
                handle.write("in the way")
            with self.assertRaises(OSError):
                output.write_all(root, {"a/x.hpp": "x\n", "b/y.hpp": "y\n"})
            self.assertEqual(sorted(os.listdir(root)), ["b"])

    def test_unchanged_files_are_not_rewritten(self):
        with tempfile.TemporaryDirectory() as root:
            self.assertEqual(len(output.write_all(root, {"a/x.hpp": "x\n", "y.hpp": "y\n"})), 2)
            self.assertEqual(output.write_all(root, {"a/x.hpp": "x\n", "y.hpp": "changed\n"}), [os.path.join(root, "y.hpp")])
            with open(os.path.join(root, "y.hpp"), encoding="utf-8") as handle:
                self.assertEqual(handle.read(), "changed\n")


if __name__ == "__main__":
    unittest.main()
