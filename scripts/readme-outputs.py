#!/usr/bin/env python3
"""The printed outputs of the README and the docs (docs/*.md), from real runs.

Each block of those pages that shows what a command prints follows a marker line

    <!-- output NAME: COMMAND -->

and is the indented block after it. COMMAND runs from the repository root with BUILD for the
build directory and OUT for a scratch directory.

    scripts/readme-outputs.py update BUILD [NAME...]   rewrite the blocks from fresh runs
    scripts/readme-outputs.py check BUILD NAME...      exit 1 if a block differs from a run

A check compares every line but the figures that measure this machine (wall seconds, real-time
factors), so the README cannot drift from what the commands print.
"""
import re
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PAGES = [ROOT / "README.md"] + sorted((ROOT / "docs").glob("*.md"))
MARKER = re.compile(r"^<!-- output ([\w-]+): (.*) -->$")
# The figures that measure the machine, not the software.
TIMING = [re.compile(p) for p in (r"\d+(\.\d+)? s wall", r"\d+x real time", r"\d+ jobs",
                                   r"\d+x one nominal simulation pass of all rows \([\d.]+ s\)")]


def blocks(lines):
    """(name, command, first line, end line) of each marked block."""
    out = []
    for i, line in enumerate(lines):
        m = MARKER.match(line)
        if not m:
            continue
        start = i + 1
        while start < len(lines) and lines[start].strip() == "":
            start += 1
        end = start
        while end < len(lines) and (lines[end].startswith("    ") or (
                lines[end].strip() == "" and end + 1 < len(lines)
                and lines[end + 1].startswith("    "))):
            end += 1
        out.append((m.group(1), m.group(2), start, end))
    return out


def run(command, build, scratch):
    cmd = command.replace("BUILD", str(build)).replace("OUT", str(scratch))
    done = subprocess.run(shlex.split(cmd), cwd=ROOT, capture_output=True, text=True,
                          stdin=subprocess.DEVNULL, timeout=900)
    if done.returncode != 0:
        sys.exit("readme-outputs: '%s' exited %d:\n%s" % (cmd, done.returncode, done.stderr))
    text = done.stdout.replace(str(scratch), "out").replace(str(build), "build")
    return ["    " + l if l else "" for l in text.rstrip("\n").split("\n")]


def masked(line):
    for t in TIMING:
        line = t.sub("<timing>", line)
    return line


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in ("update", "check"):
        sys.exit(__doc__)
    mode, build, names = sys.argv[1], Path(sys.argv[2]).resolve(), sys.argv[3:]
    pages = {page: page.read_text().split("\n") for page in PAGES}
    found = {page: blocks(lines) for page, lines in pages.items()}
    every = [b[0] for page in found for b in found[page]]
    twice = {n for n in every if every.count(n) > 1}
    if twice:
        sys.exit("readme-outputs: blocks named twice: %s" % ", ".join(sorted(twice)))
    unknown = set(names) - set(every)
    if unknown:
        sys.exit("readme-outputs: no block named %s in README.md or docs/" % ", ".join(sorted(unknown)))
    failed = 0
    for page, lines in pages.items():
        where = page.relative_to(ROOT)
        # From the last block up, so that rewriting one does not move the next.
        for name, command, start, end in reversed(found[page]):
            if names and name not in names:
                continue
            with tempfile.TemporaryDirectory() as scratch:
                fresh = run(command, build, Path(scratch) / "out")
            if mode == "update":
                lines[start:end] = fresh
                print("updated %s in %s (%d lines)" % (name, where, len(fresh)))
                continue
            old = lines[start:end]
            if [masked(l) for l in old] != [masked(l) for l in fresh]:
                failed += 1
                print("%s block '%s' differs from '%s':" % (where, name, command))
                for a, b in zip(old + [""] * len(fresh), fresh + [""] * len(old)):
                    if masked(a) != masked(b):
                        print("  page: %s\n  run:  %s" % (a.strip(), b.strip()))
                print("  (scripts/readme-outputs.py update BUILD %s rewrites it)" % name)
            else:
                print("ok   %s block '%s' is what '%s' prints" % (where, name, command))
        if mode == "update":
            page.write_text("\n".join(lines))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
