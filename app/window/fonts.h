// The interface's fonts. Dear ImGui's own font (ProggyClean) has only ASCII,
// and drew every other letter as '?': an error at /home/jürgen/scene.frag
// read /home/j?rgen/scene.frag. Each size keeps ProggyClean for ASCII, so the
// panels' layout is what it was, and takes the letters past it (Latin,
// Greek, Cyrillic, punctuation such as "—") from a TrueType monospace font
// that fontconfig finds (DejaVu Sans Mono on Debian). Other letters (a path
// or a message in Chinese, Japanese, Korean, Hebrew, ...) are added when a
// text to be shown holds them, each from a font fontconfig finds for it.
#pragma once
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <imgui.h>

namespace rm {

class InterfaceFonts {
 public:
  // Adds the fonts to `atlas`, which reads the TrueType files' bytes from
  // this object whenever it is built (the window's first frame), so it is
  // built only while this object lives.
  explicit InterfaceFonts(ImFontAtlas& atlas);
  InterfaceFonts(const InterfaceFonts&) = delete;
  InterfaceFonts& operator=(const InterfaceFonts&) = delete;

  ImFont* normal() const { return normal_; }  // 13 px, the default
  ImFont* small() const { return small_; }    // 11 px, for warnings
  // The file the letters past ASCII come from; "" when fontconfig found
  // none, and they show as '?' as before.
  const std::string& merged_file() const { return files_.empty() ? none_ : files_.front().path; }

  // Looks up, once each, the letters of `text` (UTF-8) that the fonts do
  // not have yet; true when one was found in a font, and rebuild() must run
  // before the next frame for it to be drawn. A letter no font has is drawn
  // as Dear ImGui's fallback: U+FFFD from the monospace font, or '?'.
  bool want(std::string_view text);
  // Adds the fonts to `atlas` again, cleared first, with every letter
  // want() found; normal() and small() change. The caller uploads the
  // atlas's texture again.
  void rebuild(ImFontAtlas& atlas);

  // At most this many letters are added, so that the atlas stays small.
  static constexpr size_t kMaxAdded = 4096;

 private:
  struct FontFile {
    std::string path;
    int index = 0;                // the face, in a collection (.ttc)
    std::shared_ptr<void> charset;  // fontconfig's FcCharSet: the letters it has
    std::vector<char> bytes;
    std::vector<ImWchar> added;   // letters want() found here
    std::vector<ImWchar> ranges;  // what the atlas takes from it: pairs, then 0
  };
  void add_fonts(ImFontAtlas& atlas);
  FontFile* file_for(ImWchar letter);

  std::vector<FontFile> files_;  // the monospace font first, if any
  std::set<unsigned> asked_;     // every letter looked up
  size_t added_ = 0;
  std::string none_;
  ImFont* normal_ = nullptr;
  ImFont* small_ = nullptr;
};

}  // namespace rm
