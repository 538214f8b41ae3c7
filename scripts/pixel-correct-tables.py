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
        for suffix in ("", "-lispsm", "-at-rest"):
            j = load(f"{scene}-{history}{suffix}.json")
            if not j:
                continue
            for e in j["entries"]:
                c = e["convergence"]
                print(f"| {scene}, {history} | {e['label']} | {at(c, 1):.3f} | {at(c, 20):.3f} | {at(c, 60):.3f} |")
    j = load(f"{scene}-standard-4096.json")
    if j:
        print(f"| {scene} | standard at 4096² | | | {j['entries'][0]['error']['wrong_pixel_pct']:.3f} |")

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

print("\n## Cost (1024², 1280×720, same run)\n")
print("| scene | standard ms | pixel-correct ms | ratio | timer |")
print("|---|---:|---:|---:|---|")
for scene in ("basic", "columns"):
    j = load(f"{scene}-cost-1280x720.json")
    if not j:
        continue
    ms = {e["label"]: e["ms_per_frame"]["median"] for e in j["entries"]}
    ratio = ms["pixel-correct"] / ms["standard"]
    print(f"| {scene} | {ms['standard']:.1f} | {ms['pixel-correct']:.1f} | {ratio:.2f} | {j['entries'][0]['timer']} |")
