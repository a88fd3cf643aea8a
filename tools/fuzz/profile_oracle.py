"""What counts as OK for a profile: it loads (and then reports, selects and writes
back the same), or the loader stops with its own `file: message`. On the command
line, `report` and `merge` agree with that, print no traceback, and a failed
merge writes nothing."""

import json
import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", ".."))
GENERATOR = os.path.join(ROOT, "generator", "gaphys-gen")
sys.path.insert(0, os.path.dirname(GENERATOR))

from gaphys_gen import model, profile  # noqa: E402
from outcome import Outcome, failure, normalize, ok  # noqa: E402

SPECS = {name: os.path.join(ROOT, "specs", f"{name}.ga") for name in ("e3ga", "c3ga")}
ALGEBRAS = {name: model.load(path) for name, path in SPECS.items()}


def algebra_of(data: bytes) -> str:
    """The algebra a profile was most likely made for: the one whose spec hash it
    holds, else the one it names, else e3ga; so that loading gets past the header."""
    text = data.decode("utf-8", "replace")
    for name, algebra in ALGEBRAS.items():
        if algebra.spec_hash in text:
            return name
    named = re.search(r'"algebra"\s*:\s*"(e3ga|c3ga)"', text)
    return named.group(1) if named else "e3ga"


def is_own_error(message: str, path: str) -> bool:
    """`file:line:col: message` (at the value that is wrong) or `file: message`, on one line."""
    own = re.match(re.escape(path) + r"(:\d+:\d+)?: \S", message)
    return own is not None and "\n" not in message


def check(data: bytes, folder: str) -> Outcome:
    path = os.path.join(folder, "fuzz.json")
    with open(path, "wb") as handle:
        handle.write(data)
    algebra = ALGEBRAS[algebra_of(data)]
    try:
        loaded = profile.load(path, algebra)
    except profile.ProfileError as error:
        if not is_own_error(str(error), path):
            return failure("unlocated", normalize(str(error)), str(error))
        return ok("profile_error", str(error))
    version = json.loads(data.decode("utf-8"))["version"]
    if type(version) is not int:  # true == 1 and 1.0 == 1 in Python, but neither is the format's version
        return failure("wrong_type_accepted", f"version {version!r}", data.decode("utf-8")[:2000])
    profile.report(loaded, algebra, 0.999)
    profile.select(loaded, 0.5)
    if profile.parse(profile.dumps(loaded), path, algebra) != loaded:
        return failure("round_trip", "dumps then parse differs", profile.dumps(loaded))
    return ok("loaded")


def check_cli(data: bytes, folder: str, expected: Outcome, timeout: float) -> Outcome:
    """`report` and `merge` on the input check() wrote; merge into a folder that does not exist yet."""
    path, merged = os.path.join(folder, "fuzz.json"), os.path.join(folder, "merged")
    shutil.rmtree(merged, ignore_errors=True)
    out = os.path.join(merged, "out.json")
    spec = SPECS[algebra_of(data)]
    results = []
    for arguments in (["report", path, "--spec", spec], ["merge", "--spec", spec, "--out", out, path, path]):
        try:
            results.append(subprocess.run([sys.executable, GENERATOR, *arguments], capture_output=True, text=True,
                                          timeout=timeout))
        except subprocess.TimeoutExpired:
            return failure("cli_hang", f"{arguments[0]} over {timeout:g} s", " ".join(arguments))
    report, merge = results
    for result in results:
        if "Traceback" in result.stderr:
            return failure("cli_crash", result.stderr.strip().split("\n")[-1][:100], result.stderr)
    leftovers = [f for _, _, names in os.walk(folder) for f in names if f.startswith(".gaphys-")]
    if leftovers:
        return failure("cli_partial_output", "temporary files left", "\n".join(leftovers))
    # json's depth limit is Python's recursion limit less the caller's stack, so a
    # profile nested about a thousand deep can load on one side and not the other.
    if any("nested too deeply" in text for text in (expected.detail, report.stderr, merge.stderr)):
        return ok("profile_error", "nested too deeply")
    if expected.status == "loaded":
        # Merging a profile with itself doubles its counts: the largest pass 2^128, and merge says so.
        doubled_too_far = merge.returncode == 1 and "2^128 calls or more" in merge.stderr
        if doubled_too_far and not os.path.exists(merged) and not report.returncode:
            return ok("loaded")
        if report.returncode or merge.returncode:
            return failure("cli_disagrees", "loads in process, fails on the command line", report.stderr + merge.stderr)
        doubled = profile.load(out, ALGEBRAS[algebra_of(data)]).total_calls
        single = profile.load(path, ALGEBRAS[algebra_of(data)]).total_calls
        if doubled != 2 * single or not report.stdout.startswith("profile of "):
            return failure("cli_disagrees", "merge or report output is wrong", report.stdout[:500])
        return ok("loaded")
    if os.path.exists(merged):
        return failure("cli_partial_output", "a failed merge wrote files", "\n".join(os.listdir(merged)))
    for result in results:
        if result.returncode != 1 or result.stderr.rstrip("\n") != expected.detail:
            return failure("cli_disagrees", f"exit {result.returncode}, in process {expected.status}",
                           f"command line:\n{result.stderr}\nin process:\n{expected.detail}")
    return ok("profile_error", expected.detail)
