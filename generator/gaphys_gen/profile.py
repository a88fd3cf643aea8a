"""Profiles: which coefficients were really nonzero in each library call.

A profile is JSON written by the instrumented variant (and by `merge`):

    {"format": "gaphys-profile", "version": 1,
     "algebra": "c3ga", "spec_hash": "<sha256 of the spec>", "generator_version": "0.1.0",
     "entries": [{"function": "gp", "arguments": [1054, 62], "result": 63, "count": 120000}, ...]}

`arguments` and `result` are bitmaps over canonical blade indices (bit i set:
coefficient i was nonzero). Loading validates everything and raises
ProfileError("file:line:column: message") on the first problem, at the value
that is wrong; nothing is generated from a profile that does not load.
"""

import bisect
import json
import os
import re
from dataclasses import dataclass, field

from . import VERSION
from .errors import UsageError
from .model import Algebra

FORMAT = "gaphys-profile"
FORMAT_VERSION = 1
# Counts are exact integers, but bounded: Python prints no integer of over 4300
# digits, and a sum of huge counts would make a profile that cannot be written.
# The recorder counts in 64 bits, so 2^128 leaves room for any number of merges.
MAX_COUNT = 2**128

# Recorded functions and how many multivector arguments each takes.
RECORDED_ARITY = {
    **{f: 2 for f in ("gp", "op", "lc", "rc", "scp", "add", "sub", "meet", "join", "apply")},
    **{f: 1 for f in ("neg", "smul", "reverse", "involute", "conjugate", "dual", "undual",
                      "norm2", "inverse", "general_inverse", "exp", "log")},
}


class ProfileError(UsageError):
    """A profile that cannot be used, as `file: message`."""


@dataclass(frozen=True)
class Entry:
    function: str
    arguments: tuple[int, ...]
    result: int
    count: int

    @property
    def key(self) -> tuple:
        return (self.function, self.arguments, self.result)


@dataclass(frozen=True)
class Profile:
    algebra: str
    spec_hash: str
    generator_version: str
    entries: tuple[Entry, ...]  # sorted, one per (function, arguments, result)

    @property
    def total_calls(self) -> int:
        return sum(e.count for e in self.entries)


def _combine(entries, path: str) -> tuple[Entry, ...]:
    """One entry per key, counts added; sorted for deterministic output."""
    counts: dict[tuple, int] = {}
    for e in entries:
        counts[e.key] = counts.get(e.key, 0) + e.count
        _require(counts[e.key] < MAX_COUNT, path, f"{e.function} {list(e.arguments)}: 2^128 calls or more")
    return tuple(Entry(f, a, r, c) for (f, a, r), c in sorted(counts.items()))


def _require(condition: bool, path: str, message: str) -> None:
    if not condition:
        raise ProfileError(f"{path}: {message}")


def _is_int(value) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


_SPACE = re.compile(r"[ \t\n\r]*")


@dataclass
class _Place:
    """Where a JSON value starts in the text, and where its members' values
    start (an object's by key, an array's by index)."""

    offset: int
    members: dict = field(default_factory=dict)


def _places(text: str) -> _Place:
    """The places of the values of text, which json.loads has read: each
    member of the top object, each entry of "entries", each of its members
    and each bitmap of its arguments."""
    decoder = json.JSONDecoder()

    def skip(at: int) -> int:
        return _SPACE.match(text, at).end()

    def value(at: int, depth: int) -> tuple[_Place, int]:
        place = _Place(at)
        if depth < 4 and text[at] in "{[":
            closing, at = ("}" if text[at] == "{" else "]"), skip(at + 1)
            index = 0
            while text[at] != closing:
                key = index
                if closing == "}":
                    key, at = decoder.raw_decode(text, at)
                    at = skip(skip(at) + 1)  # the colon
                place.members[key], at = value(at, depth + 1)
                at = skip(at)
                if text[at] == ",":
                    at = skip(at + 1)
                index += 1
            return place, at + 1
        return place, decoder.raw_decode(text, at)[1]

    return value(skip(0), 0)[0]


def _line_starts(text: str) -> list[int]:
    return [0] + [match.end() for match in re.finditer("\n", text)]


def _locate(starts: list[int], path: str, offset: int) -> str:
    line = bisect.bisect_right(starts, offset)
    return f"{path}:{line}:{offset - starts[line - 1] + 1}"


def _shown(value) -> str:
    """A value of the profile as its JSON reads (true, "gp", 1.5), not as Python's repr."""
    return json.dumps(value)


