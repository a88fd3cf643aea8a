"""Writing generated files all or none.

Every file is first written in full to a temporary file beside its target;
only when all of them are written are they renamed into place (a rename is
atomic on POSIX). A failure before that removes the temporaries and any
folder made for them, leaving the output folder as it was. The renames run
with SIGINT, SIGTERM and SIGHUP held back, so Ctrl-C or a kill (other than
SIGKILL) lands before them or after them all, never between two.
"""

import os
import signal
import tempfile
from contextlib import contextmanager


_HELD_SIGNALS = {getattr(signal, name) for name in ("SIGINT", "SIGTERM", "SIGHUP") if hasattr(signal, name)}


@contextmanager
def _signals_held():
    """Delivers SIGINT, SIGTERM and SIGHUP only after the block (where the
    platform can hold them)."""
    if not hasattr(signal, "pthread_sigmask"):
        yield
        return
    previous = signal.pthread_sigmask(signal.SIG_BLOCK, _HELD_SIGNALS)
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, previous)


def _make_folders(folder: str, made: list[str]) -> None:
    """Like os.makedirs, recording each folder it creates (outermost first)."""
    missing = []
    while folder and not os.path.isdir(folder):
        missing.append(folder)
        folder = os.path.dirname(folder)
    for path in reversed(missing):
        with _signals_held():  # (made and recorded together: an interrupt cannot fall between)
            os.mkdir(path)
            made.append(path)


def unchanged(target: str, text: str) -> bool:
    """Whether target holds text already (False where it is missing or not text)."""
    try:
        with open(target, encoding="utf-8", newline="") as handle:
            return handle.read() == text
    except (FileNotFoundError, UnicodeDecodeError):  # (a damaged file is written over)
        return False


def write_all(root: str, files: dict[str, str]) -> list[str]:
    """Writes {relative path: text} under root; returns the paths that changed."""
    staged: list[tuple[str, str]] = []
    made: list[str] = []
    try:
        for relative, text in sorted(files.items()):
            target = os.path.join(root, relative)
            if unchanged(target, text):
                continue  # keep the timestamp so that builds stay incremental
            _make_folders(os.path.dirname(target), made)
            with _signals_held():
                try:
                    fd, temporary = tempfile.mkstemp(prefix=".gaphys-", dir=os.path.dirname(target))
                except OSError as error:  # (named by the file it was for, not the temporary's name)
                    raise OSError(error.errno, error.strerror, target) from error
                staged.append((temporary, target))
            with os.fdopen(fd, "w", encoding="utf-8", newline="") as handle:
                handle.write(text)
    except BaseException:
        with _signals_held():
            for temporary, _ in staged:
                os.unlink(temporary)
            for folder in reversed(made):
                os.rmdir(folder)
        raise
    with _signals_held():
        for temporary, target in staged:
            os.chmod(temporary, 0o644)
            os.replace(temporary, target)
    return [target for _, target in staged]
