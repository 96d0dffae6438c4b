#!/usr/bin/env bash
# Bad input to planter-sim: one clear message naming file, line and key; exit code 2.
set -u
sim=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
expect() {  # expect NAME PATTERN -- command...
  local name=$1 pattern=$2
  shift 3
  out=$("$@" 2>&1)
  rc=$?
  if [ "$rc" -ne 2 ] || ! grep -qE "$pattern" <<<"$out"; then
    echo "FAIL $name: exit $rc, output: $out"
    fail=1
  else
    echo "ok   $name: $out"
  fi
}
cp "$src/scenarios/zhangqiu-field.toml" "$tmp/s.toml"
sed -i "s|\.\./boards|$src/boards|; s|\.\./models|$src/models|" "$tmp/s.toml"
printf '\n[route2]\nx = 1\n' >>"$tmp/s.toml"
expect unknown-table "s.toml:[0-9]+: 'route2': unknown key" -- "$sim" run "$tmp/s.toml" --out "$tmp/o"
sed "s|speed_mps = 0.06|speed_mps = 7|" "$src/scenarios/zhangqiu-field.toml" | sed "s|\.\./boards|$src/boards|; s|\.\./models|$src/models|" >"$tmp/r.toml"
expect out-of-range "r.toml:[0-9]+: 'route.speed_mps': 7 is out of range; allowed \[0.005, 1\] m/s" -- "$sim" run "$tmp/r.toml" --out "$tmp/o"
sed "s|^stops = .*|stops = [{ at_m = 14.2, duration_s = 6.0, planting_off = true }]|" "$src/scenarios/zhangqiu-field.toml" | sed "s|\.\./boards|$src/boards|; s|\.\./models|$src/models|" >"$tmp/p.toml"
expect short-planting-off-stop "p.toml:[0-9]+: 'route.stops\[0\].duration_s': must be at least start_delay_s \+ 5 s" -- "$sim" run "$tmp/p.toml" --out "$tmp/o"
printf '[scenario\n' >"$tmp/broken.toml"
expect syntax "broken.toml:1:" -- "$sim" run "$tmp/broken.toml" --out "$tmp/o"
expect missing-file "cannot open file" -- "$sim" run "$tmp/none.toml" --out "$tmp/o"
expect bad-option "" -- "$sim" run
exit $fail
