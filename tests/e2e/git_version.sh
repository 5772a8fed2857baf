#!/usr/bin/env bash
# The version the build takes from git (cmake/git_description.cmake): outside a git checkout (a
# release tarball) the project's version alone; in one, `git describe` for --version and
# <version>+git<commits>.g<hash> for the package, the bare version on the release tag; each file
# rewritten only when its content changes (an unchanged HEAD rebuilds nothing).
# Usage: git_version.sh ACCELCAL SOURCE_DIR SHARED_DATA_DIR
set -euo pipefail
accelcal=$(realpath "$1")
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
command -v git >/dev/null || { echo "SKIP: git is not installed"; exit 77; }
script=$source_dir/cmake/git_description.cmake
describe() {  # describe TREE: runs the script on TREE into $work/out
  cmake -DSOURCE_DIR="$1" -DOUT_DIR="$work/out" -DPROJECT_VERSION=1.2.3 -DGIT="$(command -v git)" -P "$script"
}
description() { sed -n 's/.*kGitDescription = "\(.*\)";/\1/p' "$work/out/git_description.cpp"; }
package_version() { sed -n 's/set(ACCELCAL_PACKAGE_VERSION "\(.*\)")/\1/p' "$work/out/package_version.cmake"; }

# A tarball: no .git.
mkdir -p "$work/tarball" "$work/out"
describe "$work/tarball"
[ "$(description)" = "" ] || fail "tarball: description '$(description)'"
[ "$(package_version)" = "1.2.3" ] || fail "tarball: package version '$(package_version)'"

# A checkout: two commits, the first tagged v1.2.3.
repo=$work/repo
git init -q "$repo"
git -C "$repo" -c user.name=t -c user.email=t@invalid commit -q --allow-empty -m one
git -C "$repo" tag v1.2.3
describe "$repo"
[ "$(description)" = "v1.2.3" ] || fail "on the tag: description '$(description)'"
[ "$(package_version)" = "1.2.3" ] || fail "on the tag: package version '$(package_version)'"
git -C "$repo" -c user.name=t -c user.email=t@invalid commit -q --allow-empty -m two
hash=$(git -C "$repo" rev-parse --short HEAD)
describe "$repo"
[ "$(description)" = "v1.2.3-1-g$hash" ] || fail "past the tag: description '$(description)'"
[ "$(package_version)" = "1.2.3+git2.g$hash" ] || fail "past the tag: package version '$(package_version)'"
dpkg --compare-versions "$(package_version)" gt 1.2.3 || fail "$(package_version) does not sort after 1.2.3"

# Unchanged: the files are not written again (their time stamps stay).
touch -d '2001-01-01' "$work/out/git_description.cpp" "$work/out/package_version.cmake"
describe "$repo"
[ "$(stat -c %Y "$work/out/git_description.cpp")" = "$(date -d 2001-01-01 +%s)" ] || fail "rewritten unchanged"

# A modified tree is dirty.
echo x > "$repo/f" && git -C "$repo" add f
describe "$repo"
[ "$(description)" = "v1.2.3-1-g$hash-dirty" ] || fail "dirty: description '$(description)'"
[ "$(package_version)" = "1.2.3+git2.g$hash.dirty" ] || fail "dirty: package version '$(package_version)'"

# The program built here says its own.
"$accelcal" --version | grep -Eq '^accelcal [0-9]+\.[0-9]+\.[0-9]+( \(git [0-9a-zA-Z._+-]+\))?$' ||
  fail "--version: $("$accelcal" --version)"
echo ok
