#!/usr/bin/env bash
# Builds the Debian package: accelcal_<version>_<arch>.deb in the current directory (or in
# $PACKAGE_DIR), with its Depends found by dpkg-shlibdeps. The version is the project's, with
# "+git<commits>.g<hash>" when the tree is past a release tag (cmake/git_description.cmake).
# Builds the program, its manual pages and completion into build/ (or $BUILD_DIR) first, as
# run.sh does; the package holds what that build made (stripped).
#   sudo apt install ./accelcal_*.deb     installs it; sudo apt remove accelcal removes it
set -euo pipefail
out_dir=$(realpath -m "${PACKAGE_DIR:-.}")
cd "$(dirname "$0")/.."
./scripts/setup.sh --package
BUILD_TARGETS="accelcal accelcal_docs" ./scripts/build.sh -DACCELCAL_UNITY=ON
build_dir=${BUILD_DIR:-build}
mkdir -p "$out_dir"
cpack --config "$build_dir/CPackConfig.cmake" -B "$out_dir/_cpack" >/dev/null
mv "$out_dir"/_cpack/accelcal_*.deb "$out_dir"/
rm -rf "$out_dir/_cpack"
ls "$out_dir"/accelcal_*.deb
