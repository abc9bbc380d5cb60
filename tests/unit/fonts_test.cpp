// The interface's fonts: ASCII is Dear ImGui's own, as before, and letters
// past it come from the font fontconfig finds, where they were all '?'.
#include <gtest/gtest.h>

#include <imgui.h>

#include <chrono>
#include <thread>

#include "window/font_loader.h"
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
  const InterfaceFonts fonts;
  ASSERT_NE(fonts.merged_file(), "") << "fontconfig found no monospace TrueType font (scripts/deps.sh installs DejaVu)";
  InterfaceFonts::Atlas atlas = fonts.make_atlas();
  build(*atlas.atlas);
  for (ImFont* font : {atlas.normal, atlas.small})
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

  const InterfaceFonts fonts;
  InterfaceFonts::Atlas merged = fonts.make_atlas();
  build(*merged.atlas);
  EXPECT_EQ(merged.atlas->Fonts[0], merged.normal) << "the default font";
  EXPECT_EQ(merged.normal->CalcTextSizeA(13.0f, 1e9f, 0.0f, "RM_MAX_STEPS 0.0001 Wg").x, proggy_width);
  EXPECT_EQ(merged.normal->FontSize, proggy_height);
  EXPECT_EQ(merged.small->FontSize, 11.0f);
}

// A text with letters past the first ranges (Chinese, Hebrew) adds them,
// each from a font fontconfig finds (scripts/deps.sh installs WenQuanYi
// Micro Hei for the Chinese ones), once: the atlas built again has them,
// and what it had before.
TEST(InterfaceFonts, LettersATextHoldsAreAddedFromAFontThatHasThem) {
  InterfaceFonts fonts;
  InterfaceFonts::Atlas before = fonts.make_atlas();
  build(*before.atlas);
  const ImWchar li = 0x674E, alef = 0x05D0;  // 李, א
  ASSERT_EQ(before.normal->FindGlyphNoFallback(li), nullptr);
  EXPECT_TRUE(fonts.want("/home/\xE6\x9D\x8E/\xD7\x90.frag:3:1: error: x"));
  EXPECT_FALSE(fonts.want("/home/\xE6\x9D\x8E/\xD7\x90.frag")) << "each letter is looked up once";
  EXPECT_FALSE(fonts.want("plain ASCII, and \xC3\xA4 which the first ranges have"));
  InterfaceFonts::Atlas atlas = fonts.make_atlas();
  build(*atlas.atlas);
  EXPECT_EQ(before.normal->FindGlyphNoFallback(li), nullptr) << "an atlas made before stays as it was";
  for (ImFont* font : {atlas.normal, atlas.small})
    for (ImWchar letter : {li, alef, ImWchar(0x00E4)}) {
      const ImFontGlyph* glyph = font->FindGlyphNoFallback(letter);
      ASSERT_NE(glyph, nullptr) << std::hex << letter;
      EXPECT_GT(glyph->X1 - glyph->X0, 0.0f) << std::hex << letter << " is drawn, not blank";
    }
  EXPECT_EQ(atlas.normal->FontSize, 13.0f);
  EXPECT_EQ(atlas.small->FontSize, 11.0f);
}

// A letter no font has (a private-use one), and bytes that are no UTF-8,
// add nothing and leave the atlas as it is.
TEST(InterfaceFonts, LettersNoFontHasAddNothing) {
  InterfaceFonts fonts;
  EXPECT_FALSE(fonts.want("\xEE\x80\x80 \xFF\xFE \xC3"));
}

// The window's thread only asks: the loader's thread looks the letters up
// and builds an atlas, with its texture data ready, which take() hands over
// once, after waking the caller.
TEST(FontLoader, BuildsAnAtlasWithTheLettersAskedOnItsOwnThread) {
  InterfaceFonts fonts;
  std::mutex mutex;
  std::vector<std::thread::id> woken_on;
  FontLoader loader(fonts, [&] {
    std::lock_guard<std::mutex> lock(mutex);
    woken_on.push_back(std::this_thread::get_id());
  });
  EXPECT_FALSE(loader.ready());
  const std::vector<ImWchar> letters = fonts.unasked("\xE6\x9D\x8E.frag");  // 李
  ASSERT_EQ(letters, std::vector<ImWchar>{0x674E});
  EXPECT_TRUE(fonts.unasked("\xE6\x9D\x8E").empty()) << "asked once";
  loader.ask(letters);
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (!loader.ready() && std::chrono::steady_clock::now() < until)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  std::optional<InterfaceFonts::Atlas> atlas = loader.take();
  ASSERT_TRUE(atlas.has_value()) << "no atlas in 20 s";
  EXPECT_FALSE(loader.ready()) << "taken once";
  EXPECT_FALSE(loader.take().has_value());
  ASSERT_TRUE(atlas->atlas->IsBuilt());
  EXPECT_NE(atlas->atlas->TexPixelsRGBA32, nullptr) << "the backend's texture data is made on the loader's thread";
  const ImFontGlyph* glyph = atlas->normal->FindGlyphNoFallback(0x674E);
  ASSERT_NE(glyph, nullptr);
  EXPECT_GT(glyph->X1 - glyph->X0, 0.0f);
  std::lock_guard<std::mutex> lock(mutex);
  ASSERT_EQ(woken_on.size(), 1u);
  EXPECT_NE(woken_on[0], std::this_thread::get_id());
}

}  // namespace
}  // namespace rm
