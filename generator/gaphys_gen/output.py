"""Writing generated files all or none.

Every file is first written in full to a temporary file beside its target;
only when all of them are written are they renamed into place (a rename is
atomic on POSIX). A failure before that removes the temporaries and leaves the
output folder as it was.
"""

import os
import tempfile


def write_all(root: str, files: dict[str, str]) -> list[str]:
    """Writes {relative path: text} under root; returns the paths that changed."""
    staged: list[tuple[str, str]] = []
    try:
        for relative, text in sorted(files.items()):
            target = os.path.join(root, relative)
            try:
                with open(target, encoding="utf-8", newline="") as handle:
                    if handle.read() == text:
                        continue  # unchanged: keep the timestamp so builds stay incremental
            except FileNotFoundError:
                pass
            os.makedirs(os.path.dirname(target), exist_ok=True)
            fd, temporary = tempfile.mkstemp(prefix=".gaphys-", dir=os.path.dirname(target))
            staged.append((temporary, target))
            with os.fdopen(fd, "w", encoding="utf-8", newline="") as handle:
                handle.write(text)
    except BaseException:
        for temporary, _ in staged:
            os.unlink(temporary)
        raise
    for temporary, target in staged:
        os.chmod(temporary, 0o644)
        os.replace(temporary, target)
    return [target for _, target in staged]
