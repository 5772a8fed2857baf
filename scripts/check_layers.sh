#!/usr/bin/env bash
# Checks the core's layering from the sources (ARCHITECTURE.md), as the build does for most of
# it: the build cannot include what a target does not link, but it cannot see the rest.
#   1. The layer graph is the one CMakeLists.txt declares, one call a layer:
#        accelcal_layer(NAME USES <the layers it includes> [PUBLIC ...] [PRIVATE ...])
#      It must be a DAG (no layer reaches itself). src/accelcal/<layer>/ includes only its own
#      layer and the layers it USES, and each layer it USES it does include (the declared graph
#      is the include graph, no edge more, no edge less); every folder of src/accelcal is a layer;
#   2. a layer's detail/ headers are private: no other layer and nothing in ui/ includes them
#      (tests may look inside);
#   3. third-party headers stay in their layer: nlohmann-json and toml++ in io, SQLite in
#      session and bags (a ROS 2 bag is an SQLite file), the chunk codecs (zstd, lz4, bz2) in
#      bags, libpq in lab, CLI11 and curses in ui/ only;
#   4. no relative include ("../x.h", "detail/x.h" from beside it) in src/, ui/ or tests/unit/:
#      the core's headers are named from their layer (accelcal/<layer>/...), which the checks
#      above and the build's include directories see; a relative path escapes both.
# Prints every violation as FILE:LINE: what; exit status 1 when there is one.
set -euo pipefail
cd "${1:-$(dirname "$0")/..}"

violations=0
report() { echo "$1"; violations=$((violations + 1)); }

# The declared graph: layers in declaration order, and each one's USES.
layers=()
declare -A uses
while read -r name used; do
  layers+=("$name")
  uses[$name]=" $used "
done < <(sed 's/#.*//' CMakeLists.txt | tr '\n' ' ' | grep -oE 'accelcal_layer\([^)]*\)' |
         sed -E 's/^accelcal_layer\(//; s/\)$//' |
         awk '{ out = $1; on = 0
                for (i = 2; i <= NF; ++i) {
                  if ($i == "USES") { on = 1; continue }
                  if ($i == "PUBLIC" || $i == "PRIVATE") on = 0
                  else if (on) out = out " " $i
                }
                print out }')
[ "${#layers[@]}" -gt 0 ] || { echo "CMakeLists.txt: no accelcal_layer(...) line"; exit 1; }
is_layer() { [[ " ${layers[*]} " == *" $1 "* ]]; }

# What each layer reaches through USES, directly or not.
declare -A reach
for layer in "${layers[@]}"; do
  seen=" " todo=(${uses[$layer]})
  while [ "${#todo[@]}" -gt 0 ]; do
    next=${todo[0]}; todo=("${todo[@]:1}")
    [[ "$seen" == *" $next "* ]] && continue
    seen+="$next "
    is_layer "$next" && todo+=(${uses[$next]})
  done
  reach[$layer]=$seen
done
for layer in "${layers[@]}"; do
  for used in ${uses[$layer]}; do
    is_layer "$used" || report "CMakeLists.txt: layer $layer USES $used, which is no layer"
  done
  [[ "${reach[$layer]}" == *" $layer "* ]] &&
    report "CMakeLists.txt: layer $layer reaches itself through USES (the layer graph has a cycle)"
done

# Every #include of a file, as "FILE:LINE:HEADER" (quoted or bracketed: Q or B before HEADER).
includes() {
  grep -rnoE '^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"][^">]+[">]' "$@" --include='*.h' \
      --include='*.cpp' |
    sed -E 's/#[[:space:]]*include[[:space:]]*"([^"]+)"$/Q\1/; s/#[[:space:]]*include[[:space:]]*<([^>]+)>$/B\1/; s/:[[:space:]]*/:/2'
}

