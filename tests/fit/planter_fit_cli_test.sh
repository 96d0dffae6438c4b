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
{ echo "t,omega_cmd,omega"; echo "0,1,2"; } >"$work/short.csv"
expect "too short" "$work/short.csv"
{ echo "t,temperature,humidity"; rows; } >"$work/nothing.csv"
expect "no observable subsystem" "$work/nothing.csv"
expect "cannot be read" "$work/missing.csv"
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
[ "$fails" -eq 0 ] && echo "planter-fit bad input: all rejected with exit 2 and one message"
exit "$fails"
