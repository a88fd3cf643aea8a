"""Shared helpers: repository paths, spec snippets, and an independent multivector toolkit.

The toolkit here deliberately does not use gaphys_gen.blades: it is the
second implementation the product tables are checked against.
"""

import os
import random
from fractions import Fraction

from gaphys_gen.errors import SpecError
from gaphys_gen.model import validate
from gaphys_gen.parser import parse

REPO_DIR = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", ".."))
SPECS_DIR = os.path.join(REPO_DIR, "specs")
GENERATOR_DIR = os.path.join(REPO_DIR, "generator")


def spec_path(name: str) -> str:
    return os.path.join(SPECS_DIR, name + ".ga")


def load_text(text: str, path: str = "test.ga"):
    """Parse and validate spec text into an Algebra."""
    return validate(parse(text, path), text)


# A small valid Euclidean prelude; tests append statements to it.
E3_PRELUDE = "algebra t\nbasis e1 e2 e3\nmetric e1.e1 = 1, e2.e2 = 1, e3.e3 = 1\n"
# The conformal basis with its off-diagonal metric entry.
C3_PRELUDE = "algebra t\nbasis no e1 e2 e3 ni\nmetric e1.e1 = 1, e2.e2 = 1, e3.e3 = 1\n"


class SpecErrorAssertions:
    """Mixin for unittest.TestCase: check a SpecError's place, message and caret display."""

    def assertSpecError(
        self, text: str, line: int, column: int, fragment: str, path: str = "bad.ga", shows_source: bool = True
    ) -> SpecError:
        with self.assertRaises(SpecError) as caught:
            load_text(text, path)
        error = caught.exception
        self.assertEqual((error.location.path, error.location.line, error.location.column), (path, line, column), str(error))
        self.assertIn(fragment, error.message)
        shown = str(error).split("\n")
        self.assertEqual(shown[0], f"{path}:{line}:{column}: error: {error.message}")
        if shows_source:
            # The offending line, then a caret under the column.
            self.assertEqual(shown[1:], [text.split("\n")[line - 1], " " * (column - 1) + "^"])
        else:
            # Errors about the file as a whole (a missing statement) have no line to show.
            self.assertEqual(len(shown), 1)
        return error


# ---------------------------------------------------------------------------
# Independent multivectors: dicts {tuple of basis indices (ascending): Fraction}.
# Products in an ORTHOGONAL basis only, by literally sorting factor lists.


def _sort_factors(factors: list[int], metric_diagonal) -> tuple[Fraction, tuple[int, ...]]:
    """Bubble-sort a word of basis vectors; each swap of distinct vectors flips the sign
    (they anticommute in an orthogonal basis), each adjacent equal pair contracts to its square."""
    word = list(factors)
    coefficient = Fraction(1)
    changed = True
    while changed:
        changed = False
        for k in range(len(word) - 1):
            if word[k] > word[k + 1]:
                word[k], word[k + 1] = word[k + 1], word[k]
                coefficient = -coefficient
                changed = True
                break
            if word[k] == word[k + 1]:
                coefficient *= metric_diagonal[word[k]]
                del word[k : k + 2]
                changed = True
                break
    return coefficient, tuple(word)


def orthogonal_blade_product(kind: str, a: tuple[int, ...], b: tuple[int, ...], metric_diagonal) -> dict:
    """Product of two basis blades of an orthogonal basis, by the subset rules:
    op needs disjoint factors, lc needs a within b, rc needs b within a, scp needs a == b."""
    sa, sb = set(a), set(b)
    allowed = {
        "gp": True,
        "op": not (sa & sb),
        "lc": sa <= sb,
        "rc": sb <= sa,
        "scp": sa == sb,
    }[kind]
    if not allowed:
        return {}
    coefficient, word = _sort_factors(list(a) + list(b), metric_diagonal)
    return {word: coefficient} if coefficient else {}


def add_into(target: dict, source: dict, scale=Fraction(1)) -> dict:
    for key, value in source.items():
        total = target.get(key, Fraction(0)) + scale * value
        if total:
            target[key] = total
        else:
            target.pop(key, None)
    return target


