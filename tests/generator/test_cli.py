"""The command line (python3 -m gaphys_gen): bad input fails loudly and writes nothing."""

import os
import shlex
import signal
import stat
import subprocess
import sys
import tempfile
import threading
import unittest
from unittest import mock

from gaphys_gen import output

from .support import GENERATOR_DIR, REPO_DIR, spec_path

HAS_CLI = os.path.isfile(os.path.join(GENERATOR_DIR, "gaphys_gen", "__main__.py"))

BAD_SPEC = "algebra bad\nbasis e1 e2\ntype vector = e1, e3\n"  # e3 is not a basis vector: 3:19


def run_cli(*arguments: str, path_first: str | None = None) -> subprocess.CompletedProcess:
    environment = dict(os.environ, PYTHONPATH=GENERATOR_DIR)
    if path_first:  # (a folder searched first for programs: a stand-in clang-format)
        environment["PATH"] = path_first + os.pathsep + environment.get("PATH", "")
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

    def test_a_namespace_that_would_stand_for_a_type_or_a_header(self):
        # vector::vector; <tables/tables.hpp>, the main header, in place of the companion tables.hpp.
        for namespace, reason in (("vector", "also the name of a type"), ("tables", "generated headers"),
                                  ("call", "generated headers"), ("EOF", "not a C++ identifier")):
            result = run_cli("generate", spec_path("e3ga"), "--variant", "reference", "--out", self.out,
                             "--namespace", namespace, "--no-format")
            self.assertEqual(result.returncode, 1, namespace)
            self.assertIn(reason, result.stderr)
            self.assertEqual(files_under(self.out), [])

    def test_a_damaged_output_file_is_stale_and_written_over(self):
        arguments = (spec_path("e3ga"), "--variant", "reference", "--out", self.out, "--no-format")
        self.assertEqual(run_cli("generate", *arguments).returncode, 0)
        damaged = os.path.join(self.out, "e3ga", "types.hpp")
        with open(damaged, "wb") as handle:
            handle.write(b"\xff\xfe not text")
        stale = run_cli("check", *arguments)
        self.assertEqual(stale.returncode, 1)
        self.assertIn("stale: " + damaged, stale.stderr)
        self.assertNotIn("Traceback", stale.stderr)
        self.assertEqual(run_cli("generate", *arguments).returncode, 0)
        self.assertEqual(run_cli("check", *arguments).returncode, 0)

    def test_main_runs_on_another_thread_and_leaves_the_signals_as_they_were(self):
        from gaphys_gen.__main__ import main

        before = signal.getsignal(signal.SIGTERM)
        codes = []
        worker = threading.Thread(target=lambda: codes.append(main(
            ["generate", spec_path("e3ga"), "--variant", "reference", "--out", self.out, "--no-format"])))
        worker.start()
        worker.join()
        self.assertEqual(codes, [0])
        self.assertEqual(main(["check", spec_path("e3ga"), "--variant", "reference", "--out", self.out,
                               "--no-format"]), 0)
        self.assertEqual(signal.getsignal(signal.SIGTERM), before)

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

    def test_coverage_without_a_profile_is_a_usage_error(self):
        # (As gaphys_add_algebra refuses COVERAGE without PROFILE: silently
        # ignored, it would look as if it had been applied.)
        result = run_cli("generate", spec_path("e3ga"), "--variant", "optimized", "--out", self.out, "--coverage", "0.5")
        self.assertEqual(result.returncode, 2)
        self.assertIn("--coverage needs --profile", result.stderr)
        self.assertEqual(files_under(self.out), [])

    def test_only_generating_needs_jinja2(self):
        # A Python without Jinja2 (Debian's python3 alone): a jinja2 package
        # first on the path that fails to import stands in for none.
        blocker = os.path.join(self.work.name, "no_jinja2")
        os.makedirs(os.path.join(blocker, "jinja2"))
        with open(os.path.join(blocker, "jinja2", "__init__.py"), "w", encoding="utf-8") as stub:
            stub.write("raise ImportError('no Jinja2 here')\n")
        environment = dict(os.environ, PYTHONPATH=blocker + os.pathsep + GENERATOR_DIR)

        def run(*arguments: str) -> subprocess.CompletedProcess:
            return subprocess.run([sys.executable, "-m", "gaphys_gen", *arguments], capture_output=True, text=True,
                                  env=environment, timeout=300)

        profile_path = os.path.join(REPO_DIR, "profiling", "profiles", "e3ga.json")
        for arguments in (["--help"], ["report", profile_path, "--spec", spec_path("e3ga")],
                          ["merge", "--spec", spec_path("e3ga"), "--out", os.path.join(self.work.name, "m.json"),
                           profile_path]):
            result = run(*arguments)
            self.assertEqual(result.returncode, 0, (arguments, result.stderr))
            self.assertNotIn("Traceback", result.stderr)
        result = run("generate", spec_path("e3ga"), "--variant", "optimized", "--out", self.out)
        self.assertNotEqual(result.returncode, 0)
        self.assertNotIn("Traceback", result.stderr)
        self.assertIn("generating needs Jinja2", result.stderr)
        self.assertEqual(files_under(self.out), [])

    def test_profile_commands_name_a_path_they_cannot_use(self):
        profile_path = os.path.join(REPO_DIR, "profiling", "profiles", "e3ga.json")
        missing = os.path.join(self.work.name, "missing.ga")
        for arguments in (("report", profile_path, "--spec", missing),
                          ("report", profile_path, "--spec", self.work.name),  # a folder
                          ("merge", "--spec", spec_path("e3ga"), "--out", self.out, profile_path)):
            result = run_cli(*arguments)
            self.assertEqual(result.returncode, 1, arguments)
            self.assertNotIn("Traceback", result.stderr)
            self.assertRegex(result.stderr, r"^gaphys-gen: .*(missing\.ga|Is a directory)")
        result = run_cli("report", profile_path, "--spec", spec_path("e3ga"), "--top", "-3")
        self.assertEqual(result.returncode, 2)  # argparse's usage error
        self.assertIn("--top: must be >= 0", result.stderr)

    def test_a_newline_in_the_spec_path_stays_inside_the_banner(self):
        odd = os.path.join(self.work.name, "odd\n#error injected\\")
        with open(spec_path("e3ga"), encoding="utf-8") as source, open(odd, "w", encoding="utf-8") as copy:
            copy.write(source.read())
        result = run_cli("generate", odd, "--variant", "reference", "--out", self.out, "--no-format")
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(os.path.join(self.out, "e3ga", "e3ga.hpp"), encoding="utf-8") as handle:
            lines = handle.read().splitlines()
        banner = lines[: next(i for i, line in enumerate(lines) if not line.startswith("//"))]
        self.assertTrue(any("odd\\x0a#error injected\\ (sha256" in line for line in banner), banner)
        self.assertFalse(any(line.startswith("#error") for line in lines))
        self.assertFalse(any(line.endswith("\\") for line in banner))

    def test_the_banners_command_regenerates_unformatted_output(self):
        result = run_cli("generate", spec_path("e3ga"), "--variant", "optimized", "--out", self.out, "--no-format")
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(os.path.join(self.out, "e3ga", "e3ga.hpp"), encoding="utf-8") as handle:
            command = next(line for line in handle if line.startswith("// Regenerate: "))
        words = shlex.split(command[len("// Regenerate: "):])
        self.assertEqual(words[:2], ["gaphys-gen", "generate"])
        self.assertIn("--no-format", words)
        # Its words, as `check`, find nothing to change (without --no-format every file was stale).
        self.assertEqual(run_cli("check", *words[2:]).returncode, 0)

    def test_a_failing_clang_format_is_an_error_that_writes_nothing(self):
        tools = os.path.join(self.work.name, "tools")
        os.mkdir(tools)
        fake = os.path.join(tools, "clang-format")
        with open(fake, "w", encoding="utf-8") as handle:
            handle.write("#!/bin/sh\necho 'cannot format this' >&2\nexit 3\n")
        os.chmod(fake, stat.S_IRWXU)
        result = run_cli("generate", spec_path("e3ga"), "--variant", "reference", "--out", self.out,
                         path_first=tools)
        self.assertEqual(result.returncode, 1)
        self.assertIn("clang-format failed (exit 3): cannot format this", result.stderr)
        self.assertNotIn("Traceback", result.stderr)
        self.assertEqual(files_under(self.out), [])


