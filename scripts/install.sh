#!/usr/bin/env bash
# Builds accelcal (as run.sh does) and installs it under $PREFIX (default /usr/local): the
# program in bin/, its procedures and scenarios in share/accelcal/, the manual pages
# (man accelcal, man accelcal-wizard, man 5 accelcal-procedure, ...) and the bash completion.
# $DESTDIR stages the install elsewhere (as packagers do). For a Debian system,
# scripts/package.sh makes a .deb instead, which apt can remove again.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh --no-test
BUILD_TARGETS="accelcal accelcal_docs" ./scripts/build.sh -DACCELCAL_UNITY=ON
cmake --install "${BUILD_DIR:-build}" --prefix "${PREFIX:-/usr/local}" --strip
