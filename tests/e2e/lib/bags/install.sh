#!/usr/bin/env bash
# Installs the bag peers of package.json (writers and readers written elsewhere: @mcap/core, the
# foxglove ROS serializers and the ROS 1 bag reader, sql.js's SQLite, the npm compressors) into
# DIR/node_modules with the machine's npm, once: a second call with the same package.json finds
# them there. Never into the source tree.
# Usage: install.sh DIR. Exit 0 when they are there; 77 (with the reason on stderr) when npm or
# node is missing or the registry cannot be reached.
set -uo pipefail
dir=$1
here=$(cd "$(dirname "$0")" && pwd)
command -v node >/dev/null && command -v npm >/dev/null || { echo "skip: node and npm are not installed (scripts/setup.sh installs nodejs)" >&2; exit 77; }
mkdir -p "$dir"
exec 9>"$dir/.install.lock"
flock 9
if [ -d "$dir/node_modules" ] && cmp -s "$here/package.json" "$dir/package.json"; then exit 0; fi
cp "$here/package.json" "$dir/package.json"
rm -rf "$dir/node_modules" "$dir/package-lock.json"
if ! (cd "$dir" && timeout 600 npm install --no-audit --no-fund --loglevel=error >"$dir/install.log" 2>&1); then
  rm -rf "$dir/node_modules" "$dir/package.json"
  echo "skip: npm could not install the bag peers (the registry unreachable?):" >&2
  tail -5 "$dir/install.log" >&2
  exit 77
fi
