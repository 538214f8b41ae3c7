#!/usr/bin/env python3
"""Decides whether a failed ASan ctest run failed only because LeakSanitizer's own thread tracer
crashed at a test's exit ("Tracer caught signal 11" while reading a bogus dynamic-TLS range of
Mesa's dlopen'ed driver: no leak is reported, the test itself passed). It strikes different GL
tests on different runs, so excluding tests one by one cannot stop it.

Usage: lsan-tracer-retry.py BUILD_DIR
Prints the names of the failed tests, one per line, and exits 0 when every failure in the last
run is such a tracer crash after "[  PASSED  ]"; exits 1 (printing why) when any failure is
something else (a leak, an ASan or UBSan report, a failed assertion), which must stay red.
The caller reruns the printed tests with the leak check still on: a real leak reproduces."""
import pathlib
import re
import sys

build = pathlib.Path(sys.argv[1])
tmp = build / "Testing" / "Temporary"
failed_log = tmp / "LastTestsFailed.log"
if not failed_log.exists():
    sys.exit(0)
failed = [line.split(":", 1)[1].strip() for line in failed_log.read_text().splitlines() if ":" in line]
log = tmp.joinpath("LastTest.log").read_text(errors="replace")
blocks = {}
for m in re.finditer(r"^\d+/\d+ Testing: (.+?)\n(.*?)<end of output>", log, re.S | re.M):
    blocks[m.group(1).strip()] = m.group(2)
for name in failed:
    out = blocks.get(name, "")
    tracer = "Tracer caught signal" in out and "LeakSanitizer has encountered a fatal error" in out
    if not (tracer and "[  PASSED  ]" in out and "ERROR: LeakSanitizer: detected" not in out
            and "ERROR: AddressSanitizer" not in out and "runtime error" not in out):
        print(f"{name}: not LeakSanitizer's tracer crash", file=sys.stderr)
        sys.exit(1)
    print(name)
