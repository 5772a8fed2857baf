# Run with cmake -P, at configure time and at every build (target accelcal_git_description):
# writes into OUT_DIR
#   git_description.cpp     accelcal::kGitDescription, `git describe --tags --always --dirty`
#                           of SOURCE_DIR ("68dabc6", "v0.2.0-3-g1a2b3c4-dirty"), empty outside
#                           a git checkout (a release tarball)
#   package_version.cmake   ACCELCAL_PACKAGE_VERSION for CPack: PROJECT_VERSION, then
#                           "+git<commits>.g<hash>[.dirty]" unless HEAD is tagged
#                           v<PROJECT_VERSION> and clean (a Debian version that grows with
#                           the history)
# Each file is rewritten only when its content changes, so an unchanged HEAD rebuilds nothing and
# a moved one recompiles git_description.cpp alone (a file of the executable only).
# Inputs: SOURCE_DIR, OUT_DIR, PROJECT_VERSION, GIT (the git program; may be empty).
set(description "")
set(package_version "${PROJECT_VERSION}")
if(GIT AND EXISTS "${SOURCE_DIR}/.git")
  execute_process(COMMAND "${GIT}" -C "${SOURCE_DIR}" describe --tags --always --dirty
                  OUTPUT_VARIABLE description RESULT_VARIABLE described
                  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  execute_process(COMMAND "${GIT}" -C "${SOURCE_DIR}" rev-list --count HEAD
                  OUTPUT_VARIABLE commits OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  execute_process(COMMAND "${GIT}" -C "${SOURCE_DIR}" rev-parse --short HEAD
                  OUTPUT_VARIABLE hash OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT described EQUAL 0)
    set(description "")
  endif()
  # Nothing but what a version and a C++ string may hold.
  string(REGEX REPLACE "[^A-Za-z0-9._+-]" "_" description "${description}")
  if(description AND NOT description STREQUAL "v${PROJECT_VERSION}" AND commits AND hash)
    set(package_version "${PROJECT_VERSION}+git${commits}.g${hash}")
    if(description MATCHES "-dirty$")
      string(APPEND package_version ".dirty")
    endif()
  endif()
endif()

function(write_if_changed path content)
  if(EXISTS "${path}")
    file(READ "${path}" old)
    if(old STREQUAL content)
      return()
    endif()
  endif()
  file(WRITE "${path}" "${content}")
endfunction()

write_if_changed("${OUT_DIR}/git_description.cpp"
"// Written by cmake/git_description.cmake at build time: do not edit.
#include \"git_description.h\"

namespace accelcal {

const char* const kGitDescription = \"${description}\";

}  // namespace accelcal
")
write_if_changed("${OUT_DIR}/package_version.cmake"
"# Written by cmake/git_description.cmake at build time: do not edit.
set(ACCELCAL_GIT_DESCRIPTION \"${description}\")
set(ACCELCAL_PACKAGE_VERSION \"${package_version}\")
")
