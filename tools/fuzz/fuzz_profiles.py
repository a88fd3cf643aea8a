#!/usr/bin/env python3
"""Fuzzes the profile loader with mutated profiles: load, report, merge, and the command line.

    python3 tools/fuzz/fuzz_profiles.py --seed 1 --count 100000

An input is OK when it loads or stops with the loader's own `file: message`
(and `gaphys-gen report` / `merge` then fail cleanly and write nothing);
anything else (an exception, over --limit processor seconds, a partial merge) is a
failure, saved under --corpus. Exit status 1 if any failed.
"""

import sys

import harness
import profile_inputs
import profile_oracle

NAME = "profiles"
SUFFIX = ".json"
make = profile_inputs.make
check = profile_oracle.check
check_cli = profile_oracle.check_cli

if __name__ == "__main__":
    sys.exit(harness.main(sys.modules[__name__]))
