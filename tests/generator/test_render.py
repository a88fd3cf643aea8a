"""Rendering: what the generated headers say, for the shipped specs and the test fixtures."""

import functools
import os
import re
import unittest

from gaphys_gen import render
from gaphys_gen.model import load

from .support import REPO_DIR, spec_path

FIXTURES_DIR = os.path.join(REPO_DIR, "tests", "algebra", "specs")


def rendered(path: str, variant: str) -> dict[str, str]:
    """Every file of one generated library, unformatted: {file name: text}
    (made once per spec text and variant: callers only read it)."""
    with open(path, encoding="utf-8") as spec:
        return _rendered(path, variant, spec.read())


@functools.lru_cache(maxsize=None)
def _rendered(path: str, variant: str, spec_text: str) -> dict[str, str]:  # spec_text: the cache key
    algebra = load(path)
    files = render.render(algebra, variant, algebra.name, "gaphys-gen generate ...", None)
    return {os.path.basename(name): text for name, text in files.items()}


def functions_of(header: str) -> list[tuple[str, str, str]]:
    """(name, parameters, body) of each function template in a kernels.hpp."""
    found = []
    for chunk in header.split("template <class T>")[1:]:
        match = re.match(r"\s*[^(]*?(\w+)\(([^)]*)\)\s*\{(.*)", chunk, re.S)
        if match:
            found.append(match.groups())
    return found


class Comments(unittest.TestCase):
    def test_no_conformal_words_outside_conformal_algebras(self):
        # Issue 16, defect 7: types.hpp said "ni as a dual plane" in every algebra.
        for variant in render.VARIANTS:
            for name, text in rendered(spec_path("e3ga"), variant).items():
                leaks = re.findall(r".*\b(?:ni|c3ga)\b.*", text)
                self.assertEqual(leaks, [], f"e3ga {variant} {name}")


class KernelParameters(unittest.TestCase):
    def test_unused_parameters_are_marked(self):
        # Issue 16, defect 6: pga3d norm2(point) is the constant 1 (the point's
        # e123 = 1; the other blades square to 0) and read nothing of its
        # argument, which -Werror builds reject.
        specs = [spec_path("e3ga"), spec_path("c3ga"), spec_path("pga3d")] + [
            os.path.join(FIXTURES_DIR, name) for name in sorted(os.listdir(FIXTURES_DIR))]
        checked = 0
        for path in specs:
            for name, params, body in functions_of(rendered(path, "optimized")["kernels.hpp"]):
                for unused, letter in re.findall(r"(\[\[maybe_unused\]\] )?(?:const basic_\w+<T>& |T )(\w+)", params):
                    used = re.search(rf"\b{letter}\b", body) is not None
                    self.assertNotEqual(bool(unused), used, f"{os.path.basename(path)}: {name}({params})")
                    checked += 1
        self.assertGreater(checked, 500)
        kernels = rendered(spec_path("pga3d"), "optimized")["kernels.hpp"]
        self.assertTrue("T norm2([[maybe_unused]] const basic_normalized_point<T>& a)" in kernels)


class Accessors(unittest.TestCase):
    def test_named_as_declared(self):
        # Issue 16, defect 8: a line declared with e3^e1 has e31(), which
        # returns the e3^e1 coefficient (minus that of e1^e3).
        types = rendered(spec_path("pga3d"), "optimized")["types.hpp"]
        for line in ("basic_line(T e01, T e02, T e03, T e23, T e31, T e12)",
                     "constexpr T e31() const { return c[4]; }",
                     "basic_normalized_point(T e032, T e013, T e021)",
                     "static constexpr T e123() { return T(1); }"):
            self.assertTrue(line in types, line)
        self.assertEqual(re.findall(r".*\b(?:e13|e023|e012)\b.*", types), [])

    def test_shipped_specs_keep_their_accessors(self):
        # Their blades are all declared in canonical order, so names are as before.
        for name in ("e3ga", "c3ga"):  # pga3d declares ganja's orientations (e31, e032)
            algebra = load(spec_path(name))
            for named in algebra.types:
                for coordinate in named.coordinates:
                    self.assertEqual(coordinate.accessor, coordinate.blade.accessor, f"{name} {named.name}")


class BannerText(unittest.TestCase):
    def test_control_characters_and_a_last_backslash_are_escaped(self):
        # A newline would end the // comment; a last backslash would join the next line to it.
        self.assertEqual(render.comment_safe("a\nb\tc"), "a\\x0ab\\x09c")
        self.assertEqual(render.comment_safe("dir\\"), "dir\\x5c")
        self.assertEqual(render.comment_safe("a\\b é"), "a\\b é")


if __name__ == "__main__":
    unittest.main()


def load_text_spec(text: str, directory: str) -> str:
    path = os.path.join(directory, "spec.ga")
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(text)
    return path


