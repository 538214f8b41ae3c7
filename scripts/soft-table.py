#!/usr/bin/env python3
"""Markdown tables of the soft-shadow benches (scripts/bench-soft.sh): rmse, wrong pixels and
ms_ratio per technique and scene, and pixel-correct-soft after 1, 20 and 60 still frames."""
import json
import os
import sys

d = sys.argv[1]
scenes = ["contact", "soft", "sponza-sun-disk"]
print("| scene | technique | rmse | wrong % | false light % | false shadow % | ms_ratio (p25-p75) |")
print("|---|---|---|---|---|---|---|")
for s in scenes:
    p = os.path.join(d, s + ".json")
    if not os.path.exists(p):
        continue
    for e in json.load(open(p))["entries"]:
        er, r = e["error"], e["ms_ratio"]
        print(f"| {s} | {e['label']} | {er['rmse']:.4f} | {er['wrong_pixel_pct']:.3f} | {er['false_light_pct']:.3f} "
              f"| {er['false_shadow_pct']:.3f} | {r['median']:.2f} ({r['p25']:.2f}-{r['p75']:.2f}) |")
print()
print("| scene | pixel-correct-soft rmse after 1 | 20 | 60 still frames | pcss rmse |")
print("|---|---|---|---|---|")
for s in scenes:
    p = os.path.join(d, s + ".json")
    if not os.path.exists(p):
        continue
    entries = {e["label"]: e for e in json.load(open(p))["entries"]}
    row = []
    for n in (1, 20):
        q = os.path.join(d, f"{s}-pcsoft-{n}.json")
        row.append(f"{json.load(open(q))['entries'][0]['error']['rmse']:.4f}" if os.path.exists(q) else "-")
    row.append(f"{entries['pixel-correct-soft']['error']['rmse']:.4f}")
    print(f"| {s} | " + " | ".join(row) + f" | {entries['pcss']['error']['rmse']:.4f} |")
