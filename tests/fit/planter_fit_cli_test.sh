#!/usr/bin/env bash
# planter-fit's bad input: one message with the file and line, exit code 2, no outputs.
set -uo pipefail
tool=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fails=0
expect() {  # expect PATTERN FILE
  local out rc
  out=$("$tool" "$2" --out "$work/out" 2>&1 >/dev/null)
  rc=$?
  if [ "$rc" -ne 2 ] || ! grep -q -- "$1" <<<"$out" || [ "$(wc -l <<<"$out")" -ne 1 ]; then
    echo "FAIL: $(basename "$2") -> exit $rc, '$out' (wanted 2 and /$1/)"
    fails=$((fails + 1))
  fi
  if [ -e "$work/out/fit.json" ]; then
    echo "FAIL: $(basename "$2") left outputs behind"
    fails=$((fails + 1))
  fi
}
rows() { for i in $(seq 0 99); do echo "0.$(printf %02d "$i"),1,2"; done; }
{ echo "omega_cmd,omega"; rows; } | cut -d, -f2- >"$work/no_time.csv"
expect "no 't' column" "$work/no_time.csv"
{ echo "t,omega_cmd,omega"; rows; echo "1.5,x,2"; } >"$work/text.csv"
expect "text.csv:102: column 'omega_cmd': 'x' is not a number" "$work/text.csv"
{ echo "t,omega_cmd,omega"; rows; echo "0.5,1,2"; } >"$work/back.csv"
expect "back.csv:102: time 0.5 s does not increase" "$work/back.csv"
{ echo "t,omega_cmd,omega"; rows; echo "1.5,nan,2"; } >"$work/nan.csv"
expect "nan.csv:102:.*NaN" "$work/nan.csv"
{ echo "# sync_period_s: 10ms"; echo "t,omega_cmd,omega"; rows; } >"$work/sync_text.csv"
expect "sync_text.csv:1: metadata sync_period_s: '10ms' must be the SYNC period in seconds, in (0, 1]" "$work/sync_text.csv"
{ echo "# sync_period_s: 0"; echo "t,omega_cmd,omega"; rows; } >"$work/sync_zero.csv"
expect "sync_zero.csv:1: metadata sync_period_s: '0' must be" "$work/sync_zero.csv"
{ echo "t,omega_cmd,omega"; echo "0,1,2"; } >"$work/short.csv"
expect "too short" "$work/short.csv"
{ echo "t,temperature,humidity"; rows; } >"$work/nothing.csv"
expect "no observable subsystem" "$work/nothing.csv"
expect "missing.csv: no such file" "$work/missing.csv"
mkfifo "$work/fifo.csv"
expect "fifo.csv: is a FIFO, not a regular file" "$work/fifo.csv"
mkdir "$work/dir.csv"
expect "dir.csv: is a directory, not a file" "$work/dir.csv"
# A 1 MB cell gives a short message, not a 1 MB one (cut, with its size).
{ echo "t,omega_cmd,omega"; rows; printf '1.5,'; head -c 1000000 /dev/zero | tr '\0' 'x'; echo ",2"; } >"$work/big.csv"
expect "big.csv:102: column 'omega_cmd': 'xxxxxxxxxx.*\.\.\. (1000000 bytes)' is not a number" "$work/big.csv"
: >"$work/empty.csv"
expect "no header" "$work/empty.csv"
# A bad --model file: its line and key, exit 2.
{ echo "t,omega_cmd,omega"; rows; } >"$work/good.csv"
printf '[[channel]]\noutput = "omega"\nT_d = 0.1\n' >"$work/model.toml"
out=$("$tool" "$work/good.csv" --model "$work/model.toml" --out "$work/out" 2>&1 >/dev/null)
rc=$?
if [ "$rc" -ne 2 ] || ! grep -q "model.toml:1: 'channel\[0\].omega_max'" <<<"$out"; then
  echo "FAIL: bad --model -> exit $rc, '$out'"
  fails=$((fails + 1))
fi
# Windows files: a UTF-8 byte-order mark before the header, CRLF line ends, and a cell of
# 1e-310 (a denormal, still a number) are read; the fit runs and writes its set.
{ printf '\xef\xbb\xbf'; echo "t,omega_cmd,omega"; for i in $(seq 0 299); do
  c=$(( (i / 50) % 2 )); [ "$i" -eq 0 ] && c=1e-310
  echo "$((i / 100)).$(printf %02d $((i % 100))),$c,$(( (i / 50) % 2 ))"; done; } | sed 's/$/\r/' >"$work/bom.csv"
out=$("$tool" "$work/bom.csv" --out "$work/bom-out" 2>&1 >/dev/null)
rc=$?
if [ "$rc" -ne 0 ] || [ ! -f "$work/bom-out/run.json" ]; then
  echo "FAIL: BOM + CRLF + 1e-310 -> exit $rc, '$out'"
  fails=$((fails + 1))
fi
# --out over a directory that is not a fit's is refused before the analysis; --force replaces it.
mkdir -p "$work/mine" && echo keep >"$work/mine/notes.txt"
out=$("$tool" "$work/bom.csv" --out "$work/mine" 2>&1 >/dev/null)
rc=$?
if [ "$rc" -ne 1 ] || ! grep -q "mine: holds files that are not the output of 'planter-fit'" <<<"$out" ||
  [ ! -f "$work/mine/notes.txt" ]; then
  echo "FAIL: foreign --out -> exit $rc, '$out'"
  fails=$((fails + 1))
fi
if ! "$tool" "$work/bom.csv" --out "$work/mine" --force >/dev/null 2>&1 || [ -e "$work/mine/notes.txt" ] ||
  [ ! -f "$work/mine/fit.json" ]; then
  echo "FAIL: --force did not replace the directory with the fit's set"
  fails=$((fails + 1))
fi
[ "$fails" -eq 0 ] && echo "planter-fit bad input: all rejected with exit 2 and one message"
exit "$fails"
