"""What counts as OK for a spec: it generates, or it stops with the generator's own
spec error at a `file:line:col` inside the input. On the command line, also: the
output folder is left as it was after an error and complete after a success."""

import os
import re
import shutil
import subprocess
import sys
import zlib

ROOT = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", ".."))
GENERATOR = os.path.join(ROOT, "generator", "gaphys-gen")
sys.path.insert(0, os.path.dirname(GENERATOR))

from gaphys_gen import expand, model, render, view  # noqa: E402
from gaphys_gen.errors import SpecError  # noqa: E402
from outcome import Outcome, failure, normalize, ok  # noqa: E402

SENTINEL = "keep.txt"  # a file already in the output folder, which every run must leave alone
_INTEGER_LITERAL = re.compile(r"\bT\((-?\d+)\)")


def seen_text(data: bytes) -> str:
    """The input as the generator reads it: UTF-8 with universal newlines."""
    return data.decode("utf-8", "replace").replace("\r\n", "\n").replace("\r", "\n")


def located(error: SpecError, data: bytes, path: str) -> Outcome:
    """OK when the error names this file and a line and column inside it, then shows
    that line with a caret under the column (errors about the whole file show no line)."""
    text = str(error)
    location = error.location
    if location.path != path or not text.startswith(f"{path}:{location.line}:{location.column}: error: "):
        return failure("unlocated", normalize(text), text)
    lines = seen_text(data).split("\n")
    if not (1 <= location.line <= len(lines) and 1 <= location.column <= len(lines[location.line - 1]) + 1):
        return failure("bad_location", normalize(text), f"outside the input ({len(lines)} lines):\n{text}")
    line = lines[location.line - 1]
    caret = "".join(c if c == "\t" else " " for c in line[: location.column - 1]) + "^"
    whole_file = error.message.startswith("missing '")
    if line and not whole_file and text.split("\n")[1:] != [line, caret]:
        return failure("wrong_source_line", normalize(text), text)
    return ok("spec_error", text)


def strings(value):
    """Every string in a view model (nested dicts and lists)."""
    if isinstance(value, str):
        yield value
    elif isinstance(value, dict):
        for item in value.values():
            yield from strings(item)
    elif isinstance(value, (list, tuple)):
        for item in value:
            yield from strings(item)


def too_large_literal(texts) -> str | None:
    """The first `T(n)` whose n no C++ integer type holds: such a header does not compile."""
    for text in texts:
        for number in _INTEGER_LITERAL.findall(text):
            if abs(int(number)) >= 2**63:
                return f"T({number})"
    return None


def check(data: bytes, folder: str) -> Outcome:
    """The stages `gaphys-gen generate` runs before printing: read, parse, validate,
    expand and build the view model (everything but Jinja2 and clang-format)."""
    path = os.path.join(folder, "fuzz.ga")
    with open(path, "wb") as handle:
        handle.write(data)
    try:
        algebra = model.load(path)
        printed = view.build(algebra, expand.expand(algebra), "optimized", [], algebra.name, [])
    except SpecError as error:
        return located(error, data, path)
    literal = too_large_literal(strings(printed))
    if literal:
        return failure("bad_literal", "integer literal over 64 bits", literal)
    return ok("generated")


def files_under(root: str) -> list[str]:
    return sorted(os.path.relpath(os.path.join(d, f), root) for d, _, names in os.walk(root) for f in names)


def read(path: str) -> str:
    with open(path, encoding="utf-8") as handle:
        return handle.read()


def is_complete(files: list[str]) -> bool:
    """One folder NS holding exactly the files a reference build has."""
    folders = {f.split(os.sep)[0] for f in files}
    if len(folders) != 1:
        return False
    namespace = folders.pop()
    expected = sorted(os.path.join(namespace, name.format(ns=namespace)) for _, name in render.files_for("reference"))
    return files == expected


def check_cli(data: bytes, folder: str, expected: Outcome, timeout: float) -> Outcome:
    """Runs `gaphys-gen generate` on the input check() wrote, into a folder holding one file.
    Half the inputs (by their checksum) take the optimized variant, which prints every kernel."""
    path, out = os.path.join(folder, "fuzz.ga"), os.path.join(folder, "out")
    shutil.rmtree(out, ignore_errors=True)
    os.mkdir(out)
    with open(os.path.join(out, SENTINEL), "w", encoding="utf-8") as handle:
        handle.write("untouched\n")
    variant = ("reference", "optimized")[zlib.crc32(data) % 2]
    command = [sys.executable, GENERATOR, "generate", path, "--variant", variant, "--out", out]
    try:
        result = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return failure("cli_hang", f"over {timeout:g} s", " ".join(command))
    stderr = "".join(line for line in result.stderr.splitlines(True) if not line.startswith("gaphys-gen: warning:"))
    files = [f for f in files_under(out) if f != SENTINEL]
    untouched = read(os.path.join(out, SENTINEL)) == "untouched\n"
    if "Traceback" in stderr:
        return failure("cli_crash", stderr.strip().split("\n")[-1][:100], stderr)
    if not untouched or any(os.path.basename(f).startswith(".gaphys-") for f in files):
        return failure("cli_partial_output", "temporary or changed files", "\n".join(files))
    if result.returncode == 0:
        if not is_complete(files):
            return failure("cli_partial_output", "incomplete after success", "\n".join(files))
        if expected.status != "generated":
            return failure("cli_disagrees", f"generated, in process {expected.status}", expected.detail)
        literal = too_large_literal(read(os.path.join(out, f)) for f in files)
        if literal:
            return failure("cli_bad_literal", "integer literal over 64 bits", literal)
        return ok("generated")
    if files:
        return failure("cli_partial_output", "files written after an error", "\n".join(files) + "\n" + stderr)
    if expected.status != "spec_error" or stderr.split("\n")[0] != expected.detail.split("\n")[0]:
        return failure("cli_disagrees", f"exit {result.returncode}, in process {expected.status}",
                       f"command line:\n{stderr}\nin process:\n{expected.detail}")
    return ok("spec_error", stderr)
