"""Profile inputs: the committed profiles with their JSON values changed, entries
added, removed and duplicated, values nested deeply, and the text itself mutated.

Most inputs keep only a few of the committed entries, which keeps them small and
fast; the profile's algebra is the one it was recorded for, so the loader's
later checks (bits, counts, functions) are reached, not only the spec hash.
"""

import copy
import json
import os
import random

from mutate import mutate_bytes, mutate_tokens, tokens

ROOT = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", ".."))
ALGEBRAS = ("e3ga", "c3ga")


def _read(algebra: str) -> dict:
    with open(os.path.join(ROOT, "profiling", "profiles", f"{algebra}.json"), encoding="utf-8") as handle:
        return json.load(handle)


COMMITTED = {algebra: _read(algebra) for algebra in ALGEBRAS}

# Raw JSON text: numbers past double's range, past Python's 4300-digit integers
# and around 2^64 and 2^128, and the non-standard constants Python's json accepts.
RAW = ["1e400", "-1e400", "1e-400", "-0", "-0.0", "NaN", "Infinity", "-Infinity", "1E2", "9" * 400, "9" * 4300,
       "9" * 4301, str(2**128 - 1), str(2**128),
       "18446744073709551616", "9223372036854775808", "-9223372036854775809"]
VALUES = [None, True, False, 0, 1, -1, 2, 1.5, -0.0, "", "gp", "14", [], {}, [1], {"a": 1}, 2**31, 2**32 - 1, 2**32,
          2**63 - 1, 2**63, 2**64 + 1, 10**30, "e3ga", "c3ga", "gaphys-profile", "0" * 64, "\u00e9", "\ud800"]
FUNCTIONS = ["gp", "apply", "reverse", "smul", "general_inverse", "exp", "log", "cross", "GP", "", "gp "]


def _value(rng: random.Random, raw: list[str]):
    """A value for a field: a plain wrong one, or a placeholder later replaced by raw text."""
    if rng.random() < 0.3:
        raw.append(rng.choice(RAW))
        return f"@RAW{len(raw) - 1}@"
    return copy.deepcopy(rng.choice(VALUES))


def _nested(rng: random.Random, value, raw: list[str]) -> str:
    """The value inside many lists or objects, as raw text: json.dumps itself stops at
    about a thousand levels."""
    depth = rng.choice((2, 50, 900, 990, 1000, 5000, 100000))
    opening, closing = ("[", "]") if rng.random() < 0.5 else ('{"k": ', "}")
    raw.append(opening * depth + json.dumps(value) + closing * depth)
    return f"@RAW{len(raw) - 1}@"


def _bitmap(rng: random.Random, algebra: str) -> int:
    blades = 8 if algebra == "e3ga" else 32
    return rng.choice([0, 1, (1 << blades) - 1, 1 << blades, -1, rng.getrandbits(blades), rng.getrandbits(blades + 1)])


def mutate_document(rng: random.Random, data: dict, algebra: str, raw: list[str]) -> None:
    """One change to the parsed profile: a header value, a key, or an entry."""
    entries = data.get("entries") if isinstance(data.get("entries"), list) else None
    roll = rng.randrange(10)
    if roll == 0:
        data[rng.choice(list(data) or ["format"])] = _value(rng, raw)
    elif roll == 1 and data:
        del data[rng.choice(list(data))]
    elif roll == 2:
        data[rng.choice(["extra", "Format", "entries ", "spec_hash"])] = _value(rng, raw)
    elif roll == 3:
        other = ALGEBRAS[1 - ALGEBRAS.index(algebra)]
        data[rng.choice(["algebra", "spec_hash"])] = COMMITTED[other][rng.choice(["algebra", "spec_hash"])]
    elif roll == 4:
        key = rng.choice(list(data) or ["format"])
        data[key] = _nested(rng, data.get(key), raw)
    elif entries is None or not entries:
        data["entries"] = [copy.deepcopy(e) for e in rng.sample(COMMITTED[algebra]["entries"], 3)]
    elif roll == 5:
        entries.extend(copy.deepcopy(rng.choice(entries)) for _ in range(rng.randint(1, 4)))
    else:
        mutate_entry(rng, rng.choice(entries), algebra, raw)


