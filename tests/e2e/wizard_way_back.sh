#!/usr/bin/env bash
# Issue 15, the way back and the bench, in line mode on the virtual bench (the real binary):
#  1. redo: b on the step after an accepted capture asks to take it again; n keeps it; b and
#     Enter take it again; the old capture stays in the session, superseded, and out of the
#     export and the report;
#  2. the resume summary lists the steps in the procedure's order by title;
#  3. the diagnosis on effects_demo's bench (radius 3 mm long, a quadratic response) in plain
#     words with the recommended choice, the statistics on d;
#  4. the same bench with the plan's captures (issue 32): the same two effects adopted;
#  5. a fit refused ends the session saved, its problem said, not a loop of Enter (this script
#     timed out at 300 s answering Enter at a refused fit); a rerun resumes at the fit.
# Usage: bash wizard_way_back.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
. "$source_dir/tests/e2e/lib/clumsy.bash"
short_procedure

# 1. Welcome 5, noise floor 1, leveling 3, then +z up captured; at -z up: b, n, b, Enter, Enter.
wizard bench_default.toml "$work/redo.db" "$(printf '\\n%.0s' $(seq 10))b\\nn\\nb\\n\\n\\n"
said "Take '+z up' again? Its capture 1 was accepted."
said "Enter takes it again, b looks further back, n keeps it."
said "Taking '+z up' again: capture 1 stays until this one is accepted"
said "'+z up' taken again: capture 2 replaces capture 1 (kept in the session, marked superseded, out of the fit and the report)."
said "Verdict: PASS"
expect 0 "$accelcal" export "$work/redo.db" -o "$work/redo.csv"
grep -q "21 captures of session" "$work/out" || fail "export: $(cat "$work/out")"
grep -q "not written: 1 capture taken again (superseded by the redo)" "$work/err" || fail "export did not name the superseded capture"
grep -v '^#' "$work/redo.csv" | tail -n +2 | cut -d, -f1 | sort -u > "$work/ids"
grep -qx 1 "$work/ids" && fail "the superseded capture 1 was exported"
grep -qx 2 "$work/ids" || fail "the redo's capture 2 was not exported"
"$accelcal" report "$work/redo.db" > "$work/report"
flat "$work/report" "21 captures: 21 used by the fit, 0 left out." || fail "the report does not hold the 21 current captures"
grep -Eq '^ +1 \+z up ' "$work/report" && fail "the report lists the superseded capture 1"

# 2. Quit after +z up and a skipped -z up; the rerun lists what the session holds, in order.
wizard bench_default.toml "$work/resume.db" "$(printf '\\n%.0s' $(seq 10))s\\ns\\nq\\n"
wizard bench_default.toml "$work/resume.db" 'q\n'
said "Resuming session"
said "Welcome: done Level the table: done +z up: done (capture 1) -z up: skipped"
grep -q "done: pose_\|done: welcome" "$work/out" && fail "the summary still shows internal ids"

# 3. The diagnosis: welcome 5, noise floor 1, leveling 3, 9 poses, 9 runs x 3, the repeats 3, fit 1 = 49
#    answers, then d (statistics), d (plain again), Enter (the recommended choice).
#    effects_demo's long radius and bent response put the uncalibrated centripetal reading near
#    the capture check's 10 % (some runs refused, each refusal one more answer): 20 % here, since
#    this part checks the diagnosis's words, not the capture check (clumsy_wrong_radius does).
#    The captures are the fixed 3 s ones (--fixed-duration), the steps' own: the plan's are part 4.
sed -i 's/^turntable_tolerance = 0.10 /turntable_tolerance = 0.20 /' "$work/short.toml"
grep -q '^turntable_tolerance = 0.20 ' "$work/short.toml" || fail "short procedure: no turntable_tolerance"
wizard effects_demo.toml "$work/fx.db" "$(printf '\\n%.0s' $(seq 49))d\\nd\\n\\n" --fixed-duration 3
said "- the turntable radius seems"
said "mm longer than entered"
said "- the sensor's output is not quite a straight line: at 1 g it bends by"
said "correct the bench and the sensor's model and refit (recommended), or keep the basic model?"
said "BIC"
said "Effects adopted: radius_offset"

# 4. The same bench with the plan's captures (lengths by the procedure's [target]): the greedy
#    diagnosis adopts the long radius, then the bent response, and Enter (the recommended choice)
#    takes them. (With fewer captures, before the repeats on the stopped turntable, radius_offset
#    alone missed p < 0.001 here (0.0013) and the fit was refused; a search of effects two at a
#    time was tried for it and dropped: on a settling sensor it adopted a 2.9 deg turntable tilt
#    the captures do not have, tests/unit/app/not_white_test.cpp.)
wizard effects_demo.toml "$work/planned.db" ''
said "- the turntable radius seems"
said "- the sensor's output is not quite a straight line: at 1 g it bends by"
said "Effects adopted: radius_offset, quadratic_nonlinearity"
grep -q "problem: the fit is not usable" "$work/out" && fail "the plan's captures: the fit was refused"

# 5. A fit refused (three poses cannot determine nine parameters): Enter at the refused fit saves
#    and quits with the problem said, the captures kept, and the command says failure (exit
#    status 1, docs/guide.md); a rerun resumes there and ends the same way.
awk '/^\[\[step\]\]/ { exit } { print }' "$work/short.toml" > "$work/three.toml"
cat >> "$work/three.toml" <<'STEPS'
[[step]]
id = "pose_pz"
kind = "static"
up = [0, 0, 1]

[[step]]
id = "pose_mz"
kind = "static"
up = [0, 0, -1]

[[step]]
id = "pose_px"
kind = "static"
up = [1, 0, 0]

[[step]]
id = "fit"
kind = "fit"
title = "Fit the nine-parameter model"
STEPS
cp "$work/three.toml" "$work/short.toml"
expect_exit=1 wizard bench_default.toml "$work/refused.db" ''
said "problem: the fit is not usable"
said "The session cannot go on from here as it is: Enter saves and quits (it resumes here)."
said "Saved. Everything accepted is in session $work/refused.db"
[ "$(grep -c 'problem: the fit is not usable' "$work/out")" -le 2 ] || fail "the refused fit was shown again and again"
expect_exit=1 wizard bench_default.toml "$work/refused.db" ''
said "Resuming session"
said "Fit the nine-parameter model"
said "Saved. Everything accepted is in session $work/refused.db"
echo "wizard_way_back: ok"
