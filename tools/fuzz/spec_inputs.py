"""Spec inputs: the shipped specs mutated, random specs from the grammar, token soup
and a few hand-picked extremes. Every function takes the input's own Random."""

import glob
import os
import random

from mutate import mutate_bytes, mutate_lines, mutate_tokens, tokens

ROOT = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", ".."))


def _read(path: str) -> str:
    with open(path, encoding="utf-8") as handle:
        return handle.read()


SHIPPED = [_read(path) for path in sorted(glob.glob(os.path.join(ROOT, "specs", "*.ga")))]

KEYWORDS = ["algebra", "basis", "metric", "scalar", "representation", "type", "alias", "constant", "function",
            "float", "double", "direct", "dual"]
FUNCTIONS = ["gp", "op", "lc", "rc", "scp", "add", "sub", "meet", "join", "apply", "neg", "reverse", "involute",
             "conjugate", "dual", "undual", "norm2", "inverse", "exp", "log", "smul", "norm", "unit"]
PUNCTUATION = ["=", ",", "^", "(", ")", ".", "*", "+", "-", "/", "\n", " ", "\t", "\r", "\r\n", "#", ";", "$", "@"]
# Names the generated C++ reserves or that look like something else.
ODD_NAMES = ["class", "int", "mv", "real", "std", "dimension", "basic_x", "a__b", "_", "e", "e0", "e10", "e1e2",
             "nan", "inf", "NaN", "Infinity", "true", "é", "α", "e\u0301", "\u200b", "\ufeff", "𝑒1", "ǅ"]
# Numbers at the edges of double and of Python's int parsing. "1e999999999" is 10 ** 10 ** 9
# written in 11 characters.
EXTREME_NUMBERS = ["0", "-0", "0.0", "00", "1", "-1", "0.5", "1/3", "1/0", "0/0", "-1/-2", "2.5e-1",
                   "1e308", "1e309", "1e400", "-1e400", "1e-400", "4.9e-324", "1e-308", "1.7976931348623157e308",
                   "9007199254740992", "1/9007199254740992", "-9007199254740991/3", "0.000000000000001",
                   "9007199254740993", "18446744073709551617", "340282366920938463463374607431768211457",
                   "1e999999999", "1e-999999999", "1" * 5000, "0." + "0" * 4999 + "1", "1.", ".5", "1e", "1e+",
                   "1_000", "0x10", "１", "٣", "1e4300", "1/" + "9" * 400]


def names_in(text: str) -> list[str]:
    return sorted({t for t in tokens(text) if t.isidentifier()})


def vocabulary(text: str) -> list[str]:
    return KEYWORDS + FUNCTIONS + PUNCTUATION + ODD_NAMES + EXTREME_NUMBERS + names_in(text)


def mutated(rng: random.Random) -> tuple[str, bytes]:
    """A shipped spec with 1 to about 6 token and line changes."""
    text = rng.choice(SHIPPED)
    words = vocabulary(text)
    for _ in range(1 + min(int(rng.expovariate(0.7)), 5)):
        if rng.random() < 0.2:
            text = mutate_lines(rng, text)
        else:
            text = "".join(mutate_tokens(rng, tokens(text), words))
    return "mutated", text.encode("utf-8", "surrogatepass")


def number_swapped(rng: random.Random) -> tuple[str, bytes]:
    """A shipped spec with some of its numbers replaced by extreme ones."""
    items = tokens(rng.choice(SHIPPED))
    numbers = [i for i, t in enumerate(items) if t[0].isdigit()]
    for i in rng.sample(numbers, min(len(numbers), rng.randint(1, 3))):
        items[i] = rng.choice(EXTREME_NUMBERS)
    return "numbers", "".join(items).encode()


def byte_level(rng: random.Random) -> tuple[str, bytes]:
    data = rng.choice(SHIPPED).encode()
    for _ in range(rng.randint(1, 4)):
        data = mutate_bytes(rng, data)
    return "bytes", data


def soup(rng: random.Random) -> tuple[str, bytes]:
    """Random tokens of the language, mostly separated by spaces and newlines."""
    words = vocabulary(rng.choice(SHIPPED))
    parts = []
    for _ in range(rng.randint(1, 60)):
        parts.append(rng.choice(words))
        parts.append(rng.choice((" ", " ", " ", "\n", "")))
    return "soup", "".join(parts).encode()


def _blade(rng: random.Random, basis: list[str]) -> str:
    if not basis or rng.random() < 0.1:
        return "1"
    factors = rng.sample(basis, rng.randint(1, len(basis)))
    return "^".join(factors)


