// Reading and writing whole text files at the edge: a file read in one piece (once: a pipe
// works) and written atomically (atomic_write.h).
#pragma once

#include <string>

namespace accelcal {

// The bytes of the file at `path`. Throws accelcal::Error "cannot open 'PATH': <reason>".
std::string ReadTextFile(const std::string& path);

// True when `path` names something that can be read only once: a pipe (`<(cat f)`, a FIFO) or
// a character device. A command that tells a session file from a text file by its first bytes
// must not sniff such an input (the bytes read are gone); it is never a session (SQLite needs a
// file it can seek in), so it is read once, as text.
bool IsReadOnceInput(const std::string& path);

// Cuts the regular file at `path` back to the end of its last whole line (after its last LF),
// so that a write cut short (a full disk) leaves no half line a reader would take for a
// malformed sample. Does nothing to a file that is not regular or cannot be opened.
void TruncateToLastWholeLine(const std::string& path);

}  // namespace accelcal
