"""Command line: python3 -m gaphys_gen (or generator/gaphys-gen) <command> ...

  generate SPEC --variant reference|instrumented|optimized --out DIR [--namespace NS]
           [--profile PROFILE [--coverage 0.999]] [--no-format]
      Parse SPEC, expand it and write DIR/<ns>/<ns>.hpp and its companions
      (all or none). NS defaults to the spec's algebra name. With a profile the
      optimized variant gets straight-line mv code for its hot bitmaps.
  check SPEC --variant V --out DIR [--namespace NS]
      Exit 1, listing the files, if generating would change anything in DIR.
  merge --spec SPEC --out PROFILE INPUT...
      Add the counts of several profiles of SPEC into one (written atomically).
  report PROFILE --spec SPEC [--coverage 0.999] [--top N]
      The hot (function, argument bitmaps) combinations with blade names, and the
      share of calls an optimized build at that coverage still sends to the fallback.
"""

import argparse
import os
import shlex
import signal
import sys
import threading

from . import model, output, profile, render
from .errors import SpecError, UsageError


def coverage(text: str) -> float:
    """--coverage: a share of calls in (0, 1]."""
    value = float(text)
    if not 0 < value <= 1:
        raise argparse.ArgumentTypeError(f"must be in (0, 1], not {text}")
    return value


def row_count(text: str) -> int:
    """--top: a number of rows, >= 0."""
    value = int(text)
    if value < 0:
        raise argparse.ArgumentTypeError(f"must be >= 0, not {text}")
    return value


def parse_arguments(argv: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="gaphys-gen", description="Geometric-algebra C++ generator.")
    commands = parser.add_subparsers(dest="command", required=True)
    for name, text in (("generate", "write the generated library"), ("check", "fail if DIR is stale")):
        command = commands.add_parser(name, help=text)
        command.add_argument("spec", help="the algebra spec (.ga)")
        command.add_argument("--variant", choices=render.VARIANTS, required=True)
        command.add_argument("--out", required=True, help="output folder (the include root)")
        command.add_argument("--namespace", help="C++ namespace and header folder (default: the algebra name)")
        command.add_argument("--no-format", action="store_true", help="skip clang-format")
        command.add_argument("--profile", help="a profile of this spec: specialize mv calls (optimized only)")
        command.add_argument("--coverage", type=coverage, default=None,
                             help="share of the profile's calls to specialize (default 0.999)")
    merge = commands.add_parser("merge", help="add the counts of several profiles")
    merge.add_argument("inputs", nargs="+", help="profiles to merge")
    merge.add_argument("--spec", required=True, help="the spec the profiles were recorded with")
    merge.add_argument("--out", required=True, help="merged profile to write")
    report = commands.add_parser("report", help="show the hot combinations of a profile")
    report.add_argument("profile")
    report.add_argument("--spec", required=True)
    report.add_argument("--coverage", type=coverage, default=0.999, help="share of calls to specialize")
    report.add_argument("--top", type=row_count, default=20, help="rows to show")
    return parser.parse_args(argv)


def profile_command(arguments: argparse.Namespace) -> int:
    algebra = model.load(arguments.spec)
    if arguments.command == "merge":
        loaded = [(path, profile.load(path, algebra)) for path in arguments.inputs]
        profile.write(arguments.out, profile.merge(loaded))
    else:
        print(profile.report(profile.load(arguments.profile, algebra), algebra, arguments.coverage, arguments.top),
              end="")
    return 0


def regenerate_command(arguments: argparse.Namespace) -> str:
    words = ["gaphys-gen", "generate", arguments.spec, "--variant", arguments.variant, "--out", arguments.out]
    if arguments.namespace:
        words += ["--namespace", arguments.namespace]
    if arguments.profile:
        words += ["--profile", arguments.profile, "--coverage", str(arguments.coverage)]
    if arguments.no_format:
        words.append("--no-format")
    return " ".join(shlex.quote(w) for w in words)


def os_error_text(error: OSError, fallback: str) -> str:
    """An OSError as "gaphys-gen: PATH: reason", naming the path that failed."""
    return f"gaphys-gen: {error.filename or fallback}: {error.strerror or error}"


def terminated(number: int, frame) -> None:
    """SIGTERM or SIGHUP as an exception, so that a write in progress removes
    its temporary files (output.write_all) before the exit."""
    raise SystemExit(128 + number)


def main(argv: list[str] | None = None) -> int:
    arguments = parse_arguments(sys.argv[1:] if argv is None else argv)
    # SIGTERM and SIGHUP as exceptions where they would kill the process (not
    # where ignored, as under nohup; only the main thread may set them), and
    # as they were again after.
    caught = {}
    if threading.current_thread() is threading.main_thread():
        for name in ("SIGTERM", "SIGHUP"):
            number = getattr(signal, name, None)
            if number is not None and signal.getsignal(number) == signal.SIG_DFL:
                caught[number] = signal.signal(number, terminated)
    try:
        return run(arguments)
    except KeyboardInterrupt:
        print("gaphys-gen: interrupted", file=sys.stderr)
        return 130
    finally:
        for number, previous in caught.items():
            signal.signal(number, previous)


def run(arguments: argparse.Namespace) -> int:
    if arguments.command in ("merge", "report"):
        try:
            return profile_command(arguments)
        except (SpecError, UsageError) as error:
            print(error, file=sys.stderr)
            return 1
        except OSError as error:
            print(os_error_text(error, arguments.spec), file=sys.stderr)
            return 1
    if arguments.coverage is not None and not arguments.profile:
        print("gaphys-gen: --coverage needs --profile (it is the share of the profile's calls to specialize)",
              file=sys.stderr)
        return 2
    if arguments.coverage is None:
        arguments.coverage = 0.999
    try:
        try:
            algebra = model.load(arguments.spec)
        except OSError as error:
            raise UsageError(f"{arguments.spec}: cannot read: {error.strerror}") from error
        namespace = arguments.namespace or algebra.name
        problem = model.namespace_problem(namespace, [*(t.name for t in algebra.types), *algebra.aliases])
        if problem:
            raise UsageError(f"--namespace {namespace!r} {problem}")
        formatter = None if arguments.no_format else render.find_clang_format()
        if formatter is None and not arguments.no_format:
            print("gaphys-gen: warning: clang-format not found, output is unformatted", file=sys.stderr)
        files = render.render(algebra, arguments.variant, namespace, regenerate_command(arguments), formatter,
                              arguments.profile, arguments.coverage)
    except (SpecError, UsageError) as error:
        print(error, file=sys.stderr)
        return 1
    if arguments.command == "check":
        stale = []
        for relative, text in sorted(files.items()):
            path = os.path.join(arguments.out, relative)
            try:
                if output.unchanged(path, text):
                    continue
            except OSError:  # not a file (a folder, a path through a file)
                pass
            stale.append(path)
        for path in stale:
            print(f"gaphys-gen: stale: {path}", file=sys.stderr)
        return 1 if stale else 0
    try:
        output.write_all(arguments.out, files)
    except OSError as error:
        print(f"gaphys-gen: cannot write {error.filename or arguments.out}: {error.strerror or error}",
              file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
