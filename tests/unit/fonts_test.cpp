// The interface's fonts: ASCII is Dear ImGui's own, as before, and letters
// past it come from the font fontconfig finds, where they were all '?'.
#include <gtest/gtest.h>

#include <imgui.h>

#include "window/fonts.h"

namespace rm {
namespace {

// An atlas of its own, no ImGui context: built as the window's is at its first frame.
void build(ImFontAtlas& atlas) {
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  atlas.GetTexDataAsAlpha8(&pixels, &width, &height);
  ASSERT_NE(pixels, nullptr);
}

TEST(InterfaceFonts, LettersPastAsciiHaveTheirOwnGlyphs) {
  ImFontAtlas atlas;
  const InterfaceFonts fonts(atlas);
  ASSERT_NE(fonts.merged_file(), "") << "fontconfig found no monospace TrueType font (scripts/deps.sh installs DejaVu)";
  build(atlas);
  for (ImFont* font : {fonts.normal(), fonts.small()})
    for (ImWchar letter : {0x00E4 /* ä */, 0x00DF /* ß */, 0x0436 /* ж */, 0x03BB /* λ */, 0x2014 /* — */,
                           0x2026 /* … */}) {
      const ImFontGlyph* glyph = font->FindGlyphNoFallback(letter);
      ASSERT_NE(glyph, nullptr) << std::hex << letter;
      EXPECT_GT(glyph->X1 - glyph->X0, 0.0f) << std::hex << letter << " is drawn, not blank";
    }
}

// ASCII keeps ProggyClean's glyphs, so each panel is laid out as before
// (the e2e tests click widgets at fixed places).
TEST(InterfaceFonts, AsciiIsDearImGuisOwnFont) {
  ImFontAtlas own;
  ImFont* proggy = own.AddFontDefault();
  build(own);
  const float proggy_width = proggy->CalcTextSizeA(13.0f, 1e9f, 0.0f, "RM_MAX_STEPS 0.0001 Wg").x;
  const float proggy_height = proggy->FontSize;

  ImFontAtlas merged;
  const InterfaceFonts fonts(merged);
  build(merged);
  EXPECT_EQ(fonts.normal()->CalcTextSizeA(13.0f, 1e9f, 0.0f, "RM_MAX_STEPS 0.0001 Wg").x, proggy_width);
  EXPECT_EQ(fonts.normal()->FontSize, proggy_height);
  EXPECT_EQ(fonts.small()->FontSize, 11.0f);
}

// A text with letters past the first ranges (Chinese, Hebrew) adds them,
// each from a font fontconfig finds (scripts/deps.sh installs WenQuanYi
// Micro Hei for the Chinese ones), once: the atlas built again has them,
// and what it had before.
TEST(InterfaceFonts, LettersATextHoldsAreAddedFromAFontThatHasThem) {
  ImFontAtlas atlas;
  InterfaceFonts fonts(atlas);
  build(atlas);
  const ImWchar li = 0x674E, alef = 0x05D0;  // 李, א
  ASSERT_EQ(fonts.normal()->FindGlyphNoFallback(li), nullptr);
  EXPECT_TRUE(fonts.want("/home/\xE6\x9D\x8E/\xD7\x90.frag:3:1: error: x"));
  EXPECT_FALSE(fonts.want("/home/\xE6\x9D\x8E/\xD7\x90.frag")) << "each letter is looked up once";
  EXPECT_FALSE(fonts.want("plain ASCII, and \xC3\xA4 which the first ranges have"));
  fonts.rebuild(atlas);
  build(atlas);
  for (ImFont* font : {fonts.normal(), fonts.small()})
    for (ImWchar letter : {li, alef, ImWchar(0x00E4)}) {
      const ImFontGlyph* glyph = font->FindGlyphNoFallback(letter);
      ASSERT_NE(glyph, nullptr) << std::hex << letter;
      EXPECT_GT(glyph->X1 - glyph->X0, 0.0f) << std::hex << letter << " is drawn, not blank";
    }
  EXPECT_EQ(fonts.normal()->FontSize, 13.0f);
  EXPECT_EQ(fonts.small()->FontSize, 11.0f);
}

// A letter no font has (a private-use one), and bytes that are no UTF-8,
// add nothing and leave the atlas as it is.
TEST(InterfaceFonts, LettersNoFontHasAddNothing) {
  ImFontAtlas atlas;
  InterfaceFonts fonts(atlas);
  EXPECT_FALSE(fonts.want("\xEE\x80\x80 \xFF\xFE \xC3"));
}

}  // namespace
}  // namespace rm