# The largest and smallest magnitudes a spec may write: kernels multiply many of them.
EDGE_NUMBERS = ["9007199254740992", "-9007199254740992", "1/9007199254740992", "9007199254740991/9007199254740992"]


def _number(rng: random.Random, edge: bool = False) -> str:
    if edge or rng.random() < 0.05:
        return rng.choice(EDGE_NUMBERS if edge else EXTREME_NUMBERS)
    return rng.choice(["1", "-1", "0", "2", "1/2", "-1/2", "0.5", "3", "-2"])


def grammar(rng: random.Random) -> tuple[str, bytes]:
    """A random spec that follows the grammar, so that it reaches validation and expansion:
    random basis, (non-diagonal, degenerate) metric, types, aliases, constants and functions."""
    basis = rng.sample(["e1", "e2", "e3", "e4", "e0", "no", "ni", "x", "y"], rng.choice((1, 2, 3, 3, 4, 4, 5, 5, 6)))
    lines = [f"algebra {rng.choice(['g', 'pga', 'sta', 'alg'])}", "basis " + " ".join(basis)]
    edge = rng.random() < 0.1  # every metric value at the edge of the allowed range
    entries = [f"{v}.{v} = {_number(rng, edge)}" for v in basis if rng.random() < 0.9]
    if len(basis) > 1:
        for _ in range(rng.randint(0, 2)):  # off the diagonal, as no.ni in c3ga
            a, b = rng.sample(basis, 2)
            entries.append(f"{a}.{b} = {_number(rng, edge)}")
    if entries:
        lines.append("metric " + ", ".join(entries))
    if rng.random() < 0.5:
        lines.append(f"scalar {rng.choice(['float', 'double'])}")
    types = [f"t{i}" for i in range(rng.randint(1, 5))]
    for name in types:
        coordinates, blades = [], set()
        for _ in range(rng.randint(1, 6)):
            blade = _blade(rng, basis)
            if frozenset(blade.split("^")) not in blades or rng.random() < 0.05:
                blades.add(frozenset(blade.split("^")))
                coordinates.append(blade + (f" = {_number(rng, edge)}" if rng.random() < 0.15 else ""))
        lines.append(f"type {name} = " + ", ".join(coordinates))
    if rng.random() < 0.3:
        lines.append(f"alias a{rng.randint(0, 3)} = {rng.choice(types)}")
    if rng.random() < 0.4:
        lines.append(f"constant k = {_number(rng)} * {_blade(rng, basis)} - {_blade(rng, basis)}")
    for _ in range(rng.randint(0, 4)):
        function = rng.choice(FUNCTIONS[:19])
        arity = 2 if FUNCTIONS.index(function) < 9 else 1
        arguments = ", ".join(rng.choice(types) for _ in range(arity if rng.random() < 0.95 else 3 - arity))
        lines.append(f"function {function}({arguments})")
    return "grammar", ("\n".join(lines) + "\n").encode()


def extreme(rng: random.Random) -> tuple[str, bytes]:
    """Empty, truncated, very long or deeply nested inputs."""
    text = rng.choice(SHIPPED)
    n = rng.choice((10, 1000, 2000))  # 2000 metric entries already take a tenth of the limit
    choices = [
        "",
        " \n\t\n",
        "# only a comment",
        text[: rng.randrange(len(text) + 1)],
        text.replace("\n", "\r\n"),
        text.replace("\n", "\r"),
        text + "function gp(" + "(" * n + "\n",
        text + "type deep = " + "e1^" * n + "e2\n",
        text + "type wide = " + ", ".join(["e1"] * n) + "\n",
        text + "constant total = " + " + ".join(["1"] * n) + "\n",
        text + "constant minus = " + "- " * n + "1\n",
        text + "metric " + ", ".join(["e1.e1 = 1"] * n) + "\n",
        text + ",\n" * n,
        "basis " + " ".join(f"v{i}" for i in range(n)) + "\nalgebra big\n",
    ]
    return "extreme", rng.choice(choices).encode()


def make(rng: random.Random) -> tuple[str, bytes]:
    roll = rng.random()
    if roll < 0.45:
        return mutated(rng)
    if roll < 0.55:
        return number_swapped(rng)
    if roll < 0.70:
        kind, data = grammar(rng)
        if rng.random() < 0.3:
            text = "".join(mutate_tokens(rng, tokens(data.decode()), vocabulary(data.decode())))
            return "grammar+mutated", text.encode()
        return kind, data
    if roll < 0.80:
        return soup(rng)
    if roll < 0.93:
        return byte_level(rng)
    return extreme(rng)
