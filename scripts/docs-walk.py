#!/usr/bin/env python3
"""The docs' commands, run as a new user would: each page in order (README.md, then docs/*.md),
each command on a terminal, timed to its first output (issue 54: every command that runs over
2 s shows progress within 2 s).

    scripts/docs-walk.py BUILD [SECONDS]

A command is a line of an indented block, or an inline `code` span, that starts with
build/apps/, man -l or ctest --test-dir and holds no placeholder (<...>, [...], an upper-case
word such as DIR). The two README commands are this run's own (CI runs scripts/test.sh from a
fresh clone; scripts/field-trial.sh is timed by scripts/bench-field-trial-build.sh), and the
pages' own scripts (scripts/fit-proof.sh, scripts/cross-test.sh, ...) are stages of it.

Each runs in a scratch folder that holds links to the tree's inputs and to BUILD, so what it
writes (out/...) lands there, never in the checkout. It runs to its end or for SECONDS (default
8) after its first output, then gets SIGINT, as a user would press Ctrl-C (a console serves until
then). Each command's line: its first output's time, how it ended and its longest silence
after that (a count that freezes shows there). The figure last:
`docs walk: N of M commands printed within 2 s, K of them never silent longer`. Exit 1 when a command failed (a non-zero exit
before it was stopped) or printed nothing for 30 s: a silence that long is no timing flake.
"""
import os
import pty
import re
import select
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PAGES = [ROOT / "README.md"] + sorted((ROOT / "docs").glob("*.md"))
STARTS = ("build/apps/", "man -l ", "ctest --test-dir ")
PLACEHOLDER = re.compile(r"<|\[|\.\.\.|\b[A-Z]{2,}\b")
INPUTS = ("scenarios", "machines", "boards", "models", "packaging")
# A server says where it serves and then waits for its user: its silence is no stall.
SERVERS = ("build/apps/planter-sim/planter-sim live ",)
PROMPT_S = 2.0
SILENT_S = 30.0


def commands(page, seen):
    """The page's commands in order, each once over all pages (`seen`)."""
    out = []
    for line in page.read_text().split("\n"):
        found = []
        if line.startswith("    "):
            found.append(line.strip().split("  #")[0].strip())
        found += re.findall(r"`([^`]+)`", line)
        for c in found:
            if c.startswith(STARTS) and not PLACEHOLDER.search(c) and c not in seen:
                seen.add(c)
                out.append(c)
    return out


def scratch_tree(build):
    d = Path(tempfile.mkdtemp(prefix="docs-walk-"))
    (d / "build").symlink_to(build)
    for name in INPUTS:
        (d / name).symlink_to(ROOT / name)
    return d


def read_some(fd, timeout):
    ready, _, _ = select.select([fd], [], [], timeout)
    if not ready:
        return b""
    try:
        return os.read(fd, 65536) or b""
    except OSError:  # the terminal closed: the command ended
        return b""


def run(command, cwd, window):
    """(seconds to first output or None, how it ended (with its longest silence), whether it
    failed, its last line, its longest silence)."""
    main, sub = pty.openpty()
    # man's pager would wait for a key: the page is printed as it is.
    env = dict(os.environ, MANPAGER="cat", PAGER="cat")
    # Ctrl-C as on a terminal: a background job of a script (CI's) starts with SIGINT ignored,
    # and an ignored signal stays ignored across exec.
    proc = subprocess.Popen(shlex.split(command), cwd=cwd, stdin=subprocess.DEVNULL,
                            stdout=sub, stderr=sub, start_new_session=True, env=env,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    os.close(sub)
    start = time.monotonic()
    first = None
    last_out, silence = 0.0, 0.0  # the longest stretch without output, once it has printed
    text = b""
    stopped, stopped_at = False, 0.0
    while True:
        now = time.monotonic() - start
        limit = (first + window) if first is not None else SILENT_S
        if now >= limit:
            stopped_at = now  # what the walk saw; the wait for the command to end is not silence
            os.killpg(proc.pid, signal.SIGINT)
            stopped = True
            break
        chunk = read_some(main, min(0.1, limit - now))
        if chunk.strip():
            at = time.monotonic() - start
            if first is None:
                first = at
            silence = max(silence, at - last_out)
            last_out = at
        text += chunk
        if not chunk and proc.poll() is not None:
            break
    try:
        code = proc.wait(timeout=10)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        code = proc.wait()
    while chunk := read_some(main, 0.05):
        text += chunk
    os.close(main)
    lines = [l for l in text.decode(errors="replace").replace("\r", "\n").split("\n") if l.strip()]
    last = lines[-1].strip() if lines else ""
    end = time.monotonic() - start
    if stopped:
        ended = "stopped (Ctrl-C) after %.1f s, still running; ended %.1f s later" % (
            stopped_at, end - stopped_at)
        silence = max(silence, stopped_at - last_out)
    else:
        ended = "ended in %.1f s, exit %d" % (end, code)
    ended += "; longest silence %.1f s" % silence
    failed = (not stopped and code != 0) or (stopped and first is None)
    return first, ended, failed, last, silence


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    build = Path(sys.argv[1]).resolve()
    window = float(sys.argv[2]) if len(sys.argv) > 2 else 8.0
    cwd = scratch_tree(build)
    total = prompt = talking = failed = 0
    slowest = (0.0, "")
    seen = set()
    for page in PAGES:
        for c in commands(page, seen):
            first, ended, bad, last, silence = run(c, cwd, window)
            total += 1
            talking += first is not None and (silence <= PROMPT_S or c.startswith(SERVERS))
            took = first if first is not None else float("inf")
            prompt += took <= PROMPT_S
            failed += bad
            if first is not None and first > slowest[0]:
                slowest = (first, c)
            shown = "%.2f s" % first if first is not None else "nothing"
            print("%s %s: %s\n    first output %s; %s%s" % (
                "FAIL" if bad else ("ok  " if took <= PROMPT_S else "SLOW"),
                page.relative_to(ROOT), c, shown, ended,
                "\n    last: " + last[:160] if bad and last else ""), flush=True)
    shutil.rmtree(cwd, ignore_errors=True)
    print("slowest first output: %.2f s (%s)" % slowest)
    print("docs walk: %d of %d commands printed within %g s, %d of them never silent longer%s" % (
        prompt, total, PROMPT_S, talking, "; %d failed" % failed if failed else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