# Rule 4 for any file: a path with "..", or a quoted path that is not one of `allowed` (a
# regex of the roots a quoted include may start with).
relative() {  # FILE LINE HEADER(with Q/B mark) ALLOWED
  local file=$1 line=$2 header=${3:1} kind=${3:0:1}
  if [[ "/$header/" == */../* ]] || { [ "$kind" = Q ] && ! [[ "$header" =~ $4 ]]; }; then
    report "$file:$line: relative include \"$header\": name the header from its root (accelcal/<layer>/...), or the layer check cannot see it"
    return 0
  fi
  return 1
}

declare -A included  # "layer target" pairs seen
for layer in "${layers[@]}"; do
  dir=src/accelcal/$layer
  [ -d "$dir" ] || { report "$dir: missing layer directory"; continue; }
  while IFS=: read -r file line marked; do
    relative "$file" "$line" "$marked" '^accelcal/' && continue
    header=${marked:1}
    case "$header" in
      accelcal/*/*)
        target=${header#accelcal/}; target=${target%%/*}
        if ! is_layer "$target"; then
          report "$file:$line: includes $header, which is in no layer"
          continue
        fi
        [ "$target" != "$layer" ] && [ -z "${included["$layer $target"]+x}" ] && included["$layer $target"]=1
        if [ "$target" = "$layer" ]; then
          :
        elif [[ "${reach[$target]}" == *" $layer "* ]]; then
          report "$file:$line: layer $layer includes $header from the higher layer $target"
        elif [[ "${uses[$layer]}" != *" $target "* ]]; then
          # Once for each pair of layers: the first include shows the edge.
          [ "${included["$layer $target"]}" = 1 ] || continue
          included["$layer $target"]=2
          if [[ "${reach[$layer]}" == *" $target "* ]]; then
            report "$file:$line: layer $layer includes $header from layer $target, which it reaches only through another: add $target to its USES (CMakeLists.txt)"
          else
            report "$file:$line: layer $layer includes $header from layer $target, which it does not use (CMakeLists.txt: accelcal_layer($layer USES${uses[$layer]%" "}))"
          fi
        elif [[ "$header" == */detail/* ]]; then
          report "$file:$line: layer $layer includes $header, private to layer $target"
        fi ;;
      accelcal/*) report "$file:$line: includes $header, which is in no layer" ;;
      nlohmann/*|toml++/*)
        [ "$layer" = io ] || report "$file:$line: $header outside io (JSON and TOML live at the file edge)" ;;
      sqlite3.h)
        [ "$layer" = session ] || [ "$layer" = bags ] || report "$file:$line: sqlite3.h outside session and bags" ;;
      zstd.h|zstd_errors.h|lz4.h|lz4frame.h|lz4hc.h|bzlib.h)
        [ "$layer" = bags ] || report "$file:$line: $header outside bags (the chunk codecs are the bag readers')" ;;
      libpq-fe.h|libpq/*|postgresql/*|pqxx/*)
        [ "$layer" = lab ] || report "$file:$line: $header outside lab (PostgreSQL lives in the lab store)" ;;
      CLI/*|curses.h|ncurses.h|ncurses/*|term.h)
        report "$file:$line: $header in the core (terminal and command-line code lives in ui/)" ;;
    esac
  done < <(includes "$dir")
done

# No edge more: each layer a layer USES is one it includes.
for layer in "${layers[@]}"; do
  for used in ${uses[$layer]}; do
    is_layer "$used" && [ -z "${included["$layer $used"]+x}" ] &&
      report "CMakeLists.txt: layer $layer USES $used but includes none of its headers (drop it from USES)"
  done
done

for stray in src/accelcal/*; do
  name=${stray#src/accelcal/}
  if [ -d "$stray" ]; then
    is_layer "$name" || report "$stray: a folder that is no layer (declare it in CMakeLists.txt: accelcal_layer($name USES ...))"
  elif [ -e "$stray" ]; then
    report "$stray: outside every layer directory"
  fi
done

while IFS=: read -r file line marked; do
  relative "$file" "$line" "$marked" '^(accelcal|cli|tui)/|^[A-Za-z0-9_]+\.h$' && continue
  header=${marked:1}
  case "$header" in
    accelcal/*/detail/*) report "$file:$line: ui includes $header, a private header of the core" ;;
    nlohmann/*|toml++/*|sqlite3.h|zstd.h|lz4*.h|bzlib.h) report "$file:$line: ui includes $header (the core's io, session and bags own it)" ;;
    libpq-fe.h|libpq/*|postgresql/*|pqxx/*) report "$file:$line: ui includes $header (the core's lab owns it)" ;;
  esac
done < <(includes ui)

# The unit tests: headers from their layer or a helper by name (the groups' include
# directories, tests/CMakeLists.txt), never by a path around them.
if [ -d tests/unit ]; then
  while IFS=: read -r file line marked; do
    relative "$file" "$line" "$marked" '^(accelcal|cli|tui)/|^[A-Za-z0-9_]+\.h$' || true
  done < <(includes tests/unit)
fi

if [ "$violations" -gt 0 ]; then
  echo "check_layers: $violations violation(s)"
  exit 1
fi
echo "check_layers: ${#layers[@]} layers as CMakeLists.txt declares them (a DAG), each including exactly the layers it uses, no foreign detail/, no relative include, third-party headers in place"
