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
  // Finds the monospace font (fontconfig) and reads it.
  InterfaceFonts();
  InterfaceFonts(const InterfaceFonts&) = delete;
  InterfaceFonts& operator=(const InterfaceFonts&) = delete;

  // An atlas of the fonts and the lists of letters it takes from them,
  // which it reads whenever it is built. It also reads the TrueType files'
  // bytes from this object then, so it is built only while this object lives.
  struct Atlas {
    std::unique_ptr<ImFontAtlas> atlas;
    ImFont* normal = nullptr;  // 13 px, the default (the atlas's first font)
    ImFont* small = nullptr;   // 11 px, for warnings
    std::vector<std::vector<ImWchar>> ranges;  // per font file: pairs, then 0
  };
  // The fonts with every letter found so far, not built yet.
  Atlas make_atlas() const;

  // The file the letters past ASCII come from; "" when fontconfig found
  // none, and they show as '?' as before.
  const std::string& merged_file() const { return merged_file_; }

  // The letters of `text` (UTF-8) past the first ranges that no call has
  // returned before (at most 2 kMaxAdded in all): cheap, for the window's
  // thread at every frame.
  std::vector<ImWchar> unasked(std::string_view text);
  // Looks up `letters` in the fonts, and in fonts fontconfig finds for them
  // (tens of ms for a new script: the lookup and reading its file); true
  // when one was found, and an atlas made now would draw it. A
  // letter no font has is drawn as Dear ImGui's fallback: U+FFFD from the
  // monospace font, or '?'.
  bool find(const std::vector<ImWchar>& letters);
  // Both: true when an atlas made now draws a letter of `text` that one made
  // before did not.
  bool want(std::string_view text) { return find(unasked(text)); }

  // unasked() touches only what no other member does: the window's thread
  // calls it while the loader's thread calls find() and make_atlas().

  // At most this many letters are added, so that the atlas stays small.
  static constexpr size_t kMaxAdded = 4096;

 private:
  struct FontFile {
    std::string path;
    int index = 0;                // the face, in a collection (.ttc)
    std::shared_ptr<void> charset;  // fontconfig's FcCharSet: the letters it has
    std::vector<char> bytes;      // its buffer stays put when files_ grows: atlases point into it
    std::vector<ImWchar> added;   // letters find() found here
  };
  FontFile* file_for(ImWchar letter);

  std::vector<FontFile> files_;  // the monospace font first, if any
  std::set<unsigned> asked_;     // every letter unasked() returned
  size_t added_ = 0;
  std::string merged_file_;
};

}  // namespace rm