class AtomicOutput(unittest.TestCase):
    def test_ctrl_c_during_the_renames_lands_after_all_of_them(self):
        real_replace = os.replace
        calls = []

        def replace_then_interrupt(source, target):
            calls.append(target)
            if len(calls) == 1:
                os.kill(os.getpid(), signal.SIGINT)  # held back until every file is in place
            real_replace(source, target)

        with tempfile.TemporaryDirectory() as root:
            files = {"a/x.hpp": "x\n", "b/y.hpp": "y\n", "z.hpp": "z\n"}
            with mock.patch.object(output.os, "replace", replace_then_interrupt):
                with self.assertRaises(KeyboardInterrupt):
                    output.write_all(root, files)
            self.assertEqual(len(calls), 3)
            self.assertEqual(files_under(root), sorted(os.path.normpath(name) for name in files))

    def test_ctrl_c_while_staging_leaves_the_folder_as_it_was(self):
        real_mkstemp = tempfile.mkstemp
        calls = []

        def mkstemp_then_interrupt(*arguments, **keywords):
            calls.append(1)
            made = real_mkstemp(*arguments, **keywords)
            if len(calls) == 2:
                os.kill(os.getpid(), signal.SIGINT)
            return made

        with tempfile.TemporaryDirectory() as root:
            with open(os.path.join(root, "z.hpp"), "w", encoding="utf-8") as handle:
                handle.write("old\n")
            with mock.patch.object(output.tempfile, "mkstemp", mkstemp_then_interrupt):
                with self.assertRaises(KeyboardInterrupt):
                    output.write_all(root, {"a/x.hpp": "x\n", "b/y.hpp": "y\n", "z.hpp": "z\n"})
            self.assertEqual(files_under(root), ["z.hpp"])
            with open(os.path.join(root, "z.hpp"), encoding="utf-8") as handle:
                self.assertEqual(handle.read(), "old\n")

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
