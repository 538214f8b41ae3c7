#!/usr/bin/env python3
"""Lists C++ function bodies longer than a limit (default 80 lines) under the given folders.

A heuristic reader, not a parser: a body starts at a line ending in `{` whose text (joined with
the lines before it up to the previous `;`, `}` or blank line) looks like a function head
(a `(`, no control keyword, not a class/struct/namespace/enum/lambda) at namespace or class depth,
and ends at its matching `}`. Lambdas and nested blocks count toward their function.

Usage: scripts/long-functions.py [--limit N] [--check] DIR...   (--check: exit 1 when any is over)"""
import pathlib
import re
import sys

CONTROL = re.compile(r"^\s*(if|for|while|switch|else|do|try|catch)\b|\belse\b\s*$")
NOT_FUNCTION = re.compile(r"\b(class|struct|namespace|enum|union)\b|=\s*\[|\[[^\]]*\]\s*\(|^\s*\[")


def functions(path):
    """(length, first line, name) of each function body in the file."""
    lines = path.read_text(errors="replace").split("\n")
    stack, head, out, current = [], "", [], None  # stack: "ns", "cls" or "blk" per open brace
    for n, raw in enumerate(lines, 1):
        line = re.sub(r"//.*", "", raw)
        line = re.sub(r'"(\\.|[^"\\])*"', '""', line)
        line = re.sub(r"'(\\.|[^'\\])'", "''", line)
        stripped = line.strip()
        if stripped.startswith("#"):
            continue
        text = (head + " " + stripped).strip()
        for ch in line:
            if ch == "{":
                if current is None and "blk" not in stack and "(" in text and not CONTROL.search(stripped) \
                        and not NOT_FUNCTION.search(text):
                    name = re.sub(r"\s+", " ", text.split("(")[0]).split(" ")[-1]
                    current = (n, len(stack), name)
                    stack.append("blk")
                elif re.search(r"\bnamespace\b", text):
                    stack.append("ns")
                elif re.search(r"\b(class|struct|union)\b", text) and "blk" not in stack:
                    stack.append("cls")
                else:
                    stack.append("blk")
            elif ch == "}" and stack:
                stack.pop()
                if current is not None and len(stack) == current[1]:
                    out.append((n - current[0] + 1, current[0], current[2]))
                    current = None
        if stripped == "" or stripped.endswith((";", "}", "{")):
            head = ""
        else:
            head = (head + " " + stripped)[-300:]
    return out


def main(argv):
    limit, check, dirs = 80, False, []
    it = iter(argv)
    for a in it:
        if a == "--limit":
            limit = int(next(it))
        elif a == "--check":
            check = True
        else:
            dirs.append(a)
    over = []
    for d in dirs:
        for p in sorted(pathlib.Path(d).rglob("*.cpp")):
            for length, line, name in functions(p):
                if length > limit:
                    over.append((length, f"{p}:{line}", name))
    for length, where, name in sorted(over, reverse=True):
        print(f"{length:5d}  {where}  {name}")
    print(f"long-functions: {len(over)} over {limit} lines", file=sys.stderr)
    return 1 if check and over else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
