#include "window/fonts.h"

#include <fontconfig/fontconfig.h>
#include <imgui.h>

#include <fstream>
#include <iterator>

namespace rm {

namespace {

// What the merged font gives: the letters of paths and messages in Latin,
// Greek and Cyrillic scripts, general punctuation and the replacement
// character; each glyph is rasterised at the window's first frame (about
// 1,000 glyphs, 15 ms for both sizes here). ASCII stays ProggyClean's. ImGui
// keeps a pointer to this list.
const ImWchar kPastAscii[] = {0x00A0, 0x024F, 0x0370, 0x03FF, 0x0400, 0x04FF, 0x2000, 0x206F, 0xFFFD, 0xFFFD, 0};

constexpr FcChar32 kProbe = 0x00E4;  // ä: a font without it is no help

// A monospace TrueType font with letters past ASCII, as fontconfig matches
// "monospace"; "" when there is none.
std::string monospace_font_file() {
  if (!FcInit()) return "";
  FcPattern* pattern = FcNameParse(reinterpret_cast<const FcChar8*>("monospace"));
  FcCharSet* wanted = FcCharSetCreate();
  FcCharSetAddChar(wanted, kProbe);
  FcPatternAddCharSet(pattern, FC_CHARSET, wanted);
  FcConfigSubstitute(nullptr, pattern, FcMatchPattern);
  FcDefaultSubstitute(pattern);
  FcResult result;
  FcPattern* match = FcFontMatch(nullptr, pattern, &result);
  std::string file;
  FcChar8* path = nullptr;
  FcChar8* format = nullptr;
  FcCharSet* has = nullptr;
  // Only TrueType: ImGui's rasteriser (stb_truetype) reads no bitmap or Type 1 font.
  if (match && FcPatternGetString(match, FC_FILE, 0, &path) == FcResultMatch &&
      FcPatternGetString(match, FC_FONTFORMAT, 0, &format) == FcResultMatch &&
      std::string(reinterpret_cast<const char*>(format)) == "TrueType" &&
      FcPatternGetCharSet(match, FC_CHARSET, 0, &has) == FcResultMatch && FcCharSetHasChar(has, kProbe))
    file = reinterpret_cast<const char*>(path);
  if (match) FcPatternDestroy(match);
  FcCharSetDestroy(wanted);
  FcPatternDestroy(pattern);
  return file;
}

}  // namespace

InterfaceFonts::InterfaceFonts(ImFontAtlas& atlas) {
  const std::string file = monospace_font_file();
  if (!file.empty()) {
    std::ifstream in(file, std::ios::binary);
    merged_bytes_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (in.bad() || merged_bytes_.empty()) merged_bytes_.clear();
    else merged_file_ = file;
  }
  auto add = [&](float pixels) {
    ImFontConfig own;
    own.SizePixels = pixels;
    ImFont* font = atlas.AddFontDefault(&own);
    if (!merged_bytes_.empty()) {
      ImFontConfig past;
      past.MergeMode = true;
      past.FontDataOwnedByAtlas = false;  // merged_bytes_ holds them, for both sizes
      atlas.AddFontFromMemoryTTF(merged_bytes_.data(), static_cast<int>(merged_bytes_.size()), pixels, &past,
                                 kPastAscii);
    }
    return font;
  };
  normal_ = add(13.0f);
  small_ = add(11.0f);
}

}  // namespace rm
