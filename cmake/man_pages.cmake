# Run with cmake -P by the build (target accelcal_docs): writes the manual pages into MAN_DIR.
#   man1/  accelcal(1) and one page per command, by the program itself (`accelcal help-man`)
#          from its command line's definition: the very text of --help.
#   man5/  the file formats, from their Markdown text (FORMAT_PAGES below) by lowdown(1).
# Every page is gzip-compressed (gzip -9n: no name or time stamp in it), as Debian installs them.
# Inputs: ACCELCAL (the program), SOURCE_DIR, MAN_DIR, LOWDOWN and GZIP (programs; LOWDOWN may be
# empty: then the section-5 pages are left out, with a warning).

# The section-5 pages: name | source | the heading of its section in the source ("" the whole
# file) | its NAME line. The text lives in the docs/ pages (README.md's "Where things are").
set(FORMAT_PAGES
  "accelcal-procedure|docs/guide.md|## Procedures|the procedure file (TOML): the wizard's steps, the checks' tolerances, the pass/fail limits and the bench's equipment"
  "accelcal-calibration|docs/formats.md|## Calibration file (JSON)|the calibration file (JSON) that fit, report and the wizard write and apply reads"
  "accelcal-capture-set|docs/formats.md|## Capture-set file (CSV)|the capture-set file (CSV) that simulate and export write and fit reads")

file(REMOVE_RECURSE "${MAN_DIR}/man1" "${MAN_DIR}/man5")
file(MAKE_DIRECTORY "${MAN_DIR}/man1" "${MAN_DIR}/man5")

set(see_also "")
foreach(page IN LISTS FORMAT_PAGES)
  string(REPLACE "|" ";" fields "${page}")
  list(GET fields 0 name)
  list(APPEND see_also --also "${name}(5)")
endforeach()
execute_process(COMMAND "${ACCELCAL}" help-man --dir "${MAN_DIR}" ${see_also} RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "accelcal help-man failed (${failed})")
endif()
execute_process(COMMAND "${ACCELCAL}" --version OUTPUT_VARIABLE version OUTPUT_STRIP_TRAILING_WHITESPACE)

# The text of `source` from the line `heading` to the next heading of level 1 to 3 (read whole:
# Markdown's blank lines and semicolons must survive, which file(STRINGS) would not keep).
function(markdown_section source heading out)
  file(READ "${source}" text)
  if(NOT heading STREQUAL "")
    string(FIND "\n${text}" "\n${heading}\n" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "${source}: no section '${heading}' for a manual page")
    endif()
    string(LENGTH "${heading}" length)
    math(EXPR at "${at} + ${length} + 1")
    string(SUBSTRING "${text}" ${at} -1 text)
    string(LENGTH "${text}" end)
    foreach(next "\n# " "\n## " "\n### ")
      string(FIND "${text}" "${next}" found)
      if(NOT found EQUAL -1 AND found LESS end)
        set(end ${found})
      endif()
    endforeach()
    string(SUBSTRING "${text}" 0 ${end} text)
  endif()
  set(${out} "${text}\n" PARENT_SCOPE)
endfunction()

if(NOT LOWDOWN)
  message(WARNING "lowdown not found (scripts/setup.sh installs it): no section-5 manual pages")
else()
  foreach(page IN LISTS FORMAT_PAGES)
    string(REPLACE "|" ";" fields "${page}")
    list(GET fields 0 name)
    list(GET fields 1 source)
    list(GET fields 2 heading)
    list(GET fields 3 summary)
    markdown_section("${SOURCE_DIR}/${source}" "${heading}" text)
    file(WRITE "${MAN_DIR}/${name}.md" "${text}")
    # Markdown as written: no superscripts (2^n-1), straight quotes.
    execute_process(COMMAND "${LOWDOWN}" -Tman --parse-no-super --out-no-smarty "${MAN_DIR}/${name}.md"
                    OUTPUT_VARIABLE body RESULT_VARIABLE failed)
    file(REMOVE "${MAN_DIR}/${name}.md")
    if(failed)
      message(FATAL_ERROR "lowdown failed on ${source} (${heading})")
    endif()
    string(TOUPPER "${name}" title)
    string(REPLACE "-" "\\-" roff_name "${name}")
    file(WRITE "${MAN_DIR}/man5/${name}.5"
      ".TH \"${title}\" \"5\" \"\" \"${version}\" \"accelcal manual\"\n"
      ".SH NAME\n${roff_name} \\- ${summary}\n.SH DESCRIPTION\n${body}"
      ".SH SEE ALSO\n\\fBaccelcal\\fR(1)\n")
  endforeach()
endif()

if(GZIP)
  file(GLOB pages "${MAN_DIR}/man1/*.1" "${MAN_DIR}/man5/*.5")
  foreach(page IN LISTS pages)
    execute_process(COMMAND "${GZIP}" -9nf "${page}" RESULT_VARIABLE failed)
    if(failed)
      message(FATAL_ERROR "gzip failed on ${page}")
    endif()
  endforeach()
endif()
