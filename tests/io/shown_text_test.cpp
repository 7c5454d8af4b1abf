// Text from files in messages: one line whatever the bytes, UTF-8 names readable, long values cut.
#include "io/shown_text.h"

#include <gtest/gtest.h>

#include <string>

namespace angio {
namespace {

TEST(ShownText, NonPrintableBytesAreEscapedUtf8KeptAndLongValuesCut) {
  EXPECT_EQ(shownText(std::string("a\nb\x01\xff", 5)), "a\\x0ab\\x01\\xff");
  EXPECT_EQ(shownText("M\xc3\xbcller \xe2\x80\x93 left"), "M\xc3\xbcller \xe2\x80\x93 left");
  EXPECT_EQ(shownText("cut \xc3"), "cut \\xc3");                   // a character cut short
  EXPECT_EQ(shownText("\xc3\x28 \xc0\xaf"), "\\xc3( \\xc0\\xaf");  // bad continuation, overlong lead
  EXPECT_EQ(shownText(std::string(100, 'x')), std::string(80, 'x') + "...");
  EXPECT_EQ(shownText(std::string(100, 'x'), 64), std::string(64, 'x') + "...");
  EXPECT_EQ(quotedText("a\tb"), "'a\\x09b'");
}

}  // namespace
}  // namespace angio
