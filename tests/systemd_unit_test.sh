#!/usr/bin/env bash
# The planterd unit passes systemd-analyze verify (with ExecStart pointed at this build), and
# carries the settings the daemon relies on.
set -euo pipefail
unit=$1
planterd=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sed "s|/usr/bin/planterd|$planterd|" "$unit" > "$work/planterd.service"
systemd-analyze verify "$work/planterd.service"
for key in "Type=notify" "WatchdogSec=" "Restart=on-failure" "KillSignal=SIGTERM" "LimitRTPRIO=" \
           "LimitMEMLOCK=infinity"; do
  grep -q "^$key" "$unit" || { echo "planterd.service lacks $key" >&2; exit 1; }
done
echo "planterd.service verified"
