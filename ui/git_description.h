// `git describe --tags --always --dirty` of the source tree the program was built from
// ("68dabc6", "v0.2.0-3-g1a2b3c4-dirty"), empty when it was not built from a git checkout (a
// release tarball). Written at every build by cmake/git_description.cmake into a file of the
// executable alone, rewritten only when it changes: a moved HEAD recompiles that one file and
// relinks the program, nothing else.
#pragma once

namespace accelcal {

extern const char* const kGitDescription;

}  // namespace accelcal
