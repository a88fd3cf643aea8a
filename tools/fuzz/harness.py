"""The fuzzers' command line: runs a target's inputs through a pool of workers,
counts the outcomes, and saves the failing and the interesting inputs.

A target is a module with NAME, SUFFIX, make(rng) -> (kind, bytes),
check(data, folder) -> Outcome and check_cli(data, folder, outcome, timeout) -> Outcome.
"""

import argparse
import os
import shutil
import sys
import time
from collections import Counter

from outcome import Outcome
from pool import Pool, make_input

PROGRESS_EVERY = 15.0  # seconds between progress lines


def save(folder: str, name: str, data: bytes, detail: str) -> None:
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as handle:
        handle.write(data)
    with open(os.path.join(folder, name + ".txt"), "w", encoding="utf-8") as handle:
        handle.write(detail if detail.endswith("\n") else detail + "\n")


class _Tally:
    """Counts outcomes and remembers which inputs to save."""

    def __init__(self, per_signature: int):
        self.per_signature = per_signature
        self.statuses, self.cli_statuses, self.kinds = Counter(), Counter(), Counter()
        self.failures: dict[str, list[tuple[int, str]]] = {}  # signature -> [(index, detail)]
        self.failure_count = 0
        self.first: dict[str, tuple[int, str]] = {}  # OK signature -> earliest (index, detail)
        self.slowest = (0.0, -1)  # (seconds in process, index): how close the inputs come to the limit

    def add(self, index: int, kind: str, outcome: Outcome, cli: Outcome | None, seconds: float) -> None:
        self.kinds[kind] += 1
        self.slowest = max(self.slowest, (seconds, index))
        self.statuses[outcome.status] += 1
        for found in (outcome, cli):
            if found is None:
                continue
            if found is cli:
                self.cli_statuses[found.status] += 1
            if found.failed:
                self.failure_count += 1
                saved = self.failures.setdefault(found.signature, [])
                saved.append((index, found.detail))
                saved.sort()
                del saved[self.per_signature:]
            elif found.signature not in self.first or index < self.first[found.signature][0]:
                self.first[found.signature] = (index, found.detail)


def summary(target, arguments, tally: _Tally, seconds: float) -> str:
    a = arguments
    lines = [f"fuzz {target.NAME}: seed {a.seed}, {a.count} inputs in {seconds:.1f} s "
             f"({a.count / seconds:.1f} inputs/s, {a.jobs} workers, limit {a.limit:g} s per input)"]
    lines += [f"  {status:<16} {n}" for status, n in sorted(tally.statuses.items())]
    cli_runs = sum(tally.cli_statuses.values())
    if cli_runs:
        shown = ", ".join(f"{s} {n}" for s, n in sorted(tally.cli_statuses.items()))
        lines.append(f"  command line runs: {cli_runs} ({shown})")
    lines.append("  inputs by kind: " + ", ".join(f"{k} {n}" for k, n in sorted(tally.kinds.items())))
    lines.append(f"  distinct OK outcomes: {len(tally.first)}; slowest input: {tally.slowest[1]} "
                 f"({tally.slowest[0]:.2f} s)")
    lines.append(f"  failures: {tally.failure_count} ({len(tally.failures)} distinct)")
    for signature, saved in sorted(tally.failures.items()):
        lines.append(f"    {signature} (first: input {saved[0][0]})")
    return "\n".join(lines)


def save_corpus(target, arguments, tally: _Tally) -> int:
    """Replaces the corpus of the last run: failing inputs, then the first to reach each OK outcome."""
    for folder in ("failures", "interesting"):
        shutil.rmtree(os.path.join(arguments.corpus, folder), ignore_errors=True)
    saved = 0
    for signature, inputs in tally.failures.items():
        for index, detail in inputs:
            kind, data = make_input(target, arguments.seed, index)
            status = signature.split(":", 1)[0]
            save(os.path.join(arguments.corpus, "failures"), f"{status}-{index}-{kind}{target.SUFFIX}", data,
                 f"{signature}\n\n{detail}")
            saved += 1
    firsts = sorted(tally.first.items(), key=lambda item: item[1][0])[: arguments.interesting]
    for signature, (index, detail) in firsts:
        kind, data = make_input(target, arguments.seed, index)
        save(os.path.join(arguments.corpus, "interesting"), f"{index}-{kind}{target.SUFFIX}", data,
             f"{signature}\n\n{detail}")
        saved += 1
    return saved


def parse_arguments(target, argv: list[str]) -> argparse.Namespace:
    root = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", ".."))
    parser = argparse.ArgumentParser(prog=f"fuzz_{target.NAME}.py", description=target.__doc__.split("\n")[0])
    parser.add_argument("--seed", type=int, default=1, help="makes the run reproducible (default 1)")
    parser.add_argument("--count", type=int, default=1000, help="inputs to check (default 1000)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="worker processes (default: cores)")
    parser.add_argument("--limit", type=float, default=1.0, help="processor seconds one input may take (default 1)")
    parser.add_argument("--cli-every", type=int, default=200,
                        help="also run every Nth input through the command line (0: never; default 200)")
    parser.add_argument("--cli-timeout", type=float, default=60.0, help="seconds one command-line run may take")
    parser.add_argument("--corpus", default=os.path.join(root, "build-fuzz", "corpus", target.NAME),
                        help="where failing and interesting inputs go (default build-fuzz/corpus/NAME)")
    parser.add_argument("--per-signature", type=int, default=20,
                        help="failing inputs saved per distinct failure (default 20)")
    parser.add_argument("--interesting", type=int, default=200,
                        help="at most this many inputs saved, the first to reach each distinct OK outcome")
    return parser.parse_args(argv)


def main(target, argv: list[str] | None = None) -> int:
    arguments = parse_arguments(target, sys.argv[1:] if argv is None else argv)
    tally = _Tally(arguments.per_signature)
    pool = Pool(target, arguments)
    start = last = time.monotonic()
    done = 0
    try:
        for index, kind, outcome, cli, seconds in pool.results(arguments.count):
            kind = kind or make_input(target, arguments.seed, index)[0]
            tally.add(index, kind, outcome, cli, seconds)
            done += 1
            if time.monotonic() - last > PROGRESS_EVERY:
                last = time.monotonic()
                print(f"fuzz {target.NAME}: {done}/{arguments.count} inputs, {tally.failure_count} failures, "
                      f"{done / (last - start):.1f} inputs/s", file=sys.stderr, flush=True)
    finally:
        pool.stop()
    seconds = time.monotonic() - start
    print(summary(target, arguments, tally, seconds))
    saved = save_corpus(target, arguments, tally)
    print(f"  saved {saved} inputs under {arguments.corpus}")
    return 1 if tally.failure_count else 0
