#!/usr/bin/env bash
# Checks a planter .deb: its control fields (package, architecture, dependencies) and files
# (dpkg-deb -I, -c), the binaries' machine, and for the build machine's own architecture a
# real install: the unit verifies under systemd-analyze, planterd and planter-can run, the
# admin's files are conffiles, then remove and purge leave nothing behind.
# Usage: scripts/package-test.sh PACKAGE.deb ARCH
set -euo pipefail
deb=$1
arch=$2
fail() { echo "package: FAIL $*" >&2; exit 1; }
info=$(dpkg-deb -I "$deb")
files=$(dpkg-deb -c "$deb")
field() { dpkg-deb -f "$deb" "$1"; }
[ "$(field Package)" = planter ] || fail "Package is $(field Package)"
[ "$(field Architecture)" = "$arch" ] || fail "Architecture is $(field Architecture), want $arch"
for dep in libgpiod2 libsocketcan2 libtomlplusplus3 libstdc++6 libc6; do
  grep -q "$dep" <<<"$(field Depends)" || fail "Depends lacks $dep: $(field Depends)"
done
for f in ./usr/bin/planterd ./usr/bin/planter-can ./lib/systemd/system/planterd.service \
         ./etc/planter/board.toml ./etc/planter/calibration.toml ./etc/default/planterd \
         ./etc/planter/machines/scallion-transplanter.toml \
         ./etc/planter/boards/rpi4-canhat/board.toml ./etc/planter/boards/rpi4-canhat/calibration.toml \
         ./etc/planter/boards/bbb-dcan/board.toml ./etc/planter/boards/host-sim/board.toml \
         ./usr/share/doc/planter/copyright ./usr/share/man/man1/planterd.1.gz \
         ./usr/share/man/man1/planter-can.1.gz; do
  grep -q " $f\$" <<<"$files" || fail "$deb lacks $f"
done
grep -q "conffiles" <<<"$info" || fail "no conffiles"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
dpkg-deb -x "$deb" "$work/root"
machine=$(readelf -h "$work/root/usr/bin/planterd" | sed -n 's/ *Machine: *//p')
case $arch in
  arm64) want="AArch64" ;;
  armhf) want="ARM" ;;
  amd64) want="Advanced Micro Devices X86-64" ;;
esac
[ "$machine" = "$want" ] || fail "planterd is built for '$machine', not $want"
# The man pages are the programs' own --help (a page made of a loader's error is no page).
zgrep -q -- 'board' "$work/root/usr/share/man/man1/planterd.1.gz" ||
  fail "planterd's man page does not hold its options: $(zcat "$work/root/usr/share/man/man1/planterd.1.gz" | sed -n 8p)"
zgrep -q -- 'iface' "$work/root/usr/share/man/man1/planter-can.1.gz" ||
  fail "planter-can's man page does not hold its options"
echo "package: $(basename "$deb"): $(field Version) $arch, $(wc -l <<<"$files") entries, planterd for $machine"
echo "package: Depends: $(field Depends)"

[ "$arch" = "$(dpkg --print-architecture)" ] || exit 0
# The build machine's own package: install it for real, use it, remove it.
sudo_cmd=""
[ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
if dpkg-query -W -f='${Status}' planter 2>/dev/null | grep -q "install ok installed"; then
  fail "a planter package is already installed here; not touching it"
fi
$sudo_cmd dpkg -i "$deb" >"$work/install.out"
trap '$sudo_cmd dpkg -P planter >/dev/null 2>&1 || true; rm -rf "$work"' EXIT
/usr/bin/planterd --help >/dev/null || fail "installed planterd does not run"
# The installed board finds its machine (/etc/planter/machines) and its calibration.
/usr/bin/planter-can --iface sim --board /etc/planter/board.toml scan | tail -1
/usr/bin/planter-can --iface sim --board /etc/planter/boards/rpi4-canhat/board.toml scan >/dev/null ||
  fail "the installed rpi4-canhat board does not load"
systemd-analyze verify /lib/systemd/system/planterd.service || fail "systemd-analyze verify"
# The console's pairing secret: made at installation, root's only, said once for the label.
secret=/var/lib/planterd/pairing-secret
[ "$(stat -c %a "$secret" 2>/dev/null)" = 600 ] || fail "$secret missing or not mode 600"
grep -Eq '^[2-9a-hjkmnp-z]{5}(-[2-9a-hjkmnp-z]{5}){3}$' "$secret" || fail "$secret: not a secret: $(cat "$secret")"
grep -q "pairing secret is $(cat "$secret")" "$work/install.out" || fail "the installation did not show the secret"
conf=$(dpkg-query -W -f='${Conffiles}' planter)
for f in /etc/planter/board.toml /etc/planter/calibration.toml \
         /etc/planter/machines/scallion-transplanter.toml /etc/default/planterd; do
  grep -q "$f" <<<"$conf" || fail "conffile $f not registered: $conf"
done
$sudo_cmd dpkg -r planter >/dev/null
[ ! -e /usr/bin/planterd ] && [ ! -e /lib/systemd/system/planterd.service ] || fail "remove left binaries"
[ -e /etc/planter/board.toml ] || fail "remove dropped the admin's board file (it should stay until purge)"
$sudo_cmd dpkg -P planter >/dev/null
[ ! -e /etc/planter ] && [ ! -e /etc/default/planterd ] || fail "purge left /etc files"
echo "package: installed, verified (systemd-analyze, the console's pairing secret made), removed and purged cleanly"