class ClosedFormExp(unittest.TestCase):
    def test_exp_into_mv_builds_its_coefficients(self):
        # exp of a bivector type that no named type holds with the scalar
        # returned basic_mv<T>(c, k a), a constructor no mv has (found by the
        # ccga tests); in a dense and in a sparse algebra.
        import tempfile
        with tempfile.TemporaryDirectory() as directory:
            for basis, metric in (("e1 e2 e3", "e1.e1 = 1, e2.e2 = 1, e3.e3 = 1"),
                                  ("e1 e2 e3 e4 e5 e6", "e1.e1 = 1, e2.e2 = 1")):
                path = load_text_spec(f"algebra t\nbasis {basis}\nmetric {metric}\ntype biv = e1^e2\n"
                                      "function exp(biv)\n", directory)
                kernels = rendered(path, "optimized")["kernels.hpp"]
                exp = next(body for name, _, body in functions_of(kernels) if name == "exp")
                self.assertIn("exp_of_square", exp)
                self.assertNotIn("basic_mv<T>(", exp)
                self.assertIn("from_blades" if len(basis.split()) > 5 else "r.c[", exp)


class SparseAlgebras(unittest.TestCase):
    def test_no_product_tables_above_five_dimensions(self):
        tables = rendered(spec_path("ccga"), "optimized")["tables.hpp"]
        self.assertIn("gaphys::ga::bitwise_product gp_table", tables)
        self.assertNotIn("_offsets[] = {\n    0, ", tables.split("orthogonal_squares")[0])
        self.assertNotIn("product_term", tables)
        self.assertLess(len(tables), 20_000)

    def test_no_recording_above_five_dimensions(self):
        # Profiled mv kernels key on one bit per blade: 32 at most.
        self.assertIn("on_call(call, const X&...) {}", rendered(spec_path("c4ga"), "instrumented")["recording.hpp"])

    def test_a_profile_is_refused_above_five_dimensions(self):
        from gaphys_gen.errors import UsageError
        algebra = load(spec_path("c4ga"))
        with self.assertRaisesRegex(UsageError, "at most 5"):
            render.render(algebra, "optimized", "c4ga", "gaphys-gen ...", None, profile_path="c4ga.json")


class Batches(unittest.TestCase):
    def test_every_named_type_has_a_batch(self):
        for path in (spec_path("e3ga"), spec_path("c3ga"), spec_path("pga3d")):
            algebra = load(path)
            for variant in render.VARIANTS:
                header = rendered(path, variant)["batch.hpp"]
                for named in algebra.types:
                    self.assertIn(f"using {named.name}_batch = basic_{named.name}<batch<W>>;", header,
                                  f"{algebra.name} {variant}")
                for alias in algebra.aliases:
                    self.assertIn(f"using {alias}_batch =", header, f"{algebra.name} {variant}")

    def test_kernels_that_cannot_run_on_packs_run_lane_by_lane(self):
        # A polynomial runs on the packs; exp, log and the mv path run lane by
        # lane; a kernel with an mv result refuses batches.
        kernels = {name: body for name, _, body in functions_of(rendered(spec_path("c3ga"), "optimized")["kernels.hpp"])
                   if name in ("exp", "log")}
        self.assertTrue(kernels)
        for name, body in kernels.items():
            self.assertIn("lanewise", body, name)
        for variant in ("reference", "instrumented"):
            for name, params, body in functions_of(rendered(spec_path("c3ga"), variant)["kernels.hpp"]):
                self.assertTrue("lanewise" in body or "no batch form" in body, f"{variant} {name}({params})")
        optimized = functions_of(rendered(spec_path("c3ga"), "optimized")["kernels.hpp"])
        polynomials = [body for name, params, body in optimized if "gp" == name and "basic_mv<T> r;" in body]
        self.assertTrue(polynomials)
        for body in polynomials:
            self.assertIn("no batch form", body)


class BuildDeclaresEveryFile(unittest.TestCase):
    def test_gaphys_add_algebra_names_the_files_the_generator_writes(self):
        # cmake/GaphysGenerate.cmake declares the generated headers to the
        # build (Ninja rebuilds what includes them only if it knows who writes
        # them); a file written but not named there would be stale one build
        # long, a name never written would make every build run the generator.
        with open(os.path.join(REPO_DIR, "cmake", "GaphysGenerate.cmake"), encoding="utf-8") as cmake:
            match = re.search(r"foreach\(header IN ITEMS ([^)]*)\)", cmake.read())
        self.assertIsNotNone(match)
        declared = {name.replace("${namespace}", "{ns}") + ".hpp" for name in match.group(1).split()}
        for variant in ("reference", "instrumented", "optimized"):
            for sparse in (False, True):
                written = {name for _, name in render.files_for(variant, sparse)}
                self.assertEqual(declared, written, (variant, sparse))
        # And render writes exactly those (the namespace in place of {ns}).
        self.assertEqual(
            set(rendered(spec_path("e3ga"), "optimized")),
            {name.replace("{ns}", "e3ga") for name in declared},
        )
