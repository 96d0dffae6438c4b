#!/usr/bin/env bash
# Issue 28, item 7: two `planter-sim live` sharing --dir interleaved their rows in one file.
# The second is refused with the directory's name while the first runs, and starts once the
# first has ended; a FIFO as the audit log is refused at once instead of holding the start.
# Exit 1 on a failure.
set -u
sim=$1 src=$2
tmp=$(mktemp -d)
first=""
trap '[ -n "$first" ] && kill "$first" 2>/dev/null; rm -rf "$tmp"' EXIT
fail=0
"$sim" live "$src/scenarios/zhangqiu-field.toml" --port 0 --dir "$tmp/d" --duration 20 \
  >"$tmp/first.log" 2>&1 &
first=$!
for _ in $(seq 100); do grep -q "^console: http" "$tmp/first.log" && break; sleep 0.1; done
grep -q "^console: http" "$tmp/first.log" || { cat "$tmp/first.log"; echo "FAIL the first live did not start"; exit 1; }
timeout 20 "$sim" live "$src/scenarios/zhangqiu-field.toml" --port 0 --dir "$tmp/d" --duration 1 \
  >"$tmp/second.log" 2>&1
rc=$?
if [ $rc -ne 0 ] && [ $rc -ne 124 ] && grep -q "$tmp/d: another planter-sim live uses this directory" "$tmp/second.log"; then
  echo "ok   a second live on the same --dir is refused: $(head -1 "$tmp/second.log")"
else
  echo "FAIL a second live on the same --dir (exit $rc):"; cat "$tmp/second.log"; fail=1
fi
kill "$first"; wait "$first" 2>/dev/null; first=""
timeout 20 "$sim" live "$src/scenarios/zhangqiu-field.toml" --port 0 --dir "$tmp/d" --duration 0.5 \
  --speed 10 >"$tmp/third.log" 2>&1 || { echo "FAIL the directory stayed locked:"; cat "$tmp/third.log"; fail=1; }
mkdir -p "$tmp/f" && mkfifo "$tmp/f/audit.log"
timeout 10 "$sim" live "$src/scenarios/zhangqiu-field.toml" --port 0 --dir "$tmp/f" --duration 1 \
  >"$tmp/fifo.log" 2>&1
rc=$?
if [ $rc -ne 0 ] && [ $rc -ne 124 ] && grep -q "audit.log: the console's audit log must be a regular file" "$tmp/fifo.log"; then
  echo "ok   a FIFO as the audit log is refused at once"
else
  echo "FAIL a FIFO as the audit log (exit $rc):"; cat "$tmp/fifo.log"; fail=1
fi
exit $fail
