#include "penumbra/support/xml.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace penumbra {
namespace {

using ::testing::HasSubstr;

TEST(Xml, EscapesWhatItWritesAndReadsItBack) {
  const std::string awkward = "a < b && c > \"d\" 'e'\n\ttab";
  XmlElement root{
      "root", {{"value", awkward}}, "", {{"child", {}, awkward, {}}, {"empty", {}, "", {}}}};
  const std::string xml = to_xml(root);
  EXPECT_THAT(xml, HasSubstr("value=\"a &lt; b &amp;&amp; c &gt; &quot;d&quot; 'e'&#10;&#9;tab\""));
  EXPECT_THAT(xml, HasSubstr("<empty/>"));
  auto back = parse_xml(xml, "doc.xml");
  ASSERT_TRUE(back.ok()) << back.error().to_string();
  EXPECT_EQ(*back->attribute("value"), awkward);
  ASSERT_EQ(back->children.size(), 2u);
  EXPECT_EQ(back->children[0].text, awkward);
  EXPECT_TRUE(back->text.empty());  // the indentation between children
  EXPECT_EQ(back->attribute("absent"), nullptr);
}

TEST(Xml, ReplacesWhatXmlCannotCarry) {
  const std::string bad = std::string("bell\x07 nul") + '\0' + " cut\xC3 end \xF0\x9F\x98\x80";
  const std::string xml = to_xml({"root", {{"v", bad}}, bad, {}});
  auto back = parse_xml(xml, "doc.xml");
  ASSERT_TRUE(back.ok()) << back.error().to_string();
  const std::string expected =
      "bell\xEF\xBF\xBD nul\xEF\xBF\xBD cut\xEF\xBF\xBD end \xF0\x9F\x98\x80";
  EXPECT_EQ(back->text, expected);
  EXPECT_EQ(*back->attribute("v"), expected);
}

TEST(Xml, ReadsCommentsCdataReferencesAndSingleQuotes) {
  auto doc = parse_xml(
      "\xEF\xBB\xBF<?xml version='1.0'?>\n<!-- c --><a x='1 &#x41;&#66;'><![CDATA[<raw>&]]>"
      "<?pi?><!-- in --><b/></a>\n",
      "doc.xml");
  ASSERT_TRUE(doc.ok()) << doc.error().to_string();
  EXPECT_EQ(*doc->attribute("x"), "1 AB");
  EXPECT_EQ(doc->text, "<raw>&");
  ASSERT_EQ(doc->children.size(), 1u);
  EXPECT_EQ(doc->children[0].name, "b");
}

TEST(Xml, RejectsWhatIsNotWellFormedWithItsPlace) {
  const std::pair<std::string, std::string> cases[] = {
      {"", "expected the root element"},
      {"<a>", "<a> is not closed"},
      {"<a></b>", "</b> does not match <a>"},
      {"<a x=1/>", "quoted attribute value"},
      {"<a x='1' x='2'/>", "given twice"},
      {"<a x='1'y='2'/>", "whitespace before an attribute"},
      {"<a>&nbsp;</a>", "unknown entity"},
      {"<a>&#0;</a>", "not an XML character"},
      {"<a>&#x110000;</a>", "out of range"},
      {"<a>a & b</a>", "'&' outside a reference"},
      {"<a/><b/>", "content after the root element"},
      {"<!DOCTYPE a><a/>", "DOCTYPE"},
      {"<a><!-- open</a>", "comment is not closed"},
      {"<a x='<'/>", "'<' in an attribute value"},
      {"\n  <1/>", "expected a name"},
  };
  for (const auto& [text, message] : cases) {
    auto doc = parse_xml(text, "doc.xml");
    ASSERT_FALSE(doc.ok()) << text;
    EXPECT_EQ(doc.error().kind, Error::Kind::bad_input);
    EXPECT_THAT(doc.error().message, HasSubstr(message)) << text;
    EXPECT_THAT(doc.error().where, ::testing::StartsWith("doc.xml:")) << text;
  }
  EXPECT_EQ(parse_xml("\n  <1/>", "doc.xml").error().where, "doc.xml:2:4");
}

TEST(Xml, BoundsTheNestingDepth) {
  std::string deep;
  for (int i = 0; i < 100000; ++i) deep += "<a>";
  auto doc = parse_xml(deep, "deep.xml");
  ASSERT_FALSE(doc.ok());
  EXPECT_THAT(doc.error().message, HasSubstr("nested deeper"));
}

}  // namespace
}  // namespace penumbra
