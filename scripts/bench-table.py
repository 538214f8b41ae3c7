#!/usr/bin/env python3
"""Prints a bench JSON (shadowlab bench --json) as the markdown table used in docs/."""
import json
import sys

j = json.load(open(sys.argv[1]))
print("| entry | ms/frame median | × entry 1 (p25–p75) | wrong % | false shadow % | false light % | image wrong % | RMSE | NaN/Inf |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
for e in j["entries"]:
    m, err, r = e["ms_per_frame"], e["error"], e["ms_ratio"]
    print(f"| {e['label']} | {m['median']:.1f} | {r['median']:.2f} ({r['p25']:.2f}–{r['p75']:.2f}) | "
          f"{err['wrong_pixel_pct']:.3f} | {err['false_shadow_pct']:.3f} | {err['false_light_pct']:.3f} | "
          f"{err['image_wrong_pct']:.3f} | {err['rmse']:.4f} | {e['nonfinite_pixels']} |")
