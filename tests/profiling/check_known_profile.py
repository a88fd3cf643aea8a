"""Runs record_known_calls with GAPHYS_PROFILE_DIR set and checks the profile
it writes, through the generator's own validating loader: exact entries, and
counts that grow with each run (merged into the existing file), whatever
layout the file was left in: the generator's own writer (as `gaphys-gen
merge` leaves it), JSON on one line, indented as `python3 -m json.tool`
leaves it. Then eight runs at once must all add up (the recorder locks the
folder), and a file the recorder cannot carry over exactly (a negative
count, one over 2^64 - 1, another format version, an unknown key) must be
left as it was, with a message.

Usage: check_known_profile.py <record_known_calls> <specs/e3ga.ga>
"""

import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "generator"))
from gaphys_gen import model, profile  # noqa: E402

VECTOR, ROTOR, SCALAR, E1_E2 = 0b1110, 0b1110001, 0b1, 0b0110
EXPECTED = {  # (function, arguments, result): count per run
    ("gp", (VECTOR, VECTOR), ROTOR): 3,
    ("gp", (E1_E2, E1_E2), SCALAR): 1,
    ("gp", (ROTOR, ROTOR), ROTOR): 1,
    ("op", (VECTOR, VECTOR), 0): 1,
    **{("reverse", (blades,), blades): 1 for blades in range(1, 256)},
}


def entries(path: str, algebra) -> dict:
    return {e.key: e.count for e in profile.load(path, algebra).entries}


def main() -> int:
    program, spec = sys.argv[1], sys.argv[2]
    algebra = model.load(spec)
    with tempfile.TemporaryDirectory() as folder:
        environment = dict(os.environ, GAPHYS_PROFILE_DIR=folder)
        path = os.path.join(folder, "e3ga.json")

        def run(times: int = 1) -> list:
            started = [subprocess.Popen([program], env=environment, stderr=subprocess.PIPE, text=True)
                       for _ in range(times)]
            return [(p.wait(), p.stderr.read()) for p in started]

        layouts = [
            None,  # the recorder's own
            lambda data: profile.dumps(profile.parse(json.dumps(data), path, algebra)),  # gaphys-gen's
            lambda data: json.dumps(data, separators=(",", ":")),  # one line
            lambda data: json.dumps(data, indent=4),  # json.tool
        ]
        runs = 0
        for layout in [None] + layouts[1:]:
            if layout is not None:
                with open(path, encoding="utf-8") as handle:
                    data = json.load(handle)
                with open(path, "w", encoding="utf-8") as handle:
                    handle.write(layout(data))
            [(code, errors)] = run()
            runs += 1
            got, want = entries(path, algebra), {key: count * runs for key, count in EXPECTED.items()}
            if code != 0 or got != want:
                print(f"run {runs}: exit {code}, profile entries differ\n  got:  {got}\n  want: {want}\n{errors}")
                return 1
        results = run(8)
        runs += 8
        got, want = entries(path, algebra), {key: count * runs for key, count in EXPECTED.items()}
        if any(code != 0 for code, _ in results) or got != want:
            print(f"eight runs at once: exits {[c for c, _ in results]}, counts differ\n  got:  {got}\n"
                  f"  want: {want}")
            return 1

        with open(path, encoding="utf-8") as handle:
            good = json.load(handle)
        first = dict(good["entries"][0])
        refused = {
            "a negative count": dict(good, entries=[dict(first, count=-5)]),
            "a count over 2^64 - 1": dict(good, entries=[dict(first, count=2**64 + 10)]),
            "format version 2": dict(good, version=2),
            "version true": dict(good, version=True),
            "an unknown key": dict(good, extra=1),
            "a float count": dict(good, entries=[dict(first, count=1.5)]),
            "counts that add past 2^64 - 1": dict(good, entries=[dict(first, count=2**64 - 1)]),
        }
        for what, data in refused.items():
            text = json.dumps(data, indent=2)
            with open(path, "w", encoding="utf-8") as handle:
                handle.write(text)
            [(code, errors)] = run()
            with open(path, encoding="utf-8") as handle:
                after = handle.read()
            if after != text or "profile not updated" not in errors:
                print(f"a profile with {what}: the recorder changed it or said nothing (exit {code}):\n{errors}")
                return 1
    print("profile entries and merged counts as expected, in every layout and from eight runs at once; "
          "profiles the recorder cannot carry over are left alone")
    return 0


if __name__ == "__main__":
    sys.exit(main())
