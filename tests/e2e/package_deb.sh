#!/usr/bin/env bash
# The Debian package and the install, from the finished build (nothing is rebuilt):
#  - cpack makes accelcal_<version>_<arch>.deb; its Depends name the package of every shared
#    library the program loads, each installed here in a version its clause allows;
#  - installed with dpkg into a scratch root (its own dpkg database, --root), never into this
#    machine's /usr: a developer's machine keeps no stray accelcal and a test killed midway
#    leaves nothing installed; the Depends, which that empty database cannot know, were checked
#    against this machine's above;
#  - from a directory outside the source tree, the installed program reports its version, lists
#    and uses the installed procedures (a title changed in the installed copy shows in the
#    session), runs a short unattended session to its end, and man finds its pages;
#  - dpkg removes it again, leaving no file;
#  - `cmake --install` to a prefix gives the same layout (the program finds its share/ there).
# Usage: package_deb.sh ACCELCAL SOURCE_DIR SHARED_DATA_DIR
set -euo pipefail
accelcal=$(realpath "$1")
build=$(dirname "$accelcal")
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
for tool in cpack dpkg dpkg-deb dpkg-shlibdeps man; do
  command -v "$tool" >/dev/null || { echo "SKIP: $tool is not installed (scripts/setup.sh)"; exit 77; }
done
as_root=()
if [ "$(id -u)" -ne 0 ]; then
  command -v fakeroot >/dev/null || { echo "SKIP: not root and no fakeroot"; exit 77; }
  as_root=(fakeroot)
fi
export HOME=$work/home XDG_DATA_HOME=$work/home/data MANPAGER=cat PAGER=cat LC_ALL=C
mkdir -p "$HOME"

# The package.
cpack --config "$build/CPackConfig.cmake" -B "$work/pkg" > "$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log" >&2; fail "cpack failed"; }
debs=("$work"/pkg/accelcal_*.deb)
[ ${#debs[@]} -eq 1 ] && [ -f "${debs[0]}" ] || fail "no single .deb: $(ls "$work/pkg")"
deb=${debs[0]}
arch=$(dpkg --print-architecture)
version=$(dpkg-deb -f "$deb" Version)
[ "$(basename "$deb")" = "accelcal_${version}_${arch}.deb" ] || fail "named $(basename "$deb")"
grep -q "ACCELCAL_PACKAGE_VERSION \"$version\"" "$build/generated/package_version.cmake" ||
  fail "version $version is not the build's ($(cat "$build/generated/package_version.cmake"))"
[[ $version =~ ^[0-9]+\.[0-9]+\.[0-9]+(\+git[0-9]+\.g[0-9a-f]+(\.dirty)?)?$ ]] || fail "version $version"
[ "$(dpkg-deb -f "$deb" Architecture)" = "$arch" ] || fail "architecture"

# Depends: the package of every shared library the program loads is named there.
depends=$(dpkg-deb -f "$deb" Depends)
[ -n "$depends" ] || fail "no Depends"
depends_names=$(sed 's/ ([^)]*)//g; s/, /\n/g; s/ | /\n/g' <<< "$depends")
for lib in $(ldd "$accelcal" | awk '$3 ~ /^\// {print $3}'); do
  owner=$(dpkg -S "$(realpath "$lib")" 2>/dev/null | head -1 | cut -d: -f1) ||
    owner=$(dpkg -S "$lib" 2>/dev/null | head -1 | cut -d: -f1) || true
  [ -n "$owner" ] || fail "no package owns $lib"
  grep -qxF "$owner" <<< "$depends_names" || fail "Depends [$depends] lacks $owner ($lib)"
done
# ... and each is installed here in a version the clause allows (what dpkg -i would check).
while IFS= read -r clause; do
  name=${clause%% *}
  have=$(dpkg-query -W -f='${Version}' "$name" 2>/dev/null) || fail "Depends names $name, not installed here"
  if [[ $clause =~ \(([<>=]+)\ ([^\)]+)\) ]]; then
    relation=${BASH_REMATCH[1]} wanted=${BASH_REMATCH[2]}
    case $relation in '>=') relation=ge ;; '<=') relation=le ;; '>>') relation=gt ;; '<<') relation=lt ;; '=') relation=eq ;; esac
    dpkg --compare-versions "$have" "$relation" "$wanted" || fail "Depends: $clause, but $name $have is installed"
  fi
