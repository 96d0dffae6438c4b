#!/usr/bin/env bash
# GNSS end to end on this host, with Debian's gpsd: the simulator's run writes its receiver's
# NMEA log; planter-can checks it clean; gpsfake feeds it to a real gpsd and the reader takes
# its fixes; bad logs (a checksum, a frozen time, 1e6 knots) are named by line and refused;
# gpsd absent is said, not waited on; and in the simulator a fix lost mid-row raises alarm bit
# 10 within a second, then clears when the fix is back.
# Usage: gnss_test.sh PLANTER_SIM PLANTER_CAN SOURCE_DIR
set -u
sim=$1 can=$2 src=$3
tmp=$(mktemp -d)
pids=()
trap 'for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done; rm -rf "$tmp"' EXIT
fail() { echo "FAIL $*"; exit 1; }
command -v gpsfake >/dev/null || fail "gpsfake is not installed (Debian gpsd-clients; scripts/setup.sh installs it)"

# A short row with the receiver fitted, and the fix lost for 3 s from 1.5 m.
sed -e "s#\"\.\./#\"$src/#g" -e 's/^distance_m = .*/distance_m = 3.0/' -e '/^stops = /d' \
  "$src/scenarios/zhangqiu-field.toml" >"$tmp/row.toml"
printf '\n[controller]\ngnss = true\n\n[gnss]\ndropout_at_m = 1.5\ndropout_s = 3.0\n' >>"$tmp/row.toml"
"$sim" run "$tmp/row.toml" --out "$tmp/run" --quiet >"$tmp/run.log" 2>&1 || { cat "$tmp/run.log"; fail "planter-sim run"; }
[ -s "$tmp/run/gnss.nmea" ] || fail "no gnss.nmea beside the run"

# The fix lost: alarm bit 10 within 1 s of the dropout, cleared after it.
python3 - "$tmp/run/recording.csv" <<'PY' || fail "the GNSS alarm's timing"
import csv, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith('#')))
lost = next(float(r['t']) for r in rows if float(r['true_x_m']) >= 1.5)
up = [float(r['t']) for r in rows if int(r['warnings']) & 1024 and float(r['t']) >= lost]
assert up, "alarm bit 10 never rose after the fix was lost"
late = up[0] - lost
print(f"fix lost at {lost:.2f} s, alarm at {up[0]:.2f} s ({late:.2f} s after)")
assert late <= 1.0, f"the alarm came {late:.2f} s after the fix was lost (goal 1 s)"
after = [r for r in rows if float(r['t']) > lost + 3.0 + 0.7 + 2.0 + 0.5]
assert after and all(int(r['warnings']) & 1024 == 0 for r in after), "the alarm did not clear when the fix came back"
before = [r for r in rows if 10.0 < float(r['t']) < lost and r['state'] == 'running']
assert before and all(int(r['warnings']) & 1024 == 0 for r in before), "the alarm rose with the fix good"
PY

# The log is clean, and other tools read it: gpsd, through gpsfake.
"$can" gnss --log "$tmp/run/gnss.nmea" >"$tmp/check.log" || { cat "$tmp/check.log"; fail "the simulator's own log is not clean"; }
port=$((29000 + RANDOM % 900))
head -600 "$tmp/run/gnss.nmea" >"$tmp/head.nmea"
gpsfake -q -P "$port" -c 0.05 -1 "$tmp/head.nmea" >"$tmp/gpsfake.log" 2>&1 &
pids+=($!)
# gpsfake starts gpsd in a second or more, more beside other tests (a CI run under the
# sanitizers found none listening 1 s on): waited for, up to 30 s, by connecting.
for _ in $(seq 300); do
  (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null && break
  sleep 0.1
done
timeout 30 "$can" gnss --port "$port" --duration 4 >"$tmp/watch.log" 2>&1 || { cat "$tmp/watch.log" "$tmp/gpsfake.log"; fail "planter-can gnss through gpsfake"; }
grep -q "connected, .* fixes, [1-9][0-9]* usable" "$tmp/watch.log" || { cat "$tmp/watch.log"; fail "no usable fix through gpsd"; }
tail -1 "$tmp/watch.log"

# Bad logs: each named by its line, exit 1.
good=$(sed -n 21p "$tmp/run/gnss.nmea" | tr -d '\r')
body=${good#\$}; body=${body%\**}
bad_sum="\$${body}*00"
frozen=$(sed -n 19p "$tmp/run/gnss.nmea" | tr -d '\r')
fast_body=$(echo "$body" | awk -F, 'BEGIN{OFS=","} {$8="1944000.0"; print}')
fast_sum=$(python3 -c "import sys,functools; b=sys.argv[1]; print('%02X' % functools.reduce(lambda a,c: a^ord(c), b, 0))" "$fast_body")
printf '%s\r\n' "$(sed -n 1p "$tmp/run/gnss.nmea" | tr -d '\r')" "$bad_sum" "$frozen" "$frozen" "\$${fast_body}*${fast_sum}" >"$tmp/bad.nmea"
if "$can" gnss --log "$tmp/bad.nmea" >"$tmp/bad.log" 2>&1; then cat "$tmp/bad.log"; fail "a bad log passed"; fi
grep -q "line 2: checksum 00" "$tmp/bad.log" || { cat "$tmp/bad.log"; fail "the bad checksum not named"; }
grep -q "line 4: RMC time stands still" "$tmp/bad.log" || { cat "$tmp/bad.log"; fail "the frozen time not named"; }
grep -q "line 5: speed 1e+06 m/s" "$tmp/bad.log" || { cat "$tmp/bad.log"; fail "the speed of 1e6 not named"; }

# gpsd absent: said within the watch, exit 1, no hang.
free_port=$((port + 1))
if timeout 10 "$can" gnss --port "$free_port" --duration 1 >"$tmp/absent.log" 2>&1; then cat "$tmp/absent.log"; fail "no gpsd, exit 0"; fi
grep -q "never connected" "$tmp/absent.log" || { cat "$tmp/absent.log"; fail "gpsd absent not said"; }
echo "gnss: the run's NMEA log clean, read through gpsd; bad logs named by line; gpsd absent said"
