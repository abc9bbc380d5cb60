#include "window/fonts.h"

#include <fontconfig/fontconfig.h>
#include <imgui_internal.h>  // ImTextCharFromUtf8

#include <fstream>
#include <iterator>

namespace rm {

namespace {

// What the merged font gives from the start: the letters of paths and
// messages in Latin, Greek and Cyrillic scripts, general punctuation and the
// replacement character; each glyph is rasterised at the window's first
// frame (about 1,000 glyphs, 15 ms for both sizes here). ASCII stays
// ProggyClean's.
const ImWchar kPastAscii[] = {0x00A0, 0x024F, 0x0370, 0x03FF, 0x0400, 0x04FF, 0x2000, 0x206F, 0xFFFD, 0xFFFD, 0};

bool in_past_ascii(unsigned letter) {
  for (const ImWchar* r = kPastAscii; r[0]; r += 2)
    if (letter >= r[0] && letter <= r[1]) return true;
  return false;
}

constexpr FcChar32 kProbe = 0x00E4;  // ä: a monospace font without it is no help
constexpr size_t kMaxFiles = 8;      // fonts the added letters may come from

// A face that has `letter`, in a format ImGui's rasteriser (stb_truetype)
// reads (TrueType or CFF, not a bitmap or Type 1 font): fontconfig's best
// match for `family` with it, or else the first such face in its sorted list.
bool find_face(const char* family, FcChar32 letter, std::string* path, int* index,
               std::shared_ptr<void>* charset) {
  if (!FcInit()) return false;
  FcPattern* pattern = FcNameParse(reinterpret_cast<const FcChar8*>(family));
  FcCharSet* wanted = FcCharSetCreate();
  FcCharSetAddChar(wanted, letter);
  FcPatternAddCharSet(pattern, FC_CHARSET, wanted);
  FcConfigSubstitute(nullptr, pattern, FcMatchPattern);
  FcDefaultSubstitute(pattern);
  FcResult result;
  FcPattern* best = FcFontMatch(nullptr, pattern, &result);
  FcFontSet* sorted = nullptr;
  bool found = false;
  for (int i = -1; !found; ++i) {
    if (i == 0) sorted = FcFontSort(nullptr, pattern, FcFalse, nullptr, &result);
    if (i >= 0 && (!sorted || i >= sorted->nfont)) break;
    FcPattern* face = i < 0 ? best : sorted->fonts[i];
    if (!face) continue;
    FcChar8* file = nullptr;
    FcChar8* format = nullptr;
    FcCharSet* has = nullptr;
    int face_index = 0;
    if (FcPatternGetString(face, FC_FILE, 0, &file) != FcResultMatch ||
        FcPatternGetString(face, FC_FONTFORMAT, 0, &format) != FcResultMatch ||
        FcPatternGetCharSet(face, FC_CHARSET, 0, &has) != FcResultMatch || !FcCharSetHasChar(has, letter))
      continue;
    const std::string kind = reinterpret_cast<const char*>(format);
    if (kind != "TrueType" && kind != "CFF") continue;
    if (FcPatternGetInteger(face, FC_INDEX, 0, &face_index) != FcResultMatch) face_index = 0;
    *path = reinterpret_cast<const char*>(file);
    *index = face_index;
    *charset = std::shared_ptr<void>(FcCharSetCopy(has), [](void* c) { FcCharSetDestroy(static_cast<FcCharSet*>(c)); });
    found = true;
  }
  if (best) FcPatternDestroy(best);
  if (sorted) FcFontSetDestroy(sorted);
  FcCharSetDestroy(wanted);
  FcPatternDestroy(pattern);
  return found;
}

std::vector<char> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) bytes.clear();
  return bytes;
}

}  // namespace

InterfaceFonts::InterfaceFonts() {
  FontFile mono;
  if (find_face("monospace", kProbe, &mono.path, &mono.index, &mono.charset)) {
    mono.bytes = read_bytes(mono.path);
    if (!mono.bytes.empty()) {
      merged_file_ = mono.path;
      files_.push_back(std::move(mono));
    }
  }
}

InterfaceFonts::FontFile* InterfaceFonts::file_for(ImWchar letter) {
  for (FontFile& f : files_)
    if (FcCharSetHasChar(static_cast<FcCharSet*>(f.charset.get()), letter)) return &f;
  if (files_.size() >= kMaxFiles) return nullptr;
  FontFile found;
  if (!find_face("monospace", letter, &found.path, &found.index, &found.charset)) return nullptr;
  found.bytes = read_bytes(found.path);
  if (found.bytes.empty()) return nullptr;
  files_.push_back(std::move(found));
  return &files_.back();
}

std::vector<ImWchar> InterfaceFonts::unasked(std::string_view text) {
  std::vector<ImWchar> letters;
  const char* at = text.data();
  const char* end = at + text.size();
  while (at < end) {
    if (static_cast<unsigned char>(*at) < 0x80) {
      ++at;
      continue;
    }
    unsigned letter = 0;
    const int bytes = ImTextCharFromUtf8(&letter, at, end);
    at += bytes > 0 ? bytes : 1;
    if (letter > IM_UNICODE_CODEPOINT_MAX || in_past_ascii(letter) || asked_.size() >= 2 * kMaxAdded ||
        !asked_.insert(letter).second)
      continue;
    letters.push_back(static_cast<ImWchar>(letter));
  }
  return letters;
}

bool InterfaceFonts::find(const std::vector<ImWchar>& letters) {
  bool found = false;
  for (ImWchar letter : letters) {
    if (added_ >= kMaxAdded) break;
    if (FontFile* f = file_for(letter)) {
      f->added.push_back(letter);
      ++added_;
      found = true;
    }
  }
  return found;
}

InterfaceFonts::Atlas InterfaceFonts::make_atlas() const {
  Atlas out;
  out.atlas = std::make_unique<ImFontAtlas>();
  for (size_t i = 0; i < files_.size(); ++i) {
    std::vector<ImWchar> ranges;
    if (i == 0) ranges.assign(std::begin(kPastAscii), std::end(kPastAscii) - 1);
    for (ImWchar letter : files_[i].added) ranges.insert(ranges.end(), {letter, letter});
    ranges.push_back(0);
    out.ranges.push_back(std::move(ranges));
  }
  auto add = [&](float pixels) {
    ImFontConfig own;
    own.SizePixels = pixels;
    ImFont* font = out.atlas->AddFontDefault(&own);
    for (size_t i = 0; i < files_.size(); ++i) {
      if (out.ranges[i].size() < 2) continue;
      const FontFile& f = files_[i];
      ImFontConfig past;
      past.MergeMode = true;
      past.FontDataOwnedByAtlas = false;  // files_ holds them, for both sizes
      past.FontNo = f.index;
      out.atlas->AddFontFromMemoryTTF(const_cast<char*>(f.bytes.data()), static_cast<int>(f.bytes.size()), pixels,
                                      &past, out.ranges[i].data());
    }
    return font;
  };
  out.normal = add(13.0f);
  out.small = add(11.0f);
  return out;
}

}  // namespace rm