done < <(sed 's/, /\n/g' <<< "$depends")

# Install into a scratch root with its own dpkg database.
root=$work/root
mkdir -p "$root/var/lib/dpkg/info" "$root/var/lib/dpkg/updates" "$root/var/lib/dpkg/triggers"
touch "$root/var/lib/dpkg/status" "$root/var/lib/dpkg/available"
dpkg_root() { "${as_root[@]}" dpkg --root="$root" --force-depends --force-not-root --force-unsafe-io "$@"; }
dpkg_root -i "$deb" > "$work/dpkg.log" 2>&1 || { cat "$work/dpkg.log" >&2; fail "dpkg -i failed"; }
dpkg_root -s accelcal | grep -q "^Status: install ok installed" || fail "not installed in the scratch root"
installed=$root/usr/bin/accelcal
[ -x "$installed" ] || fail "no $installed"
for f in share/accelcal/procedures/noise.toml share/accelcal/scenarios/bench_default.toml \
         share/man/man1/accelcal.1.gz share/man/man1/accelcal-wizard.1.gz \
         share/man/man5/accelcal-procedure.5.gz share/bash-completion/completions/accelcal; do
  [ -f "$root/usr/$f" ] || fail "the package lacks /usr/$f"
done

# Run from elsewhere: the version, the installed procedures, a session.
mkdir -p "$work/elsewhere" && cd "$work/elsewhere"
[ "$("$installed" --version)" = "$("$accelcal" --version)" ] || fail "version: $("$installed" --version)"
"$installed" --version | grep -Eq '^accelcal [0-9]+\.[0-9]+\.[0-9]+' || fail "--version: $("$installed" --version)"
[ "$("$installed" help-shipped procedures)" = "$(ls "$root/usr/share/accelcal/procedures")" ] ||
  fail "the installed program lists [$("$installed" help-shipped procedures | xargs)]"
sed -i 's/^title = .*/title = "Full calibration, installed copy"/' \
  "$root/usr/share/accelcal/procedures/full_calibration.toml"
set +e
yes '' | "$installed" wizard --source sim --speed 0 --plain --session "$work/elsewhere/s.db" \
  > "$work/session.txt" 2> "$work/session.err"
code=${PIPESTATUS[1]}
set -e
[ "$code" -eq 0 ] || fail "the installed wizard exited $code: $(cat "$work/session.err")"
head -1 "$work/session.txt" | grep -q "Full calibration, installed copy" ||
  fail "the session did not run the installed procedure: $(head -1 "$work/session.txt")"
grep -q "Calibration complete" "$work/session.txt" || fail "the session did not end: $(tail -5 "$work/session.txt")"
"$installed" simulate bench_default -o c.csv 2> /dev/null || fail "simulate by a shipped scenario's name"
[ -s c.csv ] || fail "simulate wrote nothing"

# man finds the installed pages.
[ "$(MANPATH="$root/usr/share/man" man -w accelcal-wizard)" = "$root/usr/share/man/man1/accelcal-wizard.1.gz" ] ||
  fail "man -w accelcal-wizard: $(MANPATH="$root/usr/share/man" man -w accelcal-wizard 2>&1)"
MANPATH="$root/usr/share/man" man accelcal-wizard 2>/dev/null | grep -q -- "--session" || fail "man accelcal-wizard"
MANPATH="$root/usr/share/man" man 5 accelcal-capture-set 2>/dev/null | grep -q "adc_range_counts" ||
  fail "man 5 accelcal-capture-set"

# Removed: no file of it is left.
cd "$work"
dpkg_root --purge accelcal > "$work/dpkg.log" 2>&1 || { cat "$work/dpkg.log" >&2; fail "dpkg --purge failed"; }
left=$(find "$root" -path "$root/var" -prune -o ! -type d -print)
[ -z "$left" ] || fail "left after removal: $left"

# cmake --install to a prefix: the same layout, found from there.
cmake --install "$build" --prefix "$work/prefix" > /dev/null
[ "$("$work/prefix/bin/accelcal" help-shipped scenarios)" = "$(ls "$source_dir/scenarios" | grep '\.toml$')" ] ||
  fail "cmake --install: the program does not find its scenarios"
[ -f "$work/prefix/share/man/man1/accelcal-fit.1.gz" ] || fail "cmake --install: no manual pages"
echo ok
