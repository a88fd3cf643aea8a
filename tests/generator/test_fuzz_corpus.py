"""The fuzzers' corpus (tools/fuzz): inputs that once crashed, hung or misled the
generator, and the first inputs to reach other outcomes. Each file's name says
how it must end: a spec `generates-` or stops at a located `error-`; a profile
`loads-` or is `rejected-` with the loader's own message. Never an exception.

Profiles hold `@e3ga.spec_hash@` (or c3ga) where the spec's hash goes, so that
they keep reaching the checks past the header when a spec changes.
"""

import os
import signal
import sys
import tempfile
import unittest

from .support import REPO_DIR

sys.path.insert(0, os.path.join(REPO_DIR, "tools", "fuzz"))
import profile_oracle  # noqa: E402
import spec_oracle  # noqa: E402

CORPUS = os.path.join(os.path.dirname(__file__), "fuzz_corpus")
EXPECTED = {"generates": "generated", "error": "spec_error", "loads": "loaded", "rejected": "profile_error"}
LIMIT = 10.0  # seconds; the inputs that once hung ran for minutes


def _too_slow(signum, frame):
    raise TimeoutError(f"over {LIMIT:g} s")


def with_spec_hashes(data: bytes) -> bytes:
    for name, algebra in profile_oracle.ALGEBRAS.items():
        data = data.replace(f"@{name}.spec_hash@".encode(), algebra.spec_hash.encode())
    return data


class Corpus(unittest.TestCase):
    def check_folder(self, folder: str, oracle, prepare=lambda data: data) -> None:
        names = sorted(os.listdir(os.path.join(CORPUS, folder)))
        self.assertGreater(len(names), 10)
        previous = signal.signal(signal.SIGALRM, _too_slow)
        self.addCleanup(signal.signal, signal.SIGALRM, previous)
        with tempfile.TemporaryDirectory() as work:
            for name in names:
                with self.subTest(name), open(os.path.join(CORPUS, folder, name), "rb") as handle:
                    data = prepare(handle.read())
                    signal.setitimer(signal.ITIMER_REAL, LIMIT)
                    try:
                        outcome = oracle.check(data, work)
                    finally:
                        signal.setitimer(signal.ITIMER_REAL, 0)
                    self.assertFalse(outcome.failed, outcome.detail)
                    self.assertEqual(outcome.status, EXPECTED[name.split("-")[0]], outcome.detail)

    def test_specs(self):
        self.check_folder("specs", spec_oracle)

    def test_profiles(self):
        self.check_folder("profiles", profile_oracle, with_spec_hashes)


if __name__ == "__main__":
    unittest.main()
