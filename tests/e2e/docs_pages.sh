#!/usr/bin/env bash
# End-to-end (issue 35): the README is the front door and every page it points to exists; every
# citation of a docs page in the code, scripts, procedures and docs (`docs/formats.md, "Sample
# sources"`) names a page that exists and, when it names a section, a heading of that page; the
# README stays within 200 lines.
# Usage: bash docs_pages.sh ACCELCAL SOURCE_DIR DATA_DIR
set -euo pipefail

src=$2
fail() { echo "FAIL: $*" >&2; exit 1; }
cd "$src"

lines=$(wc -l < README.md)
(( lines <= 200 )) || fail "README.md has $lines lines (the front door keeps to 200)"

# The pages the README links to.
count=0
while IFS= read -r page; do
  [[ -f $page ]] || fail "README.md points to $page, which does not exist"
  count=$((count + 1))
done < <(grep -o '](docs/[A-Za-z_]*\.md)' README.md | sed 's/^](//; s/)$//' | sort -u)
(( count >= 10 )) || fail "README.md links to only $count docs pages"

# Citations: docs/<page>.md, "Section" (possibly across a line break, as comments wrap).
grep -rhoE 'docs/[A-Za-z_]+\.md' src ui tests scripts cmake procedures scenarios docs README.md \
    ARCHITECTURE.md CMakeLists.txt | sort -u | while IFS= read -r page; do
  [[ -f $page ]] || fail "a citation names $page, which does not exist"
done
# The sections cited on one line: `docs/<page>.md, "Title"` must be a heading ("## Title" or deeper,
# or the start of one: a citation may shorten a long title).
grep -rhoE 'docs/[A-Za-z_]+\.md, "[^"]+"' src ui tests scripts cmake procedures scenarios docs \
    README.md ARCHITECTURE.md | sort -u | while IFS= read -r cite; do
  page=${cite%%,*}
  title=${cite#*\"}
  title=${title%\"}
  grep -qE "^#{2,4} $(printf '%s' "$title" | sed 's/[][().*^$/\\]/\\&/g')" "$page" ||
    fail "$cite: no such section in $page"
done

echo "docs_pages: ok ($count pages linked from README.md)"
