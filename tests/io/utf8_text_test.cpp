// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/utf8_text.h"

#include <gtest/gtest.h>

namespace roomcad {
namespace {

TEST(Utf8Text, WellFormedTextHasNoIllFormedByte) {
  EXPECT_EQ(first_ill_formed_utf8(""), std::nullopt);
  EXPECT_EQ(first_ill_formed_utf8("wall-1"), std::nullopt);
  EXPECT_EQ(first_ill_formed_utf8("K\xc3\xbc"
                                  "che \xe2\x82\xac \xf0\x9f\x8f\xa0"),
            std::nullopt);
  EXPECT_EQ(first_ill_formed_utf8("\xf4\x8f\xbf\xbf"), std::nullopt);  // U+10FFFF, the last
}

TEST(Utf8Text, EachKindOfIllFormedSequenceIsFoundWhereItStarts) {
  EXPECT_EQ(first_ill_formed_utf8("ab\xff"), 2u);  // never in UTF-8
  EXPECT_EQ(first_ill_formed_utf8("K\xfc"
                                  "che"),
            1u);                                  // Latin-1
  EXPECT_EQ(first_ill_formed_utf8("a\xc3"), 1u);  // truncated at the end
  EXPECT_EQ(first_ill_formed_utf8("\xe2\x82"
                                  "x"),
            0u);                                             // truncated inside
  EXPECT_EQ(first_ill_formed_utf8("\xc0\xaf"), 0u);          // overlong '/'
  EXPECT_EQ(first_ill_formed_utf8("\xe0\x80\xaf"), 0u);      // overlong, three bytes
  EXPECT_EQ(first_ill_formed_utf8("x\xed\xa0\x80"), 1u);     // surrogate U+D800
  EXPECT_EQ(first_ill_formed_utf8("\xf4\x90\x80\x80"), 0u);  // U+110000
  EXPECT_EQ(first_ill_formed_utf8("\x80"), 0u);              // a lone continuation byte
}

TEST(Utf8Text, IllFormedBytesAreReadAsLatin1AndTheRestKept) {
  EXPECT_EQ(utf8_from_latin1_where_ill_formed("K\xfc"
                                              "che"),
            "K\xc3\xbc"
            "che");
  EXPECT_EQ(utf8_from_latin1_where_ill_formed("\xe2\x82\xac \xa9"), "\xe2\x82\xac \xc2\xa9");
  EXPECT_EQ(utf8_from_latin1_where_ill_formed("plain"), "plain");
  EXPECT_EQ(first_ill_formed_utf8(utf8_from_latin1_where_ill_formed("\xed\xa0\x80\xff")),
            std::nullopt);
}

TEST(Utf8Text, PrintableTextEscapesOnlyIllFormedBytes) {
  EXPECT_EQ(printable_utf8("K\xfc"
                           "che \xc3\xbc"),
            "K\\xFCche \xc3\xbc");
}

}  // namespace
}  // namespace roomcad
