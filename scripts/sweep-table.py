#!/usr/bin/env python3
"""The cost of a bench sweep's values side by side, per preset and scene.

  scripts/sweep-table.py KEY COLUMN=FILE.json ...

FILE.json is one `shadowlab bench --sweep KEY=a,b,...` run: one row per technique, for each file
its ms_ratio median (frame time over the first entry's at the same frame, one interleaved run)
at each value of KEY, "a / b / ...", bold where over the issue "Interactive everywhere"'s aim
(3x standard, 4x for the presets it names). The first entry (the baseline) gives its frame time.
"""
import json
import sys

FOUR = {"alias-free", "alias-free-pixel-correct", "convolution", "convolution-soft", "lvsm"}


def cell(entries, technique, values, key):
    out = []
    for v in values:
        e = entries.get(f"{technique} {key}={v}")
        if not e:
            return ""
        r = e["ms_ratio"]["median"]
        out.append(f"**{r:.2f}**" if r > (4.0 if technique in FOUR else 3.0) else f"{r:.2f}")
    return " / ".join(out)


def main(key, columns):
    cols = []
    for arg in columns:
        name, path = arg.split("=", 1)
        cols.append((name, json.load(open(path))["entries"]))
    first = cols[0][1]
    values = []
    for e in first:
        v = e.get("sweep", {}).get(key)
        if v is not None and str(v) not in values:
            values.append(str(v))
    techniques = []
    for e in first[1:]:
        if e["technique"] not in techniques:
            techniques.append(e["technique"])
    print(f"| preset | aim | " + " | ".join(f"{n}: {key} {' / '.join(values)}" for n, _ in cols) + " |")
    print("|---|---:|" + "---:|" * len(cols))
    print(f"| {first[0]['technique']} (ms) | | " +
          " | ".join(f"{entries[0]['ms_per_frame']['median']:.1f}" for _, entries in cols) + " |")
    for t in techniques:
        cells = [cell({e["label"]: e for e in entries}, t, values, key) for _, entries in cols]
        print(f"| {t} | {4 if t in FOUR else 3} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2:])
