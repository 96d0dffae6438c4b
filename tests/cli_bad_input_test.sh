#!/usr/bin/env bash
# Bad input to planter-sim: one clear message naming file, line and key; exit code 2.
set -u
sim=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
expect() {  # expect NAME PATTERN -- command...   (exit code 2, or $want_rc)
  local name=$1 pattern=$2
  shift 3
  out=$("$@" 2>&1)
  rc=$?
  if [ "$rc" -ne "${want_rc:-2}" ] || ! grep -qE "$pattern" <<<"$out"; then
    echo "FAIL $name: exit $rc, output: $out"
    fail=1
  else
    echo "ok   $name: $out"
  fi
}
# Issue 53, items 13 and 15: a subcommand's typo is named (its bytes escaped), and --help,
# --version and --list-keys that cannot write say so and fail.
expect subcommand-typo "^planter-sim: 'runn' is not a subcommand" -- "$sim" runn
expect subcommand-escaped "'ru.x1b.0;x.x07n' is not a subcommand" -- "$sim" $'ru\x1b]0;x\x07n'
want_rc=1 expect list-keys-full "^planter-sim: cannot write the key reference" -- \
  bash -c "\"$sim\" --list-keys >/dev/full"
want_rc=1 expect help-full "^planter-sim: cannot write to standard output" -- \
  bash -c "\"$sim\" --help >/dev/full"
want_rc=1 expect version-full "^planter-sim: cannot write to standard output" -- \
  bash -c "\"$sim\" --version >/dev/full"
# Issue 53, item 3: a plan's run values go through the scenario's key table and ranges.
plan() {  # plan FILE RUN_JSON: a plan of one run on the field scenario
  printf '{"kind": "planter-sim run plan", "version": 1, "scenario": "%s", "inputs_hash": "x",\n "runs": [%s]}\n' \
    "$src/scenarios/zhangqiu-field.toml" "$2" >"$1"
}
plan "$tmp/p1.json" '{"seed": 1, "distance_m": 10, "operating_point": {"sigma": 0, "depth_mm": 100, "contact_area_mm2": 255}}'
expect plan-sigma-0 "p1.json: 'runs\[0\]\.operating_point\.sigma': 0 is outside 0.5 to 3" -- "$sim" plan-run "$tmp/p1.json" 0
plan "$tmp/p2.json" '{"seed": 1, "distance_m": 1e308}'
expect plan-distance-huge "p2.json: 'runs\[0\]\.distance_m': 1e\+308 is outside 0.1 to 10000 m" -- "$sim" plan-run "$tmp/p2.json" 0
plan "$tmp/p3.json" '{"seed": 1, "distance_m": -5}'
expect plan-distance-negative "p3.json: 'runs\[0\]\.distance_m': -5 is outside" -- "$sim" plan-run "$tmp/p3.json" 0
plan "$tmp/p4.json" '{"seed": 1, "distance_m": 10, "operating_point": {"sigma": 1.5, "depth_mm": 1e308, "contact_area_mm2": 255}}'
expect plan-depth-huge "p4.json: 'runs\[0\]\.operating_point\.depth_mm': 1e\+308 is outside 40 to 160 mm" -- "$sim" plan-run "$tmp/p4.json" 0
plan "$tmp/p5.json" '{"seed": 1, "distance_m": 10, "values": {"seedlings.strength_test_length_mm": 1e308}}'
expect plan-value-huge "p5.json: 'runs\[0\]\.values\.seedlings\.strength_test_length_mm': 1e\+308 is outside" -- "$sim" plan-run "$tmp/p5.json" 0
printf '{"kind": "planter-sim run plan",\n "version": 1,\n "runs": [ {"seed": 1,, }\n' >"$tmp/p6.json"
expect plan-malformed "p6.json:3: is not JSON" -- "$sim" plan-run "$tmp/p6.json" 0
plan "$tmp/p7.json" '{"seed": -1, "distance_m": 10}'
expect plan-seed-negative "p7.json: 'runs\[0\]\.seed': is not a whole number" -- "$sim" plan-run "$tmp/p7.json" 0
# Issue 53, item 14: no library's own words. An index of -1 does not wrap around; a plan with
# no runs says so; a folder that cannot be made names itself and why.
plan "$tmp/p8.json" '{"seed": 1, "distance_m": 10}'
expect plan-index-negative "index: .-1. is not a whole number from 0" -- "$sim" plan-run "$tmp/p8.json" -- -1
printf '{"kind": "planter-sim run plan", "version": 1, "scenario": "%s", "inputs_hash": "x", "runs": []}\n' \
  "$src/scenarios/zhangqiu-field.toml" >"$tmp/p9.json"
