#!/usr/bin/env python3
"""Markdown tables of techniques/irregular/bench.sh's JSON files (alias-free against standard)."""
import glob
import json
import os
import sys

out = sys.argv[1]


def load(path):
    j = json.load(open(path))
    e = {x["technique"]: x for x in j["entries"]}
    return j, e["standard"], e["alias-free"]


def izb_ms(entry):
    return sum(p["ms"] for p in entry["passes"] if p["name"].startswith("izb."))


def row(path, key):
    j, std, izb = load(path)
    return "| %s | %s | %.3f | %.3f | %.2f (%.2f-%.2f) | %.0f | %.0f |" % (
        key, j["size"] if isinstance(j["size"], str) else "%dx%d" % tuple(j["size"]),
        std["error"]["wrong_pixel_pct"], izb["error"]["wrong_pixel_pct"],
        izb["ms_ratio"]["median"], izb["ms_ratio"]["p25"], izb["ms_ratio"]["p75"],
        izb["ms_per_frame"]["median"], izb_ms(izb))


head = ("| %s | size | standard wrong %% | alias-free wrong %% | ms_ratio (p25-p75) | alias-free ms/frame | "
        "of which izb passes ms (last frame) |\n|---|---|---|---|---|---|---|")
for prefix, title in [("scene-", "scene"), ("size-", "scene, size"), ("tris-", "sphere segments")]:
    files = sorted(glob.glob(os.path.join(out, prefix + "*.json")),
                   key=lambda p: [int(t) if t.isdigit() else t for t in os.path.basename(p).replace("x", "-").replace(".", "-").split("-")])
    if not files:
        continue
    print(head % title)
    for f in files:
        print(row(f, os.path.basename(f)[len(prefix):-5]))
    print()
