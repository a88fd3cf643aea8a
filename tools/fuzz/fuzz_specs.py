#!/usr/bin/env python3
"""Fuzzes the generator with mutated specs: parse, validate, expand, and the command line.

    python3 tools/fuzz/fuzz_specs.py --seed 1 --count 100000

An input is OK when it generates or stops with a spec error located inside it;
anything else (an exception, over --limit processor seconds, a half-written output
folder) is a failure, saved under --corpus. Exit status 1 if any failed.
"""

import sys

import harness
import spec_inputs
import spec_oracle

NAME = "specs"
SUFFIX = ".ga"
make = spec_inputs.make
check = spec_oracle.check
check_cli = spec_oracle.check_cli

if __name__ == "__main__":
    sys.exit(harness.main(sys.modules[__name__]))
