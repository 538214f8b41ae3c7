#!/usr/bin/env python3
"""The every-preset cost table of docs/performance.md from scripts/bench-presets.sh's JSONs.

  scripts/performance-table.py COLUMN=FILE.json ...
  scripts/performance-table.py --ratios COLUMN=FILE.json ...   (ms_ratio only, and the aim)

One row per preset, one column per file: ms_ratio median (frame time over standard's at the same
frame, one interleaved run), then the pass that costs the preset most with its median ms. The
first row gives standard's own median frame time.
"""
import json
import sys

# Issue "Interactive everywhere": at most 3x standard, 4x for these.
FOUR = {"alias-free", "alias-free-pixel-correct", "convolution", "convolution-soft", "lvsm"}
ratios_only = len(sys.argv) > 1 and sys.argv[1] == "--ratios"
cols = []
for arg in sys.argv[2 if ratios_only else 1:]:
    name, path = arg.split("=", 1)
    cols.append((name, {e["label"]: e for e in json.load(open(path))["entries"]}))
labels = list(cols[0][1])
if ratios_only:
    print("| preset | aim | " + " | ".join(n for n, _ in cols) + " |")
    print("|---|---:|" + "---:|" * len(cols))
    for label in labels:
        cells = []
        for _, entries in cols:
            e = entries.get(label)
            if not e:
                cells.append("")
            elif label == labels[0]:
                cells.append(f"{e['ms_per_frame']['median']:.1f} ms")
            else:
                aim = 4.0 if label in FOUR else 3.0
                r = e["ms_ratio"]["median"]
                cells.append(f"{r:.2f}" if r <= aim else f"**{r:.2f}**")
        aim = "" if label == labels[0] else ("4" if label in FOUR else "3")
        print(f"| {label} | {aim} | " + " | ".join(cells) + " |")
    sys.exit(0)
print("| preset | " + " | ".join(f"{n} ms_ratio | {n} costliest pass (ms)" for n, _ in cols) + " |")
print("|---|" + "---:|---|" * len(cols))
for label in labels:
    cells = []
    for _, entries in cols:
        e = entries.get(label)
        if not e:
            cells += ["", ""]
            continue
        r = e["ms_ratio"]
        top = max(e.get("passes", []), key=lambda p: p["ms"], default=None)
        ratio = f"{e['ms_per_frame']['median']:.1f} ms" if label == labels[0] else f"{r['median']:.2f}"
        cells += [ratio, f"{top['name']} {top['ms']:.2f}" if top else ""]
    print(f"| {label} | " + " | ".join(cells) + " |")