want_rc=1 expect plan-empty "p9.json: run 0 is not in the plan \(it has no runs\)" -- "$sim" plan-run "$tmp/p9.json" 0
: >"$tmp/a-file"
want_rc=1 expect out-under-a-file "a-file/sub: cannot be created: Not a directory" -- \
  "$sim" sweep "$src/scenarios/zhangqiu-field.toml" --out "$tmp/a-file/sub/o" --plan-only
# Issue 54, item 6: a scenario on a machine's board says so and names the board.
sed "s|\.\./boards/host-sim|$src/boards/rpi4-canhat|; s|\.\./boards|$src/boards|; s|\.\./models|$src/models|" \
  "$src/scenarios/zhangqiu-field.toml" >"$tmp/hw.toml"
want_rc=0 expect hardware-board "^board +rpi4-canhat: a machine's board; its settings run here" -- \
  "$sim" run "$tmp/hw.toml" --out "$tmp/hw"
cp "$src/scenarios/zhangqiu-field.toml" "$tmp/s.toml"
sed -i "s|\.\./boards|$src/boards|; s|\.\./models|$src/models|" "$tmp/s.toml"
printf '\n[route2]\nx = 1\n' >>"$tmp/s.toml"
expect unknown-table "s.toml:[0-9]+: 'route2': unknown key" -- "$sim" run "$tmp/s.toml" --out "$tmp/o"
sed "s|speed_mps = 0.06|speed_mps = 7|" "$src/scenarios/zhangqiu-field.toml" | sed "s|\.\./boards|$src/boards|; s|\.\./models|$src/models|" >"$tmp/r.toml"
expect out-of-range "r.toml:[0-9]+: 'route.speed_mps': 7 is out of range; allowed \[0.005, 1\] m/s" -- "$sim" run "$tmp/r.toml" --out "$tmp/o"
sed "s|^stops = .*|stops = [{ at_m = 14.2, duration_s = 6.0, planting_off = true }]|" "$src/scenarios/zhangqiu-field.toml" | sed "s|\.\./boards|$src/boards|; s|\.\./models|$src/models|" >"$tmp/p.toml"
expect short-planting-off-stop "p.toml:[0-9]+: 'route.stops\[0\].duration_s': must be at least start_delay_s \+ 5 s" -- "$sim" run "$tmp/p.toml" --out "$tmp/o"
# The draft law proportional to speed is gone: its key is refused with the reason, as is a
# texture D497 does not name.
sed "s|^texture = .*|draft_coeff = 4.8e5|" "$src/scenarios/zhangqiu-field.toml" | sed "s|\.\./boards|$src/boards|; s|\.\./models|$src/models|" >"$tmp/d.toml"
expect old-draft-key "d.toml:[0-9]+: 'soil.draft_coeff': .*ASABE D497" -- "$sim" run "$tmp/d.toml" --out "$tmp/o"
# The tilt formula's keys are refused with what replaced them.
sed "s|^carry_angle_deg = .*|kinematic_gain = 0.2|" "$src/scenarios/zhangqiu-field.toml" | sed "s|\.\./boards|$src/boards|; s|\.\./models|$src/models|" >"$tmp/k.toml"
expect old-tilt-key "k.toml:[0-9]+: 'mechanism.kinematic_gain': .*release mechanics.*root_clearance_mm" -- "$sim" run "$tmp/k.toml" --out "$tmp/o"
# The clamp pitch is the machine's now: a scenario that still sets it is told where it went.
sed "s|^feed_miss_pct = .*|feed_pitch_mm = 44.25|" "$src/scenarios/zhangqiu-field.toml" | sed "s|\.\./boards|$src/boards|; s|\.\./models|$src/models|" >"$tmp/p.toml"
expect old-pitch-key "p.toml:[0-9]+: 'seedlings.feed_pitch_mm': is the machine's: \[planting_monitor\] clamp_pitch_mm" -- "$sim" run "$tmp/p.toml" --out "$tmp/o"
sed "s|^texture = .*|texture = \"loamy\"|" "$src/scenarios/zhangqiu-field.toml" | sed "s|\.\./boards|$src/boards|; s|\.\./models|$src/models|" >"$tmp/x.toml"
expect bad-texture "x.toml:[0-9]+: 'soil.texture': is 'loamy'; allowed: fine, medium, coarse" -- "$sim" run "$tmp/x.toml" --out "$tmp/o"
# Values that go into a Slurm script: a newline would end its line and drop the directives
# after it (issue 53). Refused before anything is written, with the option and the byte (exit
# 1, as the executor's other refusals).
want_rc=1 expect slurm-partition-newline "^planter-sim: --partition: a control character \(0x0a\) at byte 2; a Slurm script's line cannot carry it" -- \
  "$sim" sweep "$src/scenarios/zhangqiu-field.toml" --out "$tmp/slurm" --executor slurm --plan-only \
  --partition "$(printf 'a\n#SBATCH --x')"
