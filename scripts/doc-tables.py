#!/usr/bin/env python3
"""Checks (or rewrites) the tables the docs quote from stored bench JSON.

A generated table in a markdown file is marked by the command that writes it, on its own line:

    <!-- generated: python3 scripts/bench-table.py docs/bench/basic/bench.json -->
    | entry | ... |        (the command's output, up to the next blank line or the end marker)
    <!-- end generated -->

  scripts/doc-tables.py           compare every marked table with what its command prints today;
                                  exits 1 naming the file, line and first differing row
  scripts/doc-tables.py --write   replace each marked table with its command's output

Commands run from the repository root. Only `python3 scripts/...` and `shadowlab list --markdown
TABLE` (the program's declarations; $SHADOWLAB_BINARY or build/shadowlab) are accepted, so a doc
cannot run anything else.
"""
import os
import pathlib
import shlex
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
BEGIN, END = "<!-- generated:", "<!-- end generated -->"


def docs():
    for pattern in ("*.md", "docs/*.md", "techniques/*/*.md"):
        yield from sorted(ROOT.glob(pattern))


def run(command, where):
    args = shlex.split(command)
    if args[:3] == ["shadowlab", "list", "--markdown"] and len(args) == 4:
        # The program's own declarations (parts, presets): the binary CMake built, or build/'s.
        args[0] = os.environ.get("SHADOWLAB_BINARY", str(ROOT / "build" / "shadowlab"))
    elif len(args) < 2 or args[0] != "python3" or not args[1].startswith("scripts/"):
        raise SystemExit(
            f"{where}: only 'python3 scripts/...' or 'shadowlab list --markdown TABLE' may generate a table, not: {command}")
    done = subprocess.run(args, cwd=ROOT, capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"{where}: '{command}' failed ({done.returncode}): {done.stderr.strip()}")
    return done.stdout.rstrip("\n").split("\n")


def blocks(lines):
    """(index of the marker, index of the end marker, command) for each generated block."""
    i = 0
    while i < len(lines):
        if lines[i].startswith(BEGIN):
            command = lines[i][len(BEGIN):].rsplit("-->", 1)[0].strip()
            end = i + 1
            while end < len(lines) and lines[end] != END:
                end += 1
            if end == len(lines):
                raise SystemExit(f"line {i + 1}: '{BEGIN}' without '{END}'")
            yield i, end, command
            i = end
        i += 1


def main():
    write = "--write" in sys.argv[1:]
    failures, checked = [], 0
    for doc in docs():
        lines = doc.read_text().split("\n")
        out, last = [], 0
        changed = False
        for begin, end, command in blocks(lines):
            where = f"{doc.relative_to(ROOT)}:{begin + 1}"
            fresh = run(command, where)
            stored = lines[begin + 1:end]
            checked += 1
            if stored != fresh:
                changed = True
                row = next((k for k, (a, b) in enumerate(zip(stored, fresh)) if a != b), min(len(stored), len(fresh)))
                failures.append(f"{where}: the table differs from '{command}' at its row {row + 1}:\n"
                                f"  doc:    {stored[row] if row < len(stored) else '(missing)'}\n"
                                f"  script: {fresh[row] if row < len(fresh) else '(missing)'}")
            out += lines[last:begin + 1] + fresh
            last = end
        out += lines[last:]
        if write and changed:
            doc.write_text("\n".join(out))
    if write:
        print(f"doc-tables: {checked} generated table(s), {len(failures)} rewritten")
        return 0
    for f in failures:
        print(f)
    print(f"doc-tables: {checked} generated table(s), {len(failures)} differ"
          + (" (scripts/doc-tables.py --write regenerates them)" if failures else ""))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
