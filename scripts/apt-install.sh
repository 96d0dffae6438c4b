#!/usr/bin/env bash
# Installs the Debian packages named (pkg or pkg:arch) that are not installed yet; idempotent.
# The one place the project's scripts install from apt. A mirror can serve one stale index
# (seen: bookworm-security for armhf) and make `apt-get update` fail while everything needed
# is still there: the update's errors are shown, and the install decides.
# Usage: scripts/apt-install.sh TAG PACKAGE...
set -euo pipefail
tag=$1
shift
missing=()
for p in "$@"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
sudo_cmd=""
[ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
echo "$tag: installing ${missing[*]}"
$sudo_cmd apt-get update -qq || echo "$tag: apt-get update reported errors (above); installing anyway"
DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends \
  "${missing[@]}" >/dev/null
