// The interface's fonts. Dear ImGui's own font (ProggyClean) has only ASCII,
// and drew every other letter as '?': an error at /home/jürgen/scene.frag
// read /home/j?rgen/scene.frag. Each size keeps ProggyClean for ASCII, so the
// panels' layout is what it was, and takes the letters past it (Latin,
// Greek, Cyrillic, punctuation such as "—") from a TrueType monospace font
// that fontconfig finds (DejaVu Sans Mono on Debian).
#pragma once
#include <string>
#include <vector>

struct ImFont;
struct ImFontAtlas;

namespace rm {

class InterfaceFonts {
 public:
  // Adds the fonts to `atlas`, which reads the TrueType file's bytes from
  // this object whenever it is built (the window's first frame), so it is
  // built only while this object lives.
  explicit InterfaceFonts(ImFontAtlas& atlas);
  InterfaceFonts(const InterfaceFonts&) = delete;
  InterfaceFonts& operator=(const InterfaceFonts&) = delete;

  ImFont* normal() const { return normal_; }  // 13 px, the default
  ImFont* small() const { return small_; }    // 11 px, for warnings
  // The file the letters past ASCII come from; "" when fontconfig found
  // none, and they show as '?' as before.
  const std::string& merged_file() const { return merged_file_; }

 private:
  std::vector<char> merged_bytes_;
  std::string merged_file_;
  ImFont* normal_ = nullptr;
  ImFont* small_ = nullptr;
};

}  // namespace rm
