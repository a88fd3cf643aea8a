"""Runs the training workload and checks that profiling/profiles/ holds exactly
what it records today; if not, says how stale the committed profiles are and
how to refresh them (tools/profile-guided-build.sh).

Usage: check_committed_profile.py <train_workload> <repository root>
"""

import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "generator"))
from gaphys_gen import model, profile  # noqa: E402


def main() -> int:
    program, root = sys.argv[1], sys.argv[2]
    stale = False
    with tempfile.TemporaryDirectory() as folder:
        subprocess.run([program], env=dict(os.environ, GAPHYS_PROFILE_DIR=folder), check=True)
        for algebra_name in ("e3ga", "c3ga"):
            algebra = model.load(os.path.join(root, "specs", algebra_name + ".ga"))
            fresh = profile.load(os.path.join(folder, algebra_name + ".json"), algebra)
            committed = profile.load(os.path.join(root, "profiling", "profiles", algebra_name + ".json"), algebra)
            new = {e.key: e.count for e in fresh.entries}
            old = {e.key: e.count for e in committed.entries}
            if new != old:
                stale = True
                changed = sum(1 for k in new.keys() & old.keys() if new[k] != old[k])
                print(f"{algebra_name}: committed profile is stale: {len(new.keys() - old.keys())} new, "
                      f"{len(old.keys() - new.keys())} gone, {changed} changed entries "
                      f"({committed.total_calls} -> {fresh.total_calls} calls)")
    if stale:
        print("refresh with: bash tools/profile-guided-build.sh")
        return 1
    print("committed profiles match the training workload")
    return 0


if __name__ == "__main__":
    sys.exit(main())
