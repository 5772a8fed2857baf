#!/usr/bin/env bash
# End to end: the calibration report. A whole wizard session on the virtual bench (speed 0),
# whose last step writes SESSION.report.html and SESSION.report.txt; `accelcal report` of the
# session and of its calibration file in every format (text: 80 columns; json: parsed;
# calibration: read by apply; --allan/--noise fixtures); and the HTML report opened in headless
# Chromium, which must be installed (scripts/setup.sh installs it): no check is skipped.
#
# What the Chromium part checks:
#  - --dump-dom: the rendered DOM holds the three inline SVG plots (with their polylines /
#    markers), the verdict and the escaped device; no src/href/url() points anywhere, and no
#    http(s) URL appears at all (the page cannot make a network request);
#  - --screenshot (1200x2000): a PNG whose IHDR says 1200x2000, decoded here (zlib + PNG row
#    filters, python3's standard library only) to check it is not blank: enough non-white
#    pixels, enough dark ones (text, rules, plot lines), many distinct colours, and the
#    report's accent blue present;
#  - --print-to-pdf: a PDF of at least one page (the print stylesheet's path).
# Usage: bash report_html.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail
accelcal=$1 src=$2
# shellcheck source=lib/common.bash
source "$src/tests/e2e/lib/common.bash"
fixtures=$src/tests/data/report

chromium=$(command -v chromium || command -v chromium-browser || true)
[ -n "$chromium" ] || fail "chromium is not installed: run scripts/setup.sh (the HTML report check needs headless Chromium)"

# ---- the wizard's last step writes the report beside the session ----
set +e
yes '' | "$accelcal" wizard --source sim --speed 0 --session "$work/s.db" --plain >"$work/wiz" 2>&1
code=${PIPESTATUS[1]}
set -e
[ "$code" -eq 0 ] || { tail "$work/wiz" >&2; fail "wizard exit $code"; }
[ -s "$work/s.report.html" ] || fail "the wizard wrote no s.report.html"
[ -s "$work/s.report.txt" ] || fail "the wizard wrote no s.report.txt"
grep -q "Report written to $work/s.report.html" "$work/wiz" || fail "the wizard did not say where the report is"
grep -q "SIM-0001" "$work/s.report.txt" || fail "device missing from the wizard's text report"

# ---- text: 80 columns, the sections, the seed procedure's limits ----
expect 0 "$accelcal" report "$work/s.db"
grep -q "ACCELEROMETER CALIBRATION REPORT" "$work/out" || fail "text title"
grep -Eq "^  Device \(serial\): +SIM-0001$" "$work/out" || fail "text device"
grep -Eq '^ +18 .* turntable ' "$work/out" || fail "text capture table"
grep -Eq "^  Overall: (PASS|FAIL)$" "$work/out" || { cat "$work/out"; fail "text verdict"; }
[ "$(awk 'length > 80' "$work/out" | wc -l)" -eq 0 ] || fail "text wider than 80 columns"

# ---- the certificate: its number stable across re-renders, the budget in the calibration ----
number=$(grep -o "ACC-s-[0-9A-F]\{8\}" "$work/s.report.txt" | head -1)
[ -n "$number" ] || fail "no certificate number in the wizard's report"
grep -q "Certificate No.: *$number" "$work/out" || fail "accelcal report gives another certificate number"
grep -q "^B. Uncertainty budget (GUM)$" "$work/out" || fail "no uncertainty budget in the text report"
grep -q "RUL-01" "$work/out" || fail "the equipment is not listed"

# ---- json: the report model, parsed ----
expect 0 "$accelcal" report "$work/s.db" --format json -o "$work/r.json" \
  --allan "$fixtures/allan.json" --noise "$fixtures/noise.json"
python3 - "$work/r.json" <<'PY' || fail "report json"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["format"] == "accelcal-report/1", r["format"]
assert r["device"] == "SIM-0001", r["device"]
assert len(r["parameters"]) == 9 and all(p["sigma"] > 0 for p in r["parameters"])
assert len(r["captures"]) == 19 and r["fit"]["captures_used"] == 19
assert r["verdict"] in ("PASS", "FAIL") and len(r["limits"]) == 9
assert r["allan"]["unit"] == "m/s^2" and len(r["allan"]["axes"]["z"]["tau_s"]) == 14
assert r["noise"]["axes"]["x"]["std"] == 1.21
assert r["residuals"]["stages"][0]["name"] == "base model"
PY

# ---- calibration: the file apply reads; then a report from it alone ----
expect 0 "$accelcal" report "$work/s.db" --format calibration -o "$work/cal.json"
grep -q '"format": "accelcal-calibration/1"' "$work/cal.json" || fail "calibration format"
jq -e '.uncertainty_budget.parameters | length == 9 and all(.[]; .expanded > 0 and (.contributions | length) == 6)' \
  "$work/cal.json" >/dev/null || fail "the calibration carries no uncertainty budget"
printf '0 2051 2040 2400\n' | "$accelcal" apply "$work/cal.json" >/dev/null || fail "apply"
expect 0 "$accelcal" report "$work/cal.json"
grep -Eq "^  Device \(serial\): +not recorded$" "$work/out" || fail "a file alone has no device"
grep -q "The procedure states no pass/fail limits." "$work/out" || fail "a file alone has no limits"

# ---- bad input: one line naming the file ----
printf '{"unit": "g", "axes": {"x": {}}}' >"$work/bad_allan.json"
expect 1 "$accelcal" report "$work/s.db" --allan "$work/bad_allan.json"
grep -q "bad_allan.json.*unit" "$work/err" || { cat "$work/err"; fail "bad allan message"; }
[ "$(wc -l <"$work/err")" -eq 1 ] || fail "more than one line on stderr"
expect 2 "$accelcal" report "$work/s.db" --format pdf

