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
copy_tree() {  # what the check reads: the layer graph, the sources, the unit tests
  rm -rf "$work/tree" && mkdir -p "$work/tree/tests" &&
    cp -r "$src/CMakeLists.txt" "$src/src" "$src/ui" "$work/tree/" && cp -r "$src/tests/unit" "$work/tree/tests/"
}
refused() {  # WHAT EXPECTED: the check must refuse the copy, saying EXPECTED
  if got=$(bash "$src/scripts/check_layers.sh" "$work/tree"); then
    fail "not refused: $1"
  fi
  grep -q -- "$2" <<<"$got" || fail "$1: expected '$2' in: $got"
}
plant() {  # FILE LINE EXPECTED: a copy of the tree with LINE added to FILE must be refused
  copy_tree
  mkdir -p "$(dirname "$work/tree/$1")"
  printf '%s\n' "$2" >> "$work/tree/$1"
  refused "'$2' in $1" "$3"
}
graph() {  # SED EXPECTED: a copy whose CMakeLists.txt is edited by SED must be refused
  copy_tree
  sed -i -E "$1" "$work/tree/CMakeLists.txt"
  refused "CMakeLists.txt edited by '$1'" "$2"
}
plant src/accelcal/base/capture.cpp '#include "accelcal/app/wizard/wizard_engine.h"' \
  'base/capture.cpp:.*layer base includes accelcal/app/wizard/wizard_engine.h from the higher layer app'
plant src/accelcal/calibration/apply.cpp '#include "accelcal/io/calibration_file.h"' 'from the higher layer io'
plant src/accelcal/app/calibration_pipeline.cpp '#include "accelcal/session/detail/sqlite_db.h"' 'private to layer session'
plant ui/cli/fit.cpp '#include "accelcal/io/detail/json_values.h"' 'a private header of the core'
plant src/accelcal/report/report_model.cpp '#include <nlohmann/json.hpp>' 'outside io'
plant src/accelcal/analysis/welch_psd.cpp '#include <ncurses.h>' 'in the core'
plant src/accelcal/io/recording_stream.cpp '#include <zstd.h>' 'outside bags'
# bags sits beside calibration (base only below it); acquire and above use it.
plant src/accelcal/bags/bag_file.h '#include "accelcal/calibration/apply.h"' \
  'layer bags includes accelcal/calibration/apply.h from layer calibration, which it does not use'
plant src/accelcal/bags/bag_file.h '#include "accelcal/acquire/source/sample_source.h"' \
  'layer bags includes accelcal/acquire/source/sample_source.h from the higher layer acquire'
plant src/accelcal/analysis/welch_psd.cpp '#include "accelcal/bags/bag_open.h"' \
  'layer analysis includes accelcal/bags/bag_open.h from layer bags, which it does not use'
plant src/accelcal/session/procedure.cpp '#include "accelcal/nowhere.h"' 'in no layer'
plant src/accelcal/app/device_history.cpp '#include <libpq-fe.h>' 'outside lab'
# lab sits beside io (base and report below it); app uses it.
plant src/accelcal/io/text_file.cpp '#include "accelcal/lab/lab_store.h"' \
  'layer io includes accelcal/lab/lab_store.h from layer lab, which it does not use'
plant src/accelcal/report/report_text.cpp '#include "accelcal/lab/lab_store.h"' 'from the higher layer lab'
# The graph is a DAG, not a chain: analysis and session do not use acquire.
plant src/accelcal/analysis/welch_psd.cpp '#include "accelcal/acquire/window_sums.h"' \
  'layer analysis includes accelcal/acquire/window_sums.h from layer acquire, which it does not use'
plant src/accelcal/session/procedure.cpp '#include "accelcal/analysis/welch_psd.h"' 'which it does not use'
# A path around the layer check, from a layer, ui/ and a unit test.
plant src/accelcal/base/capture.cpp '#include "../app/wizard/wizard_engine.h"' \
  'base/capture.cpp:.*relative include "../app/wizard/wizard_engine.h"'
plant src/accelcal/report/report_text.cpp '#include "detail/sqlite_db.h"' 'relative include'
plant src/accelcal/io/allan_file.cpp '#include "accelcal/io/../app/device_history.h"' 'relative include'
plant ui/cli/fit.cpp '#include "../../src/accelcal/io/detail/json_values.h"' 'relative include'
plant tests/unit/base/gravity_test.cpp '#include "../app/wizard_test_support.h"' 'relative include'
# A folder that is no declared layer.
plant src/accelcal/fixtures/fixture.h '#pragma once' 'src/accelcal/fixtures: a folder that is no layer'
# The declared graph itself: an edge the includes do not have, one they have and it lacks, a cycle.
graph 's/^accelcal_layer\(analysis USES base calibration\)/accelcal_layer(analysis USES base calibration acquire)/' \
  'layer analysis USES acquire but includes none of its headers'
graph 's/^accelcal_layer\(acquire USES base calibration bags\)/accelcal_layer(acquire USES calibration bags)/' \
  'from layer base, which it reaches only through another: add base to its USES'
graph 's/^accelcal_layer\(base PUBLIC/accelcal_layer(base USES app PUBLIC/' 'layer base reaches itself'
echo "layers_check: every planted violation refused"
