"""Runs record_known_calls three times with GAPHYS_PROFILE_DIR set and checks
the profile it writes, through the generator's own validating loader: exact
entries, and counts that grow with each run (merge into the existing file).
Before the third run the file is rewritten by the generator's own writer (as
`gaphys-gen merge` leaves it), so the recorder must read that format too.

Usage: check_known_profile.py <record_known_calls> <specs/e3ga.ga>
"""

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


def main() -> int:
    program, spec = sys.argv[1], sys.argv[2]
    algebra = model.load(spec)
    with tempfile.TemporaryDirectory() as folder:
        environment = dict(os.environ, GAPHYS_PROFILE_DIR=folder)
        path = os.path.join(folder, "e3ga.json")
        for run in (1, 2, 3):
            if run == 3:
                profile.write(path, profile.load(path, algebra))
            subprocess.run([program], env=environment, check=True)
            loaded = profile.load(path, algebra)
            got = {e.key: e.count for e in loaded.entries}
            want = {key: count * run for key, count in EXPECTED.items()}
            if got != want:
                print(f"run {run}: profile entries differ\n  got:  {got}\n  want: {want}")
                return 1
    print("profile entries and merged counts as expected")
    return 0


if __name__ == "__main__":
    sys.exit(main())