# ---- HTML in headless Chromium ----
expect 0 "$accelcal" report "$work/s.db" --format html -o "$work/r.html" \
  --allan "$fixtures/allan.json" --noise "$fixtures/noise.json"
chrome() {
  timeout 120 "$chromium" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --user-data-dir="$(mktemp -d "$work/profile.XXXX")" "$@" 2>>"$work/chromium.log"
}
chrome --dump-dom "file://$work/r.html" >"$work/dom.html" || { tail "$work/chromium.log" >&2; fail "chromium --dump-dom"; }
chrome --screenshot="$work/shot.png" --window-size=1200,2000 "file://$work/r.html" >/dev/null \
  || { tail "$work/chromium.log" >&2; fail "chromium --screenshot"; }
chrome --print-to-pdf="$work/r.pdf" --no-pdf-header-footer "file://$work/r.html" >/dev/null \
  || { tail "$work/chromium.log" >&2; fail "chromium --print-to-pdf"; }
[ "${ACCELCAL_KEEP_SCREENSHOT:-}" = "" ] || cp "$work/shot.png" "$ACCELCAL_KEEP_SCREENSHOT"

# The certificate's print: "Page k of N" and its number in the footer of every page.
command -v pdftotext >/dev/null || fail "pdftotext is not installed: run scripts/setup.sh (poppler-utils)"
pdftotext -layout "$work/r.pdf" "$work/r.pdf.txt" || fail "pdftotext"
pages=$(grep -c "Page [0-9]* of [0-9]*" "$work/r.pdf.txt" || true)
last=$(grep -o "Page [0-9]* of [0-9]*" "$work/r.pdf.txt" | tail -1)
[ "$pages" -ge 3 ] && [ "$last" = "Page $pages of $pages" ] || fail "page x of y: $pages footers, last '$last'"
[ "$(grep -c "Certificate No. ACC-s-" "$work/r.pdf.txt")" -ge "$pages" ] || fail "the number is not on every page"
grep -q "SIMULATED" "$work/r.pdf.txt" || fail "no SIMULATED mark in the print"

python3 - "$work/dom.html" "$work/shot.png" "$work/r.pdf" <<'PY' || fail "chromium checks"
import re, struct, sys, zlib
dom = open(sys.argv[1], encoding="utf-8").read()
svgs = re.findall(r"<svg\b.*?</svg>", dom, re.S)
assert len(svgs) == 3, f"{len(svgs)} svg plots in the DOM, expected 3"
assert all("<text" in s for s in svgs), "a plot without text"
assert sum(s.count("<circle") + s.count("<rect") + s.count("<path") for s in svgs) > 40, "plots without markers"
assert "<polyline" in svgs[2], "Allan plot without curves"
assert "SIM-0001" in dom and re.search(r'class="verdict (pass|fail)"', dom), "device or verdict missing"
assert not re.search(r"https?:", dom, re.I), "a URL in the rendered DOM"
refs = re.findall(r'\b(?:src|href)\s*=\s*"([^"]*)"', dom, re.I) + re.findall(r"url\(", dom, re.I)
assert not refs, f"external references: {refs}"

png = open(sys.argv[2], "rb").read()
assert png[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
w, h, depth, ctype = struct.unpack(">IIBB", png[16:26])
assert (w, h) == (1200, 2000), (w, h)
assert depth == 8 and ctype in (2, 6), (depth, ctype)
idat, pos = b"", 8
while pos < len(png):
    n, kind = struct.unpack(">I4s", png[pos:pos + 8])
    if kind == b"IDAT":
        idat += png[pos + 8:pos + 8 + n]
    pos += 12 + n
raw, bpp = zlib.decompress(idat), 3 if ctype == 2 else 4
stride, prev, non_white, colours, blue, ink = w * bpp, bytearray(w * bpp), 0, set(), 0, 0
for y in range(h):  # PNG row filters (ISO/IEC 15948, section 9)
    f, row = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a = row[i - bpp] if i >= bpp else 0
        b, c = prev[i], prev[i - bpp] if i >= bpp else 0
        if f == 1: row[i] = (row[i] + a) & 255
        elif f == 2: row[i] = (row[i] + b) & 255
        elif f == 3: row[i] = (row[i] + (a + b) // 2) & 255
        elif f == 4:
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            row[i] = (row[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    for x in range(0, stride, bpp * 2):  # every other pixel: plenty for these counts
        px = bytes(row[x:x + 3])
        colours.add(px)
        if px != b"\xff\xff\xff": non_white += 1
        if max(px) < 120: ink += 1
        if abs(px[0] - 0x1f) < 24 and abs(px[1] - 0x4e) < 24 and abs(px[2] - 0x79) < 24: blue += 1
    prev = row
sampled = w * h // 2
assert non_white > sampled * 0.05, f"screenshot nearly blank: {non_white} of {sampled} pixels not white"
assert ink > sampled * 0.005, f"too little text or line work: {ink} dark pixels of {sampled}"
assert len(colours) > 200, f"only {len(colours)} colours"
assert blue > 500, f"the report's accent colour is missing ({blue} pixels)"

pdf = open(sys.argv[3], "rb").read()
assert pdf[:5] == b"%PDF-", "not a PDF"
pages = len(re.findall(rb"/Type\s*/Page\b", pdf))
assert pages >= 1, "a PDF without pages"
print(f"ok: 3 plots, {non_white}/{sampled} non-white and {ink} dark sampled pixels, {len(colours)} colours, {pages} PDF pages")
PY
echo ok