def bilinear(blade_product, a: dict, b: dict) -> dict:
    """Extend a product of basis blades to multivectors (dicts keyed by blade)."""
    result: dict = {}
    for ka, va in a.items():
        for kb, vb in b.items():
            add_into(result, blade_product(ka, kb), va * vb)
    return result


def indices_of(bitmap: int) -> tuple[int, ...]:
    return tuple(i for i in range(bitmap.bit_length()) if bitmap >> i & 1)


def bitmap_of(indices) -> int:
    return sum(1 << i for i in indices)


def random_fraction(rng: random.Random) -> Fraction:
    return Fraction(rng.randint(-9, 9), rng.randint(1, 4))


def random_multivector(rng: random.Random, dimension: int, grades=None) -> dict:
    """Random rational multivector keyed by bitmap, optionally only of the given grades."""
    mv = {}
    for bitmap in range(1 << dimension):
        if grades is not None and bin(bitmap).count("1") not in grades:
            continue
        value = random_fraction(rng)
        if value:
            mv[bitmap] = value
    return mv


def _outer(x: dict, y: dict) -> dict:
    return bilinear(lambda a, b: orthogonal_blade_product("op", a, b, None), x, y)


class OrthogonalModel:
    """An algebra computed in an orthogonal basis, reached from the spec's basis by a change of basis.

    to_images[i] / from_images[k]: the spec's basis vector i as a combination of orthogonal
    vectors, and orthogonal vector k as a combination of the spec's vectors (dicts {(index,): value}).
    Blades map as outermorphisms (wedges of their factors' images), which is metric-free.
    """

    def __init__(self, diagonal, to_images: dict, from_images: dict):
        self.diagonal = [Fraction(v) for v in diagonal]
        self.to_images = to_images
        self.from_images = from_images

    @staticmethod
    def _map(x: dict, images: dict) -> dict:
        result: dict = {}
        for blade, value in x.items():
            image = {(): Fraction(1)}
            for i in blade:
                image = _outer(image, images[i])
            add_into(result, image, value)
        return result

    def to_orthogonal(self, x: dict) -> dict:
        return self._map({indices_of(b): v for b, v in x.items()}, self.to_images)

    def from_orthogonal(self, x: dict) -> dict:
        return {bitmap_of(k): v for k, v in self._map(x, self.from_images).items()}

    def product(self, kind: str, x: dict, y: dict) -> dict:
        """Product of multivectors {bitmap: Fraction} in the spec's basis."""
        result = bilinear(
            lambda a, b: orthogonal_blade_product(kind, a, b, self.diagonal), self.to_orthogonal(x), self.to_orthogonal(y)
        )
        return self.from_orthogonal(result)


def _identity_images(n: int) -> dict:
    return {i: {(i,): Fraction(1)} for i in range(n)}


EUCLIDEAN3_MODEL = OrthogonalModel([1, 1, 1], _identity_images(3), _identity_images(3))

# Conformal: spec basis no, e1, e2, e3, ni (indices 0..4); orthogonal e1, e2, e3, e4, e5
# (indices 0..4) with e4^2 = 1, e5^2 = -1. no = (e5 - e4)/2, ni = e4 + e5; back:
# e4 = ni/2 - no, e5 = no + ni/2.
CONFORMAL_MODEL = OrthogonalModel(
    [1, 1, 1, 1, -1],
    {
        0: {(3,): Fraction(-1, 2), (4,): Fraction(1, 2)},
        1: {(0,): Fraction(1)},
        2: {(1,): Fraction(1)},
        3: {(2,): Fraction(1)},
        4: {(3,): Fraction(1), (4,): Fraction(1)},
    },
    {
        0: {(1,): Fraction(1)},
        1: {(2,): Fraction(1)},
        2: {(3,): Fraction(1)},
        3: {(4,): Fraction(1, 2), (0,): Fraction(-1)},
        4: {(0,): Fraction(1), (4,): Fraction(1, 2)},
    },
)
