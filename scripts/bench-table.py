#!/usr/bin/env python3
"""Prints a bench JSON (shadowlab bench --json) as the markdown table used in docs/."""
import json
import sys

j = json.load(open(sys.argv[1]))
print("| entry | ms/frame median | p95 | wrong % | false shadow % | false light % | RMSE | NaN/Inf |")
print("|---|---:|---:|---:|---:|---:|---:|---:|")
for e in j["entries"]:
    m, err = e["ms_per_frame"], e["error"]
    print(f"| {e['label']} | {m['median']:.1f} | {m['p95']:.1f} | {err['wrong_pixel_pct']:.3f} | "
          f"{err['false_shadow_pct']:.3f} | {err['false_light_pct']:.3f} | {err['rmse']:.4f} | {e['nonfinite_pixels']} |")
