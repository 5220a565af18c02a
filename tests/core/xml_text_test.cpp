#include "core/xml_text.h"

#include <gtest/gtest.h>

namespace viscera::core {
namespace {

TEST(XmlText, escapes_the_four_characters_that_break_text_and_attributes) {
  EXPECT_EQ(xml_escaped(R"(a<b & "c">d)"), "a&lt;b &amp; &quot;c&quot;&gt;d");
}

TEST(XmlText, leaves_other_text_and_utf8_alone) {
  EXPECT_EQ(xml_escaped("uterus 30° optics 'left'"), "uterus 30° optics 'left'");
  EXPECT_EQ(xml_escaped(""), "");
}

TEST(XmlText, escapes_an_ampersand_once_not_again) {
  EXPECT_EQ(xml_escaped("&amp;"), "&amp;amp;");
}

}  // namespace
}  // namespace viscera::core
