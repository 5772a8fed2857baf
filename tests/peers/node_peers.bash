# The test peers written by others, from the npm registry (sourced by the end-to-end scripts that
# need them, after lib/common.bash). Installed by the tests themselves into the build directory
# (beside the accelcal binary: <build>/test-peers/node), once, and reused by later runs; never
# committed, no lock file (it would name the registry's host). The versions are pinned here.
#
#   need_node_peers   sets ACCELCAL_NODE_MODULES to the installed node_modules, installing
#                     node-mavlink first when it is not there yet. Exits 77 (skipped, with the
#                     reason) when node or npm is not installed; fails when the install fails.
node_peer_packages=(node-mavlink@2.3.0 mavlink-mappings@1.0.21-20250824-1)

need_node_peers() {
  command -v node >/dev/null && command -v npm >/dev/null || {
    echo "skipped: node and npm are needed for the MAVLink test vehicle (node-mavlink)"; exit 77; }
  local dir
  dir="$(cd "$(dirname "$accelcal")" && pwd)/test-peers/node"
  mkdir -p "$dir"
  # Two tests may start at once: one installs, the other waits for it.
  (
    flock 9
    if [ ! -f "$dir/installed" ] || [ "$(cat "$dir/installed")" != "${node_peer_packages[*]}" ]; then
      rm -rf "$dir/node_modules"
      npm install --prefix "$dir" --no-save --no-package-lock --no-audit --no-fund --loglevel=error \
        "${node_peer_packages[@]}" >"$dir/install.log" 2>&1 \
        || { cat "$dir/install.log" >&2; echo "FAIL: npm could not install ${node_peer_packages[*]}" >&2; exit 1; }
      echo "${node_peer_packages[*]}" > "$dir/installed"
    fi
  ) 9>"$dir/.lock" || exit 1
  export ACCELCAL_NODE_MODULES="$dir/node_modules"
}
