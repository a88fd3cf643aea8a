"""Worker processes that check fuzz inputs one at a time, under a watchdog.

Input i is made from `random.Random(f"{seed}:{i}")` alone, so a run gives the
same inputs and outcomes whatever the number of workers, and anyone can make
input i again from its index. A worker checks its input under a timer; Python's
timer cannot interrupt a long computation inside C (a huge `10 ** n`), so the
parent also kills a worker that stops answering, counts a hang and starts another.
"""

import multiprocessing
import random
import resource
import shutil
import signal
import tempfile
import time
from multiprocessing.connection import wait

from outcome import crash, failure

MEMORY_LIMIT = 2 << 30  # a worker that needs more has a bug; keep the machine usable
GRACE = 2.0  # seconds the watchdog waits beyond a worker's own timer


def make_input(target, seed: int, index: int) -> tuple[str, bytes]:
    return target.make(random.Random(f"{seed}:{index}"))


class _Timeout(BaseException):
    """Raised by the timer; a BaseException so that no `except Exception` in a target swallows it."""


def _on_alarm(signum, frame):
    raise _Timeout()


def _check_one(target, data: bytes, folder: str, limit: float, with_cli: bool, cli_timeout: float):
    """(in-process outcome, command-line outcome or None, seconds in process)."""
    start = time.perf_counter()
    # Processor time, not wall time: on a loaded machine (a parallel build,
    # ctest -j) a healthy input can wait longer than the limit for a core.
    signal.setitimer(signal.ITIMER_PROF, limit)
    try:
        outcome = target.check(data, folder)
    except _Timeout as error:
        outcome = failure("hang", f"over {limit:g} s of processor time", crash(error).detail)
    except Exception as error:  # noqa: BLE001 - every other exception is what we are looking for
        outcome = crash(error)
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
    seconds = time.perf_counter() - start
    cli = None
    if with_cli:
        try:
            cli = target.check_cli(data, folder, outcome, cli_timeout)
        except Exception as error:  # noqa: BLE001 - a harness bug; report it rather than stop the run
            cli = crash(error)
    return outcome, cli, seconds


def _worker(target, seed: int, connection, folder: str, limit: float, cli_every: int, cli_timeout: float) -> None:
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))
    signal.signal(signal.SIGPROF, _on_alarm)
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent handles ^C
    while (index := connection.recv()) is not None:
        kind, data = make_input(target, seed, index)
        with_cli = cli_every > 0 and index % cli_every == 0
        connection.send((index, kind, *_check_one(target, data, folder, limit, with_cli, cli_timeout)))


class Pool:
    """Workers that each hold at most one input, and the deadline of that input."""

    def __init__(self, target, arguments):
        self.target, self.arguments = target, arguments
        self.context = multiprocessing.get_context("fork")
        # The parent owns every worker's scratch folder: a killed worker cannot clean up.
        self.folder = tempfile.mkdtemp(prefix=f"gaphys-fuzz-{target.NAME}-")
        self.workers = [self.start() for _ in range(arguments.jobs)]

    def start(self) -> dict:
        parent, child = self.context.Pipe()
        a = self.arguments
        folder = tempfile.mkdtemp(dir=self.folder)
        process = self.context.Process(target=_worker, args=(self.target, a.seed, child, folder, a.limit,
                                                             a.cli_every, a.cli_timeout), daemon=True)
        process.start()
        child.close()
        return {"process": process, "connection": parent, "index": None, "deadline": 0.0}

    def deadline(self, index: int) -> float:
        a = self.arguments
        cli = a.cli_timeout if a.cli_every > 0 and index % a.cli_every == 0 else 0.0
        return time.monotonic() + a.limit + cli + GRACE

    def give(self, worker: dict, index: int) -> None:
        worker["connection"].send(index)
        worker["index"], worker["deadline"] = index, self.deadline(index)

    def replace(self, worker: dict) -> None:
        worker["process"].kill()
        worker["process"].join()
        worker.update(self.start())

    def stop(self) -> None:
        for worker in self.workers:
            if worker["index"] is None:
                worker["connection"].send(None)
        for worker in self.workers:
            worker["process"].join(timeout=1)
            if worker["process"].is_alive():
                worker["process"].kill()
                worker["process"].join()
        shutil.rmtree(self.folder, ignore_errors=True)

    def results(self, count: int):
        """Yields (index, kind, outcome, cli outcome or None, seconds) for inputs 0..count-1,
        in completion order; kind is None when the worker gave no answer."""
        pending = iter(range(count))
        for worker in self.workers:
            index = next(pending, None)
            if index is not None:
                self.give(worker, index)
        while any(w["index"] is not None for w in self.workers):
            busy = {w["connection"]: w for w in self.workers if w["index"] is not None}
            for connection in wait(list(busy), timeout=0.2):
                worker = busy[connection]
                try:
                    result = connection.recv()
                except (EOFError, OSError):  # the worker died: out of memory, a signal, a crash in C
                    worker["process"].join(timeout=1)
                    code = worker["process"].exitcode
                    result = (worker["index"], None, failure("crash", f"worker died ({code})", f"exit code {code}"),
                              None, 0.0)
                    self.replace(worker)
                yield result
                self.next_for(worker, pending)
            now = time.monotonic()
            for worker in self.workers:
                if worker["index"] is not None and now > worker["deadline"]:
                    index = worker["index"]
                    self.replace(worker)
                    yield (index, None, failure("hang", "killed by the watchdog", "the worker stopped answering"), None,
                           0.0)
                    self.next_for(worker, pending)

    def next_for(self, worker: dict, pending) -> None:
        index = next(pending, None)
        worker["index"] = None
        if index is not None:
            self.give(worker, index)
