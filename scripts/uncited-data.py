#!/usr/bin/env python3
"""Lists the stored bench data and figures (JSON, PNG, SVG, CSV, HTML under docs/ and
techniques/) that nothing in the docs cites: no Markdown file names them, by path, by a
pattern (`{a,b}`, `{1..5}`, `*`, `<scene>`), or by file name; nor a script that turns them
into a table the docs quote (scripts/*.py). Such files are kept by nobody's reading: delete them.

Usage: scripts/uncited-data.py [--delete]   exits 1 when any is uncited (and not deleted)."""
import fnmatch
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
DATA = (".json", ".png", ".svg", ".csv", ".html")
TOKEN = re.compile(r"[\w./{}*,<>\-]+\.(?:json|png|svg|csv|html)")
FOLDER = re.compile(r"[\w.{}*,<>\-]+(?:/[\w.{}*,<>\-]+)+/(?=[`)\s])")  # docs/bench/x/: all in it


def tracked(*patterns):
    out = subprocess.run(["git", "ls-files", *patterns], cwd=ROOT, capture_output=True, text=True, check=True)
    return out.stdout.split()


def expand(token):
    """Brace expansion ({a,b} and {1..5}) of one token; <name> reads as *."""
    token = re.sub(r"<[^>]*>", "*", token)
    m = re.search(r"\{([^{}]*)\}", token)
    if not m:
        return [token]
    body = m.group(1)
    rng = re.fullmatch(r"(\d+)\.\.(\d+)", body)
    choices = [str(i) for i in range(int(rng.group(1)), int(rng.group(2)) + 1)] if rng else body.split(",")
    return [e for c in choices for e in expand(token[: m.start()] + c + token[m.end():])]


def citations():
    patterns = set()
    # A bench report (HTML) shows the images of its run folder: it cites them, relative to itself.
    for f in tracked("*.md", "scripts/*.py", "*.html"):
        if f == "scripts/uncited-data.py":
            continue
        text = (ROOT / f).read_text(errors="replace")
        here = str(pathlib.Path(f).parent) + "/" if f.endswith(".html") else ""
        for token in TOKEN.findall(text):
            patterns.update(here + p.lstrip("./") for p in expand(token.strip(",")))
        for token in FOLDER.findall(text):
            patterns.update(here + p.lstrip("./") + "*" for p in expand(token))
    return patterns


def main():
    patterns = citations()
    data = [f for f in tracked("docs", "techniques") if f.endswith(DATA)]
    uncited = [f for f in data if not any(fnmatch.fnmatch(f, "*" + p) for p in patterns)]
    for f in uncited:
        print(f"uncited: {f}")
    if uncited and "--delete" in sys.argv[1:]:
        subprocess.run(["git", "rm", "-q", *uncited], cwd=ROOT, check=True)
        print(f"deleted {len(uncited)} uncited files")
        return 0
    print(f"{len(data) - len(uncited)} of {len(data)} stored data files are cited")
    return 1 if uncited else 0


if __name__ == "__main__":
    sys.exit(main())
