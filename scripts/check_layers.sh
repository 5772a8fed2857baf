#!/usr/bin/env bash
# Checks the core's layering from the sources (ARCHITECTURE.md), as the build does for most of
# it: the build cannot include what a target does not link, but it cannot see the rest.
#   1. src/accelcal/<layer>/ includes only its own layer and the layers below it:
#        base -> calibration -> acquire -> analysis -> session -> report -> io -> app
#      (so the include graph between layers has no cycle and no upward edge);
#   2. a layer's detail/ headers are private: no other layer and nothing in ui/ includes them
#      (tests may look inside);
#   3. third-party headers stay in their layer: nlohmann-json and toml++ in io, SQLite in
#      session and bags (a ROS 2 bag is an SQLite file), the chunk codecs (zstd, lz4, bz2) in
#      bags, CLI11 and curses in ui/ only.
# bags (the bag readers, siblings of base's sample reader) ranks just above base: it includes
# base only, and acquire (the file: source replays a bag), io and the layers above may include it.
# Prints every violation as FILE:LINE: what; exit status 1 when there is one.
set -euo pipefail
cd "${1:-$(dirname "$0")/..}"

layers=(base bags calibration acquire analysis session report io app)
declare -A rank
for i in "${!layers[@]}"; do rank[${layers[$i]}]=$i; done

violations=0
report() { echo "$1"; violations=$((violations + 1)); }

# Every #include of a file, as "FILE:LINE:HEADER".
includes() {
  grep -rnoE '^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"][^">]+[">]' "$@" --include='*.h' \
      --include='*.cpp' | sed -E 's/#[[:space:]]*include[[:space:]]*[<"]([^">]+)[">]$/\1/; s/:[[:space:]]*/:/2'
}

for layer in "${layers[@]}"; do
  dir=src/accelcal/$layer
  [ -d "$dir" ] || { report "$dir: missing layer directory"; continue; }
  while IFS=: read -r file line header; do
    case "$header" in
      accelcal/*/*)
        target=${header#accelcal/}; target=${target%%/*}
        if [ -z "${rank[$target]+x}" ]; then
          report "$file:$line: includes $header, which is in no layer"
        elif [ "${rank[$target]}" -gt "${rank[$layer]}" ]; then
          report "$file:$line: layer $layer includes $header from the higher layer $target"
        elif [[ "$header" == */detail/* && "$target" != "$layer" ]]; then
          report "$file:$line: layer $layer includes $header, private to layer $target"
        fi ;;
      accelcal/*) report "$file:$line: includes $header, which is in no layer" ;;
      nlohmann/*|toml++/*)
        [ "$layer" = io ] || report "$file:$line: $header outside io (JSON and TOML live at the file edge)" ;;
      sqlite3.h)
        [ "$layer" = session ] || [ "$layer" = bags ] || report "$file:$line: sqlite3.h outside session and bags" ;;
      zstd.h|zstd_errors.h|lz4.h|lz4frame.h|lz4hc.h|bzlib.h)
        [ "$layer" = bags ] || report "$file:$line: $header outside bags (the chunk codecs are the bag readers')" ;;
      CLI/*|curses.h|ncurses.h|ncurses/*|term.h)
        report "$file:$line: $header in the core (terminal and command-line code lives in ui/)" ;;
    esac
  done < <(includes "$dir")
done

for stray in src/accelcal/*.h src/accelcal/*.cpp; do
  [ -e "$stray" ] && report "$stray: outside every layer directory"
done

while IFS=: read -r file line header; do
  case "$header" in
    accelcal/*/detail/*) report "$file:$line: ui includes $header, a private header of the core" ;;
    nlohmann/*|toml++/*|sqlite3.h|zstd.h|lz4*.h|bzlib.h) report "$file:$line: ui includes $header (the core's io, session and bags own it)" ;;
  esac
done < <(includes ui)

if [ "$violations" -gt 0 ]; then
  echo "check_layers: $violations violation(s)"
  exit 1
fi
echo "check_layers: ${#layers[@]} layers, no upward include, no foreign detail/, third-party headers in place"