want_rc=1 expect slurm-time-limit-tab "^planter-sim: --time-limit: a control character \(0x09\) at byte 3" -- \
  "$sim" montecarlo "$src/scenarios/zhangqiu-field.toml" --out "$tmp/slurm" --executor slurm \
  --plan-only --time-limit "$(printf '10\t5')"
want_rc=1 expect slurm-folder-newline "the plan's folder: a control character \(0x0a\)" -- \
  "$sim" montecarlo "$src/scenarios/zhangqiu-field.toml" --runs 2 --distance 1 --executor slurm \
  --plan-only --out "$tmp/two$(printf '\nlines')"
[ ! -e "$tmp/two"$'\n'"lines.runs/plan.sbatch" ] || { echo "FAIL slurm-folder-newline: a script was written"; fail=1; }
printf '[scenario\n' >"$tmp/broken.toml"
expect syntax "broken.toml:1:" -- "$sim" run "$tmp/broken.toml" --out "$tmp/o"
expect missing-file "none.toml: no such file" -- "$sim" run "$tmp/none.toml" --out "$tmp/o"
expect bad-option "" -- "$sim" run

# Inputs that are not regular files are refused at once, never opened for a blocking read.
mkfifo "$tmp/fifo.toml"
expect fifo "fifo.toml: is a FIFO, not a regular file" -- timeout 10 "$sim" run "$tmp/fifo.toml" --out "$tmp/o"
mkdir "$tmp/dir.toml"
expect directory "dir.toml: is a directory, not a file" -- "$sim" run "$tmp/dir.toml" --out "$tmp/o"
# A scenario saved with a UTF-8 byte-order mark (Windows editors) loads; the run must succeed.
printf '\xef\xbb\xbf' >"$tmp/bom.toml"
sed "s|\.\./boards|$src/boards|; s|\.\./models|$src/models|; s|^distance_m = .*|distance_m = 1.0|; s|^stops = .*|stops = []|" \
  "$src/scenarios/zhangqiu-field.toml" >>"$tmp/bom.toml"
want_rc=0 expect bom-scenario "wrote $tmp/bom-out/" -- "$sim" run "$tmp/bom.toml" --quiet --out "$tmp/bom-out"

# Outputs: a whole set or nothing. A write that fails (file size limit: EFBIG, as a full disk
# gives ENOSPC) exits 1 naming the file and leaves no output directory behind.
want_rc=1 expect write-fails "recording.csv: |cannot be written|write failed" -- \
  bash -c "trap '' XFSZ; ulimit -f 64; exec \"$sim\" run \"$tmp/bom.toml\" --quiet --out \"$tmp/full\""
if [ -e "$tmp/full" ] || compgen -G "$tmp/full.partial-*" >/dev/null; then
  echo "FAIL write-fails: left $(ls -d "$tmp"/full*)"; fail=1
fi
# A second run replaces the first run's set whole; the manifest names every file.
want_rc=0 expect rerun "wrote" -- "$sim" run "$tmp/bom.toml" --quiet --out "$tmp/bom-out"
for f in recording.csv seedlings.csv summary.json report.html; do
  grep -q "\"$f\": $(stat -c %s "$tmp/bom-out/$f")" "$tmp/bom-out/run.json" || {
    echo "FAIL manifest: $f missing or of another size in run.json"; fail=1; }
done
# --out over a directory holding something else is refused unless --force.
mkdir "$tmp/mine" && echo keep >"$tmp/mine/notes.txt"
want_rc=1 expect foreign-out "mine: holds files that are not the output of .planter-sim run. .*--force" -- \
  "$sim" run "$tmp/bom.toml" --quiet --out "$tmp/mine"
