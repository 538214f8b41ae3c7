#!/usr/bin/env python3
"""Checks the layers of docs/architecture.md from the code's own #include lines (tests excluded:
a test may reach any layer to set up its case).

    core, scene  ->  gl  ->  part (the part SDK)  ->  render | technique families  ->  registry
                 ->  front ends (cli, explorer, bench, tour, plot, metrics, reference)

- app/part/ includes only core, gl, scene and itself: the SDK knows no renderer and no family.
- app/render/ includes no family and not the registry (techniques/technique.h): the renderer
  sees a technique through the SDK alone.
- a family (a folder of techniques/) includes no app/ folder but core, gl, scene, part, and
  not the registry: families are listed by the registry, never the other way round.
- nothing but a family's own folder and the registry includes a family's headers: front ends
  reach a family's parts through the registry and the SDK's virtual functions, never its types.

Prints every include that breaks a rule (file:line) and exits 1 when there is one.
Usage: scripts/layer-check.py"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
BASE = {"core", "gl", "scene"}
FAMILIES = sorted(p.name for p in (ROOT / "techniques").iterdir() if p.is_dir())
REGISTRY_FILES = {"techniques/registry.cpp", "techniques/technique.h", "techniques/param_hints.cpp",
                  "techniques/param_hints.h"}


def is_test(path):
    return path.name.endswith("_test.cpp") or "tests" in path.parts or path.name.endswith("_test_util.h")


def target_of(inc):
    """('app', folder) or ('family', folder) or ('registry', None) for an include path."""
    first = inc.split("/")[0]
    if inc in ("technique.h", "param_hints.h"):
        return "registry", None
    if "/" in inc and first in FAMILIES:
        return "family", first
    if "/" in inc and (ROOT / "app" / first).is_dir():
        return "app", first
    return "other", None


def owner_of(rel):
    parts = rel.split("/")
    if rel in REGISTRY_FILES:
        return "registry", None
    if parts[0] == "techniques" and len(parts) > 2:
        return "family", parts[1]
    if parts[0] == "app" and len(parts) > 2:
        return "app", parts[1]
    return "other", None


def broken(owner, target):
    kind, folder = owner
    tkind, tfolder = target
    if kind == "app" and folder == "part":
        if tkind == "app" and tfolder not in BASE | {"part"}:
            return "the part SDK includes app/" + tfolder
        if tkind in ("family", "registry"):
            return "the part SDK includes a technique family or the registry"
    if kind == "app" and folder == "render" and tkind in ("family", "registry"):
        return "the renderer includes " + ("the registry" if tkind == "registry" else "family " + tfolder)
    if kind == "family":
        if tkind == "app" and tfolder not in BASE | {"part"}:
            return f"family {folder} includes app/{tfolder} (a family sees the renderer through part/ alone)"
        if tkind == "registry":
            return f"family {folder} includes the registry"
    if tkind == "family" and kind != "registry" and not (kind == "family" and folder == tfolder):
        who = f"family {folder}" if kind == "family" else f"app/{folder}"
        return f"{who} includes family {tfolder}'s header (only the registry lists families; share through part/)"
    return None


def main():
    problems = []
    for path in sorted(list((ROOT / "app").rglob("*.[ch]*")) + list((ROOT / "techniques").rglob("*.[ch]*"))):
        if path.suffix not in (".h", ".cpp") or is_test(path):
            continue
        rel = path.relative_to(ROOT).as_posix()
        owner = owner_of(rel)
        for n, line in enumerate(path.read_text().splitlines(), 1):
            m = INCLUDE.match(line)
            if m:
                why = broken(owner, target_of(m.group(1)))
                if why:
                    problems.append(f"{rel}:{n}: #include \"{m.group(1)}\": {why}")
    for p in problems:
        print(p)
    print(f"layer-check: {len(problems)} include(s) against the layers", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
