#!/usr/bin/env bash
# The manual pages the build writes (build/share/man): one per command --help lists, each page's
# options exactly --help's (names, types, defaults, descriptions), rendered by man(1); the file
# formats in section 5; every NAME line readable by lexgrog (what mandb and whatis read).
# Usage: man_pages.sh ACCELCAL SOURCE_DIR SHARED_DATA_DIR
set -euo pipefail
accelcal=$(realpath "$1")
man_dir=$(dirname "$accelcal")/share/man
source_dir=$2
. "$source_dir/tests/e2e/lib/common.bash"
command -v man >/dev/null || { echo "SKIP: man (man-db) is not installed"; exit 77; }
export MANPAGER=cat PAGER=cat MANWIDTH=200 LC_ALL=C.UTF-8

commands=$("$accelcal" --help | awk '/^Subcommands:/{on=1; next} on && !/^ /{exit} on && /^  [a-z]/{print $1}')
[ "$(echo "$commands" | wc -l)" -ge 12 ] || fail "too few commands in --help: $commands"
pages=$(ls "$man_dir/man1")
[ "$(echo "$pages" | wc -l)" -eq $(( $(echo "$commands" | wc -l) + 1 )) ] ||
  fail "man1 holds [$(echo $pages)], not one page per command and accelcal.1"

check_page() {  # check_page NAME HELP_ARGS...: NAME's page against `accelcal HELP_ARGS --help`
  local name=$1; shift
  local page=$man_dir/man1/$name.1.gz
  [ -f "$page" ] || fail "no page $page"
  [ "$(man -M "$man_dir" -w "$name")" = "$page" ] || fail "man -w $name does not find $page"
  lexgrog "$page" | grep -q "\"$name - ." || fail "$name: NAME not readable: $(lexgrog "$page")"
  "$accelcal" "$@" --help > "$work/help.txt"
  man --nh --nj -l "$page" > "$work/page.txt" 2> "$work/man.err"
  [ ! -s "$work/man.err" ] || fail "$name: man says $(cat "$work/man.err")"
  python3 - "$page" "$work/help.txt" "$work/page.txt" <<'PY' || fail "$name: the page's options differ from --help"
import gzip, re, sys
roff = gzip.open(sys.argv[1], "rt").read()
help_text = open(sys.argv[2]).read()
rendered = open(sys.argv[3]).read()

def plain(roff_text):
    text = roff_text.replace("\\-", "-").replace("\\(aq", "'").replace("\\(ga", "`")
    text = text.replace("\\e", "\\").replace("\\&", "")
    return re.sub(r"\\f[BRI]", "", text)

def words(text):
    return " ".join(text.split())

# The page's options: each .TP entry before its COMMANDS (accelcal(1)'s list of commands):
# the head line and the description lines up to the next macro.
entries = []
groups = set()  # the sections holding them: --help's groups (ARGUMENTS is its "Positionals")
section = ""
lines = roff.split("\n")
if ".SH COMMANDS" in lines:
    lines = lines[:lines.index(".SH COMMANDS")]
for i, line in enumerate(lines):
    if line.startswith(".SH "):
        section = line[4:]
    if line == ".TP" and lines[i + 1].startswith("\\fB"):
        groups.add("POSITIONALS" if section == "ARGUMENTS" else section)
        head = plain(lines[i + 1])
        desc = []
        for l in lines[i + 2:]:
            if l.startswith(".") and l not in (".nf", ".fi", ".PP"):
                break
            if l not in (".nf", ".fi", ".PP"):
                desc.append(plain(l))
        entries.append((head, "\n".join(desc)))
heads = [h for h, _ in entries]

# --help's option entries: a line of two spaces and a name, in a group ("Options:", ...) up to
# the blank line that ends it.
help_heads = []
in_group = False
for line in help_text.split("\n"):
    if re.match(r"^[A-Z][A-Za-z ]*:$", line):
        in_group = line[:-1].upper() in groups
        continue
    if not line:
        in_group = False
    if in_group and re.match(r"^  [^ ]", line):
        help_heads.append(line)

unmatched = []
for line in help_heads:
    match = [h for h in heads if line == "  " + h or line.startswith("  " + h + " ")]
    if not match:
        unmatched.append(line)
assert not unmatched, ("in --help, not on the page", unmatched, heads)
for h in heads:
    assert any(l == "  " + h or l.startswith("  " + h + " ") for l in help_heads), ("on the page, not in --help", h)
flat_help = words(help_text)
flat_page = words(rendered)
for head, desc in entries:
    assert words(head) in flat_page, ("head not rendered", head)
    # The description as --help prints it (its line breaks aside), and as man renders it.
    assert words(desc) in flat_help, ("description not in --help", head, desc)
    assert words(desc) in flat_page, ("description not rendered", head, desc)
PY
}

check_page accelcal
for command in $commands; do check_page "accelcal-$command" "$command"; done
[ ! -e "$man_dir/man1/accelcal-help-man.1.gz" ] || fail "a page for a hidden command"

# The root page lists every command and points to its page.
man -l "$man_dir/man1/accelcal.1.gz" > "$work/accelcal.txt"
for command in $commands; do
  grep -q "See accelcal-$command(1)" "$work/accelcal.txt" || fail "accelcal(1) does not point to accelcal-$command(1)"
done
grep -q "EXIT STATUS" "$work/accelcal.txt" || fail "accelcal(1) has no EXIT STATUS"

# The file formats.
for page in procedure:nominal_scale_counts_per_mps2 calibration:accelcal-calibration/1 capture-set:adc_range_counts; do
  name=accelcal-${page%%:*}
  [ "$(man -M "$man_dir" -w 5 "$name")" = "$man_dir/man5/$name.5.gz" ] || fail "man 5 $name not found"
  lexgrog "$man_dir/man5/$name.5.gz" | grep -q "\"$name - ." || fail "$name(5): NAME not readable"
  man -M "$man_dir" 5 "$name" 2> "$work/man.err" | grep -qF -- "${page#*:}" || fail "$name(5) lacks ${page#*:}"
  [ ! -s "$work/man.err" ] || fail "$name(5): man says $(cat "$work/man.err")"
done
echo ok