[ -f "$tmp/mine/notes.txt" ] || { echo "FAIL foreign-out: notes.txt was removed"; fail=1; }
echo x >"$tmp/afile"
want_rc=1 expect out-is-file "afile: exists and is not a directory" -- "$sim" run "$tmp/bom.toml" --quiet --out "$tmp/afile"
# User strings are escaped in HTML: a scenario named </script> cannot end a script element.
sed 's|^name = .*|name = "x</script><b>y"|' "$tmp/bom.toml" >"$tmp/html.toml"
want_rc=0 expect html-name "wrote" -- "$sim" run "$tmp/html.toml" --quiet --out "$tmp/html-out"
if grep -q "</script><b>y" "$tmp/html-out/report.html"; then
  echo "FAIL html-name: the name reached report.html unescaped"; fail=1
fi
# A newline in a name would break the recording's metadata line: refused with its key.
sed 's|^name = .*|name = "two\\nlines"|' "$tmp/bom.toml" >"$tmp/nl.toml"
expect newline-name "nl.toml:[0-9]+: 'scenario.name': " -- "$sim" run "$tmp/nl.toml" --quiet --out "$tmp/nl-out"
# A route longer than max_duration_s is said to be cut short, in the output and summary.json.
sed 's|^\[scenario\]|[scenario]\nmax_duration_s = 20.0|' "$tmp/bom.toml" >"$tmp/cut.toml"
want_rc=0 expect route-cut "note: the route was not finished within max_duration_s = 20 s" -- \
  "$sim" run "$tmp/cut.toml" --quiet --out "$tmp/cut-out"
grep -q '"route_complete": false' "$tmp/cut-out/summary.json" || {
  echo "FAIL route-cut: summary.json does not say route_complete false"; fail=1; }
# The same board in a run: the controller's boot fails on it, the summary says so by name, and
# the run exits 1 (issue 28, item 12: it had simulated the boot fault and exited 0).
source "$src/tests/board_copy.sh"
board_copy "$src" host-sim "$tmp/badmap-board"
sed -i 's|tpdo2 = \["6064:00:32", "6077:00:16"\]|tpdo2 = ["6064:00:32", "2077:00:16"]|' \
  "$tmp/badmap-board/machines/scallion-transplanter.toml"
sed "s|^board = .*|board = \"$tmp/badmap-board/board.toml\"|; s|^\[scenario\]|[scenario]\nmax_duration_s = 15.0|" \
  "$tmp/bom.toml" >"$tmp/badmap.toml"
want_rc=1 expect unmapped-object "the machine never moved: final state fault, faults 0x40" -- \
  "$sim" run "$tmp/badmap.toml" --out "$tmp/badmap-out"
# Issue 28, item 15: a recording with none of the model's channels gave an empty replay.csv
# and exit 0; issue 29: a refused output folder was found only after all the work.
{ echo "t,nothing_known"; for i in $(seq 0 99); do echo "$i.5,1"; done; } >"$tmp/unknown.csv"
printf '[[channel]]\noutput = "omega"\nsubsystem = "disc drive"\nT_d = 0.19\nomega_max = 0.45\n' >"$tmp/model.toml"
expect replay-no-channel "unknown.csv: has none of the model's channels; nothing to replay" -- \
  "$sim" replay "$tmp/model.toml" "$tmp/unknown.csv" --out "$tmp/rp"
[ ! -e "$tmp/rp/replay.csv" ] || { echo "FAIL replay-no-channel: replay.csv written"; fail=1; }
# Issue 28, item 15: an effect on a channel planter-fit never puts it on, and a channel named
# twice, were replayed as if they meant something.
{ echo "t,omega_cmd,omega"; for i in $(seq 0 99); do echo "$i.5,0.3,0.3"; done; } >"$tmp/omega.csv"
{ cat "$tmp/model.toml"; printf '[[channel.effect]]\nname = "Coulomb friction"\ncoulomb = 1.0\n'; } >"$tmp/wrong-effect.toml"
expect replay-wrong-effect "wrong-effect.toml:7: 'name': 'Coulomb friction' is not an effect of channel 'omega'" -- \
  "$sim" replay "$tmp/wrong-effect.toml" "$tmp/omega.csv" --out "$tmp/rp2"
{ cat "$tmp/model.toml" "$tmp/model.toml"; } >"$tmp/twice.toml"
expect replay-channel-twice "twice.toml:7: 'channel\\[1\\]\\.output': 'omega' has a \[\[channel\]\] table already" -- \
  "$sim" replay "$tmp/twice.toml" "$tmp/omega.csv" --out "$tmp/rp3"
mkdir -p "$tmp/busy" && echo mine >"$tmp/busy/notes.txt"
want_rc=1 expect replay-busy-out "busy: holds files that are not the output of 'planter-sim replay'" -- \
  "$sim" replay "$tmp/model.toml" "$tmp/unknown.csv" --out "$tmp/busy"
exit $fail
