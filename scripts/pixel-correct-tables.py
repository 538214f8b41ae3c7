#!/usr/bin/env python3
"""Prints the markdown tables of techniques/accumulation/README.md ("Measured against the paper")
from the JSON files scripts/bench-pixel-correct.sh writes into the given folder."""
import json
import os
import sys

folder = sys.argv[1] if len(sys.argv) > 1 else "docs/bench/pixel-correct"


def load(name):
    path = os.path.join(folder, name)
    return json.load(open(path)) if os.path.exists(path) else None


def at(curve, frame):
    return curve[min(frame, len(curve)) - 1]


print("## Convergence, wrong % at frames 1 / 20 / 60 (512², 320×180)\n")
print("| scene, history | entry | frame 1 | frame 20 | frame 60 |")
print("|---|---|---:|---:|---:|")
for scene in ("basic", "columns"):
    for history in ("empty", "filled"):
        for suffix in ("", "-keep-best", "-lispsm", "-at-rest"):
            j = load(f"{scene}-{history}{suffix}.json")
            if not j:
                continue
            for e in j["entries"]:
                c = e["convergence"]
                label = e["label"] + (" pc.keep_best=on" if suffix == "-keep-best" else "")
                print(f"| {scene}, {history} | {label} | {at(c, 1):.3f} | {at(c, 20):.3f} | {at(c, 60):.3f} |")
    j = load(f"{scene}-standard-4096.json")
    if j:
        print(f"| {scene} | standard at 4096² | | | {j['entries'][0]['error']['wrong_pixel_pct']:.3f} |")

print("\n## Larger screens: wrong % at frames 1 / 20 / 60, empty history, 512²\n")
print("| scene, size | entry | frame 1 | frame 20 | frame 60 | standard at 4096² |")
print("|---|---|---:|---:|---:|---:|")
for size in ("640x360", "1280x720"):
    for scene in ("basic", "columns"):
        j, big = load(f"{scene}-empty-{size}.json"), load(f"{scene}-standard-4096-{size}.json")
        if not j or not big:
            continue
        ref = big["entries"][0]["error"]["wrong_pixel_pct"]
        for e in j["entries"]:
            c = e["convergence"]
            print(f"| {scene}, {size} | {e['label']} | {at(c, 1):.3f} | {at(c, 20):.3f} | {at(c, 60):.3f} | {ref:.3f} |")

print("\n## Flicker along paths (filled history; 512², 320×180, 60 frames at 30 fps)\n")
print("| scene, path | entry | flicker excess | wrong % (mean over the path) |")
print("|---|---|---:|---:|")
for scene, path in (("basic", "drift"), ("basic", "orbit"), ("columns", "walk")):
    for group in ("standard", "pixel-correct", "at-rest", "lispsm"):
        j = load(f"{scene}-{path}-{group}.json")
        if not j:
            continue
        for e in j["entries"]:
            c = e["convergence"]
            print(f"| {scene}, {path} | {e['label']} | {e['flicker']['excess']:.2e} | {sum(c) / len(c):.3f} |")

print("\n## Cost (1024², 1280×720; both entries interleaved in each run, 5 runs, 3 on sponza)\n")
print("| scene | pixel-correct × standard per run (`ms_ratio` median) | median of runs | standard ms (median of runs) | timer |")
print("|---|---|---:|---:|---|")
for scene in ("basic", "columns", "sponza"):
    runs = [j for j in (load(f"{scene}-cost-1280x720-{r}.json") for r in range(1, 6)) if j]
    if not runs:
        continue
    ratios = sorted(next(e for e in j["entries"] if e["label"] == "pixel-correct")["ms_ratio"]["median"] for j in runs)
    standard = sorted(next(e for e in j["entries"] if e["label"] == "standard")["ms_per_frame"]["median"] for j in runs)
    mid = lambda v: v[len(v) // 2]
    print(f"| {scene} | {', '.join(f'{x:.2f}' for x in ratios)} | {mid(ratios):.2f} | {mid(standard):.1f} | "
          f"{runs[0]['entries'][0]['timer']} |")
