#!/usr/bin/env bash
# The firmware sees only the C++ standard library, its own headers and the HAL interfaces:
# no OS, socket, GPIO or simulator header may appear in firmware/.
set -u
root=${1:-$(dirname "$0")/..}
bad=$(grep -rnE '^\s*#\s*include\s*[<"]' "$root/firmware" |
  grep -vE '#\s*include\s*"(firmware/|planter/hal/)' |
  grep -vE '#\s*include\s*<(algorithm|array|cmath|cstddef|cstdint|cstdio|limits|span|string|string_view|vector|utility|type_traits)>' || true)
if [ -n "$bad" ]; then
  echo "layering: firmware/ includes a header outside the standard library and the HAL interfaces:"
  echo "$bad"
  exit 1
fi
bad=$(grep -rnE '#\s*include\s*"(sim|hal/sim|hal/linux|config)/' "$root/firmware" "$root/hal/include" || true)
if [ -n "$bad" ]; then
  echo "layering: a lower layer includes a higher one:"; echo "$bad"; exit 1
fi
echo "layering ok: firmware/ uses only the standard library and hal/include"