def parse(text: str, path: str, algebra: Algebra | None = None) -> Profile:
    try:
        data = json.loads(text)
    except json.JSONDecodeError as error:
        raise ProfileError(f"{path}:{error.lineno}:{error.colno}: malformed JSON: {error.msg}") from error
    except RecursionError as error:
        raise ProfileError(f"{path}: malformed JSON: nested too deeply") from error
    except ValueError as error:  # Python's int refuses numbers of over 4300 digits
        raise ProfileError(f"{path}: malformed JSON: a number has too many digits") from error

    def require(condition: bool, keys: tuple, message: str) -> None:
        """Raises at file:line:column of the value at keys (of the nearest that
        exists), found only then: a profile that loads is not walked again."""
        if condition:
            return
        place = _places(text)
        for key in keys:
            if key not in place.members:
                break
            place = place.members[key]
        raise ProfileError(f"{_locate(_line_starts(text), path, place.offset)}: {message}")

    require(isinstance(data, dict), (), "a profile is a JSON object")
    require(data.get("format") == FORMAT, ("format",), f"not a gaphys profile (\"format\" must be \"{FORMAT}\")")
    require(_is_int(data.get("version")) and data["version"] == FORMAT_VERSION, ("version",),  # not true, not 1.0
            f"profile format version {_shown(data.get('version'))} is not supported (expected {FORMAT_VERSION})")
    for key in ("algebra", "spec_hash", "generator_version"):
        require(isinstance(data.get(key), str), (key,), f"\"{key}\" must be a string")
    require(isinstance(data.get("entries"), list), ("entries",), "\"entries\" must be a list")
    unknown = sorted(set(data) - {"format", "version", "algebra", "spec_hash", "generator_version", "entries"})
    require(not unknown, tuple(unknown[:1]), f"unknown key(s): {', '.join(unknown)}")
    if algebra is not None:
        require(data["algebra"] == algebra.name, ("algebra",),
                f"profile is for algebra {_shown(data['algebra'])}, not {_shown(algebra.name)}")
        require(data["spec_hash"] == algebra.spec_hash, ("spec_hash",),
                f"profile was recorded with another version of the spec (spec_hash {data['spec_hash'][:12]}..., "
                f"current {algebra.spec_hash[:12]}...): record it again")
    limit = 1 << (algebra.blade_count if algebra is not None else 32)
    entries = []
    for number, raw in enumerate(data["entries"]):
        where = f"entry {number}"
        require(isinstance(raw, dict), ("entries", number), f"{where}: must be an object")
        require(set(raw) == {"function", "arguments", "result", "count"}, ("entries", number),
                f"{where}: needs exactly the keys function, arguments, result, count")
        function = raw["function"]
        require(isinstance(function, str) and function in RECORDED_ARITY, ("entries", number, "function"),
                f"{where}: unknown function {_shown(function)}")
        arguments = raw["arguments"]
        require(isinstance(arguments, list) and len(arguments) == RECORDED_ARITY[function],
                ("entries", number, "arguments"),
                f"{where}: {function} takes {RECORDED_ARITY[function]} bitmap argument(s)")
        bitmaps = [(("arguments", k), b) for k, b in enumerate(arguments)] + [(("result",), raw["result"])]
        for keys, bitmap in bitmaps:
            require(_is_int(bitmap), ("entries", number, *keys),
                    f"{where}: {keys[0]} bitmap {_shown(bitmap)} is not an integer")
            require(0 <= bitmap < limit, ("entries", number, *keys),
                    f"{where}: {keys[0]} bitmap {bitmap} has bits outside the algebra's {limit.bit_length() - 1} "
                    f"blades (0 to {limit - 1})")
        require(_is_int(raw["count"]) and raw["count"] >= 0, ("entries", number, "count"),
                f"{where}: count must be a non-negative integer, not {_shown(raw['count'])}")
        require(raw["count"] < MAX_COUNT, ("entries", number, "count"), f"{where}: count of 2^128 or more")
        entries.append(Entry(function, tuple(arguments), raw["result"], raw["count"]))
    return Profile(data["algebra"], data["spec_hash"], data["generator_version"], _combine(entries, path))


def load(path: str, algebra: Algebra | None = None) -> Profile:
    try:
        with open(path, encoding="utf-8") as handle:
            text = handle.read()
    except OSError as error:
        raise ProfileError(f"{path}: cannot read: {error.strerror}") from error
    except UnicodeDecodeError as error:
        raise ProfileError(f"{path}: not UTF-8 text") from error
    return parse(text, path, algebra)


def dumps(profile: Profile) -> str:
    """Deterministic JSON, one entry a line: same profile, same bytes."""
    header = {"format": FORMAT, "version": FORMAT_VERSION, "algebra": profile.algebra,
              "spec_hash": profile.spec_hash, "generator_version": profile.generator_version}
    lines = [f"  {json.dumps(key)}: {json.dumps(value)}," for key, value in header.items()]
    entries = [
        "    " + json.dumps({"function": e.function, "arguments": list(e.arguments),
                             "result": e.result, "count": e.count})
        for e in profile.entries
    ]
    body = "[\n" + ",\n".join(entries) + "\n  ]" if entries else "[]"
    return "{\n" + "\n".join(lines) + f'\n  "entries": {body}\n' + "}\n"


