// Text that came from outside (answers typed in the wizard, fields of files, command-line
// options) on its way to places that cannot hold every byte:
//
//   - JSON holds only well-formed UTF-8 (RFC 8259 section 8.1): ToValidUtf8 replaces each
//     ill-formed byte with U+FFFD, the replacement character, so a typed answer with a stray
//     Latin-1 byte is kept (visibly damaged) rather than refused or written as invalid JSON.
//   - A terminal, a table, an error message or a one-line comment in an exported file holds no
//     control character and no line break: DisplayText writes them as escapes, so a label can
//     neither move the cursor, nor clear the screen, nor start a new line in a parameter file.
//
// UTF-8 is well-formed as RFC 3629 defines it: no overlong forms, no surrogates (U+D800..DFFF),
// nothing above U+10FFFF.
#pragma once

#include <string>
#include <string_view>

namespace accelcal {

// True when `text` is well-formed UTF-8.
bool IsValidUtf8(std::string_view text);

// `text` with every byte that is not part of a well-formed UTF-8 sequence replaced by U+FFFD
// (EF BF BD); well-formed text comes back unchanged.
std::string ToValidUtf8(std::string_view text);

// `text` as one line of printable text: well-formed printable characters are kept (any
// script); LF, CR and TAB become "\n", "\r", "\t"; the other control characters (C0, DEL, the
// C1 range U+0080..U+009F, which holds NEL), the line and paragraph separators U+2028/U+2029,
// the byte-order mark U+FEFF, the non-characters U+FFFE/U+FFFF and each ill-formed byte become
// "\xHH" per byte of their UTF-8 form. A backslash is kept as it is (a path stays readable).
std::string DisplayText(std::string_view text);

// DisplayText(text) cut to at most `max_bytes` bytes (at a character's boundary) with "~" at
// the end when it was cut: a label in a table column.
std::string ShortDisplayText(std::string_view text, size_t max_bytes);

// Each line of `text` through DisplayText, the line breaks (LF) kept: an error message of
// several lines whose parts came from a file or a user.
std::string DisplayLines(std::string_view text);

}  // namespace accelcal
