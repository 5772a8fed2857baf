#!/usr/bin/env bash
# The layering check (scripts/check_layers.sh): it passes on the tree, and it fails on a copy of
# the tree with each kind of violation planted, naming the file.
# Usage: bash layers_check.sh SOURCE_DIR
set -u
src=$1
fail() { echo "FAIL: $*"; exit 1; }

out=$(bash "$src/scripts/check_layers.sh" "$src") || fail "the tree has layering violations: $out"
echo "$out"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
plant() {  # FILE LINE EXPECTED: a copy of src/ and ui/ with LINE added to FILE must be refused
  rm -rf "$work/tree" && mkdir -p "$work/tree" && cp -r "$src/src" "$src/ui" "$work/tree/"
  printf '%s\n' "$2" >> "$work/tree/$1"
  if got=$(bash "$src/scripts/check_layers.sh" "$work/tree"); then
    fail "not refused: '$2' in $1"
  fi
  grep -q -- "$3" <<<"$got" || fail "'$2' in $1: expected '$3' in: $got"
}
plant src/accelcal/base/capture.cpp '#include "accelcal/app/wizard/wizard_engine.h"' \
  'base/capture.cpp:.*layer base includes accelcal/app/wizard/wizard_engine.h from the higher layer app'
plant src/accelcal/calibration/apply.cpp '#include "accelcal/io/calibration_file.h"' 'from the higher layer io'
plant src/accelcal/app/calibration_pipeline.cpp '#include "accelcal/session/detail/sqlite_db.h"' 'private to layer session'
plant ui/cli/fit.cpp '#include "accelcal/io/detail/json_values.h"' 'a private header of the core'
plant src/accelcal/report/report_model.cpp '#include <nlohmann/json.hpp>' 'outside io'
plant src/accelcal/analysis/welch_psd.cpp '#include <ncurses.h>' 'in the core'
plant src/accelcal/io/recording_stream.cpp '#include <zstd.h>' 'outside bags'
plant src/accelcal/bags/bag_file.h '#include "accelcal/calibration/apply.h"' 'from the higher layer calibration'
plant src/accelcal/session/procedure.cpp '#include "accelcal/nowhere.h"' 'in no layer'
echo "layers_check: every planted violation refused"