def merge(profiles: list[tuple[str, Profile]]) -> Profile:
    """Adds counts; every profile must be for the same algebra and spec."""
    _, first = profiles[0]
    for path, other in profiles[1:]:
        _require(other.algebra == first.algebra and other.spec_hash == first.spec_hash, path,
                 f"cannot merge: profile is for {other.algebra} (spec {other.spec_hash[:12]}...), "
                 f"the first for {first.algebra} (spec {first.spec_hash[:12]}...)")
    entries: tuple[Entry, ...] = ()
    for path, other in profiles:  # one at a time, to name the profile that overflows a count
        entries = _combine(entries + other.entries, path)
    return Profile(first.algebra, first.spec_hash, VERSION, entries)


def select(profile: Profile, coverage: float) -> list[tuple[str, tuple[int, ...], int]]:
    """The hottest (function, argument bitmaps) combinations that together cover
    at least `coverage` of all calls: [(function, arguments, calls)], hottest first."""
    calls: dict[tuple, int] = {}
    for e in profile.entries:
        calls[(e.function, e.arguments)] = calls.get((e.function, e.arguments), 0) + e.count
    ranked = sorted(calls.items(), key=lambda item: (-item[1], item[0]))
    total, covered, chosen = sum(calls.values()), 0, []
    for (function, arguments), count in ranked:
        if total == 0 or covered >= coverage * total or count == 0:
            break
        chosen.append((function, arguments, count))
        covered += count
    return chosen


def blade_list(algebra: Algebra, bitmap: int) -> str:
    names = [b.name for b in algebra.blades if bitmap >> b.index & 1]
    return "{" + ", ".join(names) + "}" if names else "{}"


def report(profile: Profile, algebra: Algebra, coverage: float, top: int = 20) -> str:
    """A readable table of the hot combinations, and what an optimized build
    selected at `coverage` would still send to the generic fallback."""
    from .expand import SPECIALIZABLE, expand_profile, worth_a_kernel

    total = profile.total_calls
    chosen = select(profile, coverage)
    # Functions without mv kernels (not in SPECIALIZABLE) count as chosen:
    # their recorded calls are straight-line named-type code or made of
    # specialized calls. Sums in an algebra where no kernel pays
    # (expand.worth_a_kernel) take the dense generic sum on purpose and are
    # counted apart. Every other call goes to its own kernel, else to a kernel
    # made for a superset of its bitmaps, else to the generic path.
    kernels = expand_profile(algebra, chosen)
    with_kernel = {(k.function, k.argument_bits) for k in kernels}
    made = {(function, arguments) for function, arguments, _ in chosen
            if function not in SPECIALIZABLE or (function, arguments) in with_kernel}
    calls: dict[tuple, int] = {}
    for e in profile.entries:
        calls[(e.function, e.arguments)] = calls.get((e.function, e.arguments), 0) + e.count
    covered = sum(count for key, count in calls.items() if key in made)
    dense = sum(count for (function, _), count in calls.items()
                if function in SPECIALIZABLE and not worth_a_kernel(algebra, function))
    superset = sum(count for (function, arguments), count in calls.items()
                   if (function, arguments) not in made and worth_a_kernel(algebra, function)
                   and any(k.function == function and k.serves(arguments) for k in kernels))
    fallback = total - covered - dense - superset
    lines = [
        f"profile of {profile.algebra}: {total} calls, {len(profile.entries)} entries",
        f"specialized at coverage {coverage}: {len(made)} combinations, "
        f"{covered} calls; served by a superset's kernel: {superset} calls; "
        + (f"dense generic sums (no sum kernel pays in this algebra): {dense} calls; " if dense else "")
        + f"generic fallback: {fallback} calls ({100.0 * fallback / total if total else 0.0:.3f}%)",
        "",
        "| calls | share | function | arguments |",
        "|---:|---:|---|---|",
    ]
    for function, arguments, count in chosen[:top]:
        shown = " x ".join(blade_list(algebra, a) for a in arguments)
        lines.append(f"| {count} | {100.0 * count / total:.2f}% | {function} | {shown} |")
    if len(chosen) > top:
        lines.append(f"| ... | | {len(chosen) - top} more | |")
    return "\n".join(lines) + "\n"


def write(path: str, profile: Profile) -> None:
    """Writes a profile atomically."""
    from .output import write_all

    write_all(os.path.dirname(os.path.abspath(path)), {os.path.basename(path): dumps(profile)})
