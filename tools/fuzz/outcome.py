"""What checking one fuzz input found, and how outcomes are grouped."""

import re
import traceback
from dataclasses import dataclass


@dataclass(frozen=True)
class Outcome:
    status: str  # "generated", "spec_error", "loaded", "profile_error", or a failure: "crash", "hang", ...
    failed: bool
    signature: str  # what groups alike outcomes: a normalized message, or a crash's type and site
    detail: str = ""  # the full message or traceback


def ok(status: str, message: str = "") -> Outcome:
    return Outcome(status, False, f"{status}: {normalize(message)}" if message else status, message)


def failure(status: str, signature: str, detail: str) -> Outcome:
    return Outcome(status, True, f"{status}: {signature}", detail)


def normalize(message: str) -> str:
    """The shape of an error message: names, numbers and listed alternatives left out,
    so that `unknown type 'x'` and `unknown type 'y'` count as one distinct message."""
    first = message.split("\n")[0]
    if " error: " in first:  # a spec error: `file:line:col: error: message`
        first = re.sub(r"^.*?:\d+:\d+: error: ", "", first, count=1)
    else:  # a profile error: `file[:line:col]: message`
        first = re.sub(r"^\S*?(:\d+:\d+)?: ", "", first, count=1)
    first = re.sub(r"'[^']*'|\"[^\"]*\"", "_", first)
    first = re.sub(r"\([^)]*\)", "(...)", first)
    return re.sub(r"-?\d[\d.e+-]*", "N", first)[:120]


def crash(error: BaseException) -> Outcome:
    """An exception the code under test should never raise: grouped by type and the
    innermost frame of the generator (or of the harness when it never got there)."""
    frames = traceback.extract_tb(error.__traceback__)
    inside = [f for f in frames if "gaphys_gen" in f.filename] or frames or [None]
    site = f"{inside[-1].filename.rsplit('/', 1)[-1]}:{inside[-1].name}" if inside[-1] else "?"
    detail = "".join(traceback.format_exception(type(error), error, error.__traceback__))
    return failure("crash", f"{type(error).__name__} in {site}", detail)
