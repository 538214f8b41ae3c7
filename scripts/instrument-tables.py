#!/usr/bin/env python3
"""Prints the per-scene tables of docs/benchmarks.md ("Every technique against the reference")
from the JSON files scripts/bench-instruments.sh writes into the given folder."""
import json
import os
import sys

folder = sys.argv[1] if len(sys.argv) > 1 else "docs/bench/instruments"
print("| scene | entry | wrong % | false shadow % | false light % | image wrong % | × standard (p25–p75) |")
print("|---|---|---:|---:|---:|---:|---:|")
for name in sorted(os.listdir(folder)):
    if not name.endswith(".json"):
        continue
    j = json.load(open(os.path.join(folder, name)))
    for e in j["entries"]:
        err, r = e["error"], e["ms_ratio"]
        print(f"| {j['scene']} | {e['label']} | {err['wrong_pixel_pct']:.3f} | {err['false_shadow_pct']:.3f} | "
              f"{err['false_light_pct']:.3f} | {err['image_wrong_pct']:.3f} | {r['median']:.2f} ({r['p25']:.2f}–{r['p75']:.2f}) |")
