#!/usr/bin/env python3
"""The before/after table of an architecture change from alternating bench runs.

A folder holds before-N.json and after-N.json (`shadowlab bench --json`), run in turn
(before-1, after-1, before-2, ...) on the same scene and techniques: each run's ms_ratio (the
entry's frame time over the first entry's, interleaved within the run) per preset, the medians
over the runs and their change. Usage: scripts/bench-ab-table.py FOLDER"""
import json
import pathlib
import statistics
import sys


def ratios(path):
    entries = json.loads(path.read_text())["entries"]
    return {e["technique"]: e["ms_ratio"]["median"] for e in entries}


def main(folder):
    root = pathlib.Path(folder)
    n = len(list(root.glob("before-*.json")))
    before = [ratios(root / f"before-{i}.json") for i in range(1, n + 1)]
    after = [ratios(root / f"after-{i}.json") for i in range(1, n + 1)]
    print("| preset | before: ms_ratio per run | after: ms_ratio per run | median before | median after | change |")
    print("|---|---|---|---:|---:|---:|")
    for t in before[0]:
        b = [r[t] for r in before]
        a = [r[t] for r in after]
        mb, ma = statistics.median(b), statistics.median(a)
        runs = lambda v: " ".join(f"{x:.2f}" for x in v)
        print(f"| `{t}` | {runs(b)} | {runs(a)} | {mb:.3f} | {ma:.3f} | {100 * (ma / mb - 1):+.1f} % |")


if __name__ == "__main__":
    main(sys.argv[1])
