#!/usr/bin/env bash
# The field run's recording.csv and seedlings.csv are byte for byte the ones stored in
# tests/data/field_run_checksums.txt (with the reason of their last change). Exit 1 otherwise.
set -u
sim=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$sim" run "$src/scenarios/zhangqiu-field.toml" --out "$tmp/run" --quiet >"$tmp/log" 2>&1 ||
  { cat "$tmp/log"; echo "FAIL planter-sim run exited"; exit 1; }
grep -v '^#' "$src/tests/data/field_run_checksums.txt" >"$tmp/expected"
if ! (cd "$tmp/run" && sha256sum --quiet -c "$tmp/expected"); then
  echo "FAIL the field run's outputs changed; if the model changed on purpose, update"
  echo "     tests/data/field_run_checksums.txt with the reason. Now:"
  (cd "$tmp/run" && sha256sum recording.csv seedlings.csv)
  exit 1
fi
echo "field run unchanged: recording.csv and seedlings.csv match their stored checksums"
