#!/usr/bin/env python3
"""The conclusion slide's table and figures from scripts/bench-conclusion.sh's bench JSONs.

usage: conclusion-table.py BENCH_DIR IMAGE_DIR > table.md
Prints one markdown table per scene (family, technique, wrong %, RMSE, ms_ratio p25-p75) and
writes IMAGE_DIR/conclusion-<scene>.svg: wrong pixels (log) against ms_ratio, one point per
technique, coloured by the survey's family.
"""
import glob
import json
import math
import os
import sys

FAMILIES = {
    "standard": "baseline",
    "pcf": "baseline (filtered)",
    "lispsm": "warping",
    "tsm": "warping",
    "psm": "warping",
    "cascaded": "z-partitioning",
    "sdsm": "z-partitioning",
    "virtual": "adaptive partitioning",
    "alias-free": "irregular sampling",
    "pixel-correct": "temporal reprojection",
    "silhouette": "reconstruction",
    "forward": "reconstruction",
}
COLORS = {
    "baseline": "#555555",
    "baseline (filtered)": "#999999",
    "warping": "#1f77b4",
    "z-partitioning": "#2ca02c",
    "adaptive partitioning": "#ff7f0e",
    "irregular sampling": "#d62728",
    "temporal reprojection": "#9467bd",
    "reconstruction": "#8c564b",
}


def family(tech):
    return FAMILIES.get(tech, "other")


def svg(scene, entries, path):
    w, h, ml, mr, mt, mb = 560, 360, 60, 170, 30, 45
    xs = [e["ms_ratio"]["median"] for e in entries]
    ys = [max(e["error"]["wrong_pixel_pct"], 1e-3) for e in entries]
    x0, x1 = 0.0, max(xs) * 1.1
    y0, y1 = math.floor(math.log10(min(ys))), math.ceil(math.log10(max(ys)) + 1e-9)
    if y1 <= y0:
        y1 = y0 + 1

    def px(x):
        return ml + (x - x0) / (x1 - x0) * (w - ml - mr)

    def py(y):
        return h - mb - (math.log10(y) - y0) / (y1 - y0) * (h - mt - mb)

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="11">',
           f'<rect width="{w}" height="{h}" fill="white"/>',
           f'<text x="{ml}" y="18" font-size="13">{scene}: wrong pixels vs cost (one interleaved run)</text>']
    for d in range(y0, y1 + 1):
        y = h - mb - (d - y0) / (y1 - y0) * (h - mt - mb)
        out.append(f'<line x1="{ml}" y1="{y:.1f}" x2="{w - mr}" y2="{y:.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{ml - 6}" y="{y + 4:.1f}" text-anchor="end">{10.0 ** d:g} %</text>')
    step = max(0.5, round(x1 / 6 * 2) / 2)
    x = 0.0
    while x <= x1:
        out.append(f'<line x1="{px(x):.1f}" y1="{mt}" x2="{px(x):.1f}" y2="{h - mb}" stroke="#eee"/>')
        out.append(f'<text x="{px(x):.1f}" y="{h - mb + 14}" text-anchor="middle">{x:g}</text>')
        x += step
    out.append(f'<text x="{(ml + w - mr) / 2}" y="{h - 8}" text-anchor="middle">ms_ratio (frame time / standard)</text>')
    out.append(f'<text x="14" y="{(mt + h - mb) / 2}" transform="rotate(-90 14 {(mt + h - mb) / 2})" '
               'text-anchor="middle">wrong pixels (log)</text>')
    for e, x, y in zip(entries, xs, ys):
        c = COLORS.get(family(e["technique"]), "#000")
        out.append(f'<circle cx="{px(x):.1f}" cy="{py(y):.1f}" r="4.5" fill="{c}"/>')
        out.append(f'<text x="{px(x) + 7:.1f}" y="{py(y) + 4:.1f}">{e["label"]}</text>')
    ly = mt + 5
    for fam, c in COLORS.items():
        if any(family(e["technique"]) == fam for e in entries):
            out.append(f'<circle cx="{w - mr + 20}" cy="{ly}" r="4.5" fill="{c}"/>')
            out.append(f'<text x="{w - mr + 30}" y="{ly + 4}">{fam}</text>')
            ly += 16
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def main():
    bench_dir, image_dir = sys.argv[1], sys.argv[2]
    for path in sorted(glob.glob(os.path.join(bench_dir, "*.json"))):
        j = json.load(open(path))
        scene = j["scene"] if isinstance(j["scene"], str) else os.path.splitext(os.path.basename(path))[0]
        entries = j["entries"]
        print(f"### {scene}\n")
        print(f"`{j['command']}` ({j['date']}, {j['renderer']})\n")
        print("| family | technique | wrong % | false shadow % | false light % | RMSE | ms_ratio median (p25–p75) | NaN/Inf |")
        print("|---|---|---:|---:|---:|---:|---:|---:|")
        for e in sorted(entries, key=lambda e: e["ms_ratio"]["median"]):
            err, r = e["error"], e["ms_ratio"]
            print(f"| {family(e['technique'])} | {e['label']} | {err['wrong_pixel_pct']:.3f} | "
                  f"{err['false_shadow_pct']:.3f} | {err['false_light_pct']:.3f} | {err['rmse']:.4f} | "
                  f"{r['median']:.2f} ({r['p25']:.2f}–{r['p75']:.2f}) | {e['nonfinite_pixels']} |")
        print()
        name = os.path.basename(path)[:-5]
        svg(scene, entries, os.path.join(image_dir, f"conclusion-{name}.svg"))
        print(f"![{scene}](images/conclusion-{name}.svg)\n")


main()
