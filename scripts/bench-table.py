#!/usr/bin/env python3
"""Prints a bench JSON (shadowlab bench --json) as the markdown table used in docs/.

  scripts/bench-table.py F.json           the standard table
  scripts/bench-table.py --path F.json    a run along a camera path (--path): the frames' mean and
                                          p95 time, the mean of the per-frame wrong %, and flicker
"""
import json
import sys

args = sys.argv[1:]
path = "--path" in args
args = [a for a in args if a != "--path"]
j = json.load(open(args[0]))
if path:
    print("| entry | ms/frame mean | ms/frame p95 | wrong % mean (frames) | wrong % max | flicker excess | world flicker | NaN/Inf |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for e in j["entries"]:
        ms = e["ms_per_frame"]["frames"]
        wrong = [c["wrong_pixel_pct"] if isinstance(c, dict) else c for c in e["convergence"]]
        f = e["flicker"]
        print(f"| {e['label']} | {sum(ms) / len(ms):.1f} | {e['ms_per_frame']['p95']:.1f} | "
              f"{sum(wrong) / len(wrong):.3f} | {max(wrong):.3f} | {f['excess']:.2e} | {f['world']:.2e} | "
              f"{e['nonfinite_pixels']} |")
    sys.exit(0)
print("| entry | ms/frame median | × entry 1 (p25–p75) | wrong % | false shadow % | false light % | image wrong % | RMSE | NaN/Inf |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
for e in j["entries"]:
    m, err, r = e["ms_per_frame"], e["error"], e["ms_ratio"]
    print(f"| {e['label']} | {m['median']:.1f} | {r['median']:.2f} ({r['p25']:.2f}–{r['p75']:.2f}) | "
          f"{err['wrong_pixel_pct']:.3f} | {err['false_shadow_pct']:.3f} | {err['false_light_pct']:.3f} | "
          f"{err['image_wrong_pct']:.3f} | {err['rmse']:.4f} | {e['nonfinite_pixels']} |")
