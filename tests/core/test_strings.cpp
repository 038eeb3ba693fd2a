// Text helpers (core/strings.h): what a message may quote of a damaged file.
#include <glint/core/strings.h>

#include <gtest/gtest.h>

namespace glint {

TEST(PrintableText, KeepsTextAndUtf8AndMarksEverythingElse) {
    EXPECT_EQ(printable_text("plain text, tab\tand newline\n"), "plain text, tab\tand newline\n");
    EXPECT_EQ(printable_text("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x8c\x8d"),
              "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x8c\x8d");  // 2-, 3- and 4-byte sequences
    EXPECT_EQ(printable_text(std::string("\x00\x02\x1b\x7f", 4)), "????");   // control bytes
    EXPECT_EQ(printable_text("\xd2\x04@\x9a PNG chunk"), "??@? PNG chunk");  // broken UTF-8
    EXPECT_EQ(printable_text("cut \xe2\x82"), "cut ??");  // a sequence cut short at the end
    EXPECT_EQ(printable_text("\xff\xfe"), "??");          // bytes that start no sequence
}

}  // namespace glint
