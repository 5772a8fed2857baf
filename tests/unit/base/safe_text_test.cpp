// Text from outside on its way to JSON, terminals and exported comments (base/safe_text.h).
#include <gtest/gtest.h>

#include "accelcal/base/safe_text.h"

namespace accelcal {
namespace {

TEST(SafeText, WellFormedUtf8IsRecognized) {
  EXPECT_TRUE(IsValidUtf8(""));
  EXPECT_TRUE(IsValidUtf8("SN-1234"));
  EXPECT_TRUE(IsValidUtf8("Se\xC3\xB1or Mu\xC3\xB1oz \xE2\x82\xAC \xF0\x9F\x98\x80"));  // ñ € 😀
  EXPECT_FALSE(IsValidUtf8("SN\xFF"));            // never in UTF-8
  EXPECT_FALSE(IsValidUtf8("Se\xF1or"));          // Latin-1 n tilde
  EXPECT_FALSE(IsValidUtf8("\xC0\xAF"));          // overlong '/'
  EXPECT_FALSE(IsValidUtf8("\xE0\x80\xAF"));      // overlong, three bytes
  EXPECT_FALSE(IsValidUtf8("\xED\xA0\x80"));      // a surrogate
  EXPECT_FALSE(IsValidUtf8("\xF4\x90\x80\x80"));  // beyond U+10FFFF
  EXPECT_FALSE(IsValidUtf8("\xE2\x82"));          // cut short
}

TEST(SafeText, IllFormedBytesBecomeReplacementCharacters) {
  EXPECT_EQ(ToValidUtf8("SN\xFF\xFE-1"), "SN\xEF\xBF\xBD\xEF\xBF\xBD-1");
  EXPECT_EQ(ToValidUtf8("Se\xC3\xB1or"), "Se\xC3\xB1or");  // well-formed: unchanged
  EXPECT_EQ(ToValidUtf8("\xE2\x82"), "\xEF\xBF\xBD\xEF\xBF\xBD");
  EXPECT_TRUE(IsValidUtf8(ToValidUtf8("a\x80\xC3(\xF5\xED\xA0\x80z")));
}

TEST(SafeText, ControlCharactersAndLineBreaksAreEscaped) {
  EXPECT_EQ(DisplayText("SN1\nINS_ACCOFFS_X,9"), "SN1\\nINS_ACCOFFS_X,9");
  EXPECT_EQ(DisplayText("a\r\tb"), "a\\r\\tb");
  EXPECT_EQ(DisplayText("\x1B[2Jcleared"), "\\x1B[2Jcleared");
  EXPECT_EQ(DisplayText("del\x7F"), "del\\x7F");
  EXPECT_EQ(DisplayText("nel\xC2\x85"), "nel\\xC2\\x85");              // C1 NEL: a YAML line break
  EXPECT_EQ(DisplayText("ls\xE2\x80\xA8ps\xE2\x80\xA9"), "ls\\xE2\\x80\\xA8ps\\xE2\\x80\\xA9");
  EXPECT_EQ(DisplayText("bad\xFF"), "bad\\xFF");
  EXPECT_EQ(DisplayText("Se\xC3\xB1or C:\\data"), "Se\xC3\xB1or C:\\data");  // kept
}

}  // namespace
}  // namespace accelcal
