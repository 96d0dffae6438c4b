#!/usr/bin/env bash
# Fails when any C++ file differs from clang-format's output.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
files=$(git ls-files '*.cpp' '*.h')
bad=0
for f in $files; do
  if ! clang-format --style=file "$f" | cmp -s - "$f"; then echo "not formatted: $f"; bad=1; fi
done
[ $bad -eq 0 ] && echo "clang-format ok ($(echo "$files" | wc -w) files)"
exit $bad
