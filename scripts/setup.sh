#!/usr/bin/env bash
# Installs the Debian packages accelcal needs, only those missing. Debian/Ubuntu, as root or
# with sudo. Safe to run again.
#   setup.sh            what building, running, packaging and testing need
#   setup.sh --no-test  only what building and running need
#   setup.sh --package  what building, running and packaging (scripts/package.sh) need
set -euo pipefail

# lowdown writes the file formats' manual pages from their Markdown (cmake/man_pages.cmake).
packages=(
  g++ cmake make pkg-config tmux jq lowdown
  libeigen3-dev libnlopt-cxx-dev libncurses-dev libsqlite3-dev libtomlplusplus-dev
  nlohmann-json3-dev libcli11-dev libfmt-dev libgtest-dev libbenchmark-dev
  libzstd-dev liblz4-dev libbz2-dev libpq-dev
)
# The .deb: CPack asks dpkg-shlibdeps (dpkg-dev), which asks file(1), for its Depends.
package_packages=(dpkg-dev file)
# Only the tests need these: headless Chromium renders the HTML report and prints it to PDF,
# poppler-utils reads the PDF's pages back (tests/e2e/report_html.sh); man-db's man reads the
# manual pages (tests/e2e/man_pages.sh, package_deb.sh); libiio's tools read the fake IIO tree
# beside accelcal (tests/e2e/iio_devices.sh). Node.js and its npm run the peers written elsewhere
# that the tests install into the build directory when they first need them: the bag writers and
# readers (tests/e2e/bags_*.sh) and the MAVLink test vehicle on node-mavlink (tests/peers/). The
# PostgreSQL server runs the lab store's tests (tests/lab/pg_server.sh starts a private one, as
# the user postgres the package creates, when the tests run as root).
test_packages=(chromium poppler-utils man-db libiio-utils nodejs postgresql)
case "${1:-}" in
  --no-test) ;;
  --package) packages+=("${package_packages[@]}") ;;
  *) packages+=("${package_packages[@]}" "${test_packages[@]}") ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages are installed"
  exit 0
fi

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "setup: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}"