def mutate_entry(rng: random.Random, entry, algebra: str, raw: list[str]) -> None:
    if not isinstance(entry, dict):
        return
    key = rng.choice(["function", "arguments", "result", "count"])
    roll = rng.randrange(6)
    if roll == 0:
        entry.pop(key, None)
    elif roll == 1:
        entry[rng.choice(["extra", "Count"])] = 1
    elif key == "function":
        entry[key] = rng.choice(FUNCTIONS) if roll < 4 else _value(rng, raw)
    elif key == "arguments" and roll < 4:
        entry[key] = [_bitmap(rng, algebra) for _ in range(rng.choice((0, 1, 2, 2, 3)))]
    elif key == "result" and roll < 4:
        entry[key] = _bitmap(rng, algebra)
    elif key == "count" and roll < 4:
        entry[key] = rng.choice([0, -1, 2**63, 2**64, 10**30, 10**400, 1, -(2**63)])
    elif roll == 4:
        entry[key] = _value(rng, raw)
    else:
        entry[key] = _nested(rng, entry.get(key), raw)


def _text(rng: random.Random, data, raw: list[str]) -> str:
    text = json.dumps(data, indent=rng.choice((None, 2)), ensure_ascii=rng.random() < 0.5)
    # Last first: a nested value's raw text can hold the placeholders made before it.
    for i in reversed(range(len(raw))):
        text = text.replace(f'"@RAW{i}@"', raw[i])
    return text


def structured(rng: random.Random) -> tuple[str, bytes]:
    """A committed profile, usually cut down to a few entries, with 1 to 4 changes."""
    algebra = rng.choice(ALGEBRAS)
    data = copy.deepcopy(COMMITTED[algebra])
    if rng.random() < 0.8:
        data["entries"] = rng.sample(data["entries"], rng.randint(0, 6))
    raw: list[str] = []
    for _ in range(rng.randint(1, 4)):
        mutate_document(rng, data, algebra, raw)
    return f"{algebra}-structured", _text(rng, data, raw).encode("utf-8", "surrogatepass")


def duplicate_keys(rng: random.Random) -> tuple[str, bytes]:
    """JSON objects with a key twice: Python keeps the last, which must still be checked."""
    algebra = rng.choice(ALGEBRAS)
    data = copy.deepcopy(COMMITTED[algebra])
    data["entries"] = rng.sample(data["entries"], 2)
    text = json.dumps(data)
    key = rng.choice(["count", "result", "function", "format", "version", "entries"])
    value = json.dumps(rng.choice([-1, "x", [], 2**64, None]))
    return f"{algebra}-duplicate-key", text.replace(f'"{key}": ', f'"{key}": {value}, "{key}": ', 1).encode()


def textual(rng: random.Random) -> tuple[str, bytes]:
    """Token and byte mutations of a small profile's text."""
    algebra = rng.choice(ALGEBRAS)
    data = copy.deepcopy(COMMITTED[algebra])
    data["entries"] = rng.sample(data["entries"], rng.randint(0, 4))
    text = json.dumps(data, indent=2)
    words = ["{", "}", "[", "]", ",", ":", '"', "null", "true", "-", "1e400", "NaN", "9" * 5000, "\\u0000", "\\"]
    for _ in range(rng.randint(1, 3)):
        text = "".join(mutate_tokens(rng, tokens(text), words))
    data = text.encode()
    for _ in range(rng.choice((0, 0, 1, 2))):
        data = mutate_bytes(rng, data)
    return f"{algebra}-text", data


def soup(rng: random.Random) -> tuple[str, bytes]:
    """Random JSON values, and a few texts that are hardly JSON at all."""
    raw: list[str] = []

    def value(depth: int):
        roll = rng.random()
        if depth > 4 or roll < 0.5:
            return _value(rng, raw)
        if roll < 0.75:
            return [value(depth + 1) for _ in range(rng.randint(0, 4))]
        return {rng.choice(["format", "entries", "count", "x"]): value(depth + 1) for _ in range(rng.randint(0, 4))}

    choices = ["", " ", "{", "[" * 100000, '{"a":' * 5000, "\ufeff{}", "\x00", "1" * 5000, "{}", "[]", "null"]
    if rng.random() < 0.3:
        return "soup", rng.choice(choices).encode()
    return "soup", _text(rng, value(0), raw).encode("utf-8", "surrogatepass")


def make(rng: random.Random) -> tuple[str, bytes]:
    roll = rng.random()
    if roll < 0.6:
        return structured(rng)
    if roll < 0.7:
        return duplicate_keys(rng)
    if roll < 0.9:
        return textual(rng)
    return soup(rng)
