#include "core/channel_spec.h"

#include <charconv>
#include <cstdio>

#include "core/lexing.h"
#include "core/one_line.h"

namespace rm {

namespace {

// The next blank-separated word of `text` from *at, or "" at the end.
std::string_view next_word(std::string_view text, size_t* at) {
  *at = lexing::skip_blanks(text, *at);
  const size_t begin = *at;
  while (*at < text.size() && !lexing::is_blank(text[*at])) ++*at;
  return text.substr(begin, *at - begin);
}

bool read_setting(std::string_view word, ChannelSpec* spec, std::string* error) {
  const size_t eq = word.find('=');
  const std::string_view key = word.substr(0, eq), value = eq == std::string_view::npos ? "" : word.substr(eq + 1);
  Sampler* s = &spec->sampler;
  if (key == "size" && spec->kind == ChannelSpec::Kind::Pass && spec->shape == ChannelSpec::Shape::Cube) {
    int size = 0;
    for (char c : value) size = lexing::is_digit(c) && size <= 16384 ? size * 10 + (c - '0') : -1;
    if (value.empty() || size < 1 || size > 4096) {
      *error = "size=N expects a face size from 1 to 4096, not '" + brief(value) + "'";
      return false;
    }
    spec->cube_size = size;
  } else if ((key == "size" || key == "scale") && spec->shape == ChannelSpec::Shape::Flat &&
             (spec->kind == ChannelSpec::Kind::Pass || spec->kind == ChannelSpec::Kind::Self)) {
    std::optional<BufferSize> size = parse_buffer_size(value, key == "size", error);
    if (!size) {
      *error = std::string(key) + "=" + *error;
      return false;
    }
    spec->buffer_size = *size;
  } else if (key == "filter" && value == "nearest") s->filter = Sampler::Filter::Nearest;
  else if (key == "filter" && value == "linear") s->filter = Sampler::Filter::Linear;
  else if (key == "filter" && value == "mipmap") s->filter = Sampler::Filter::Mipmap;
  else if (key == "wrap" && value == "clamp") s->wrap = Sampler::Wrap::Clamp;
  else if (key == "wrap" && value == "repeat") s->wrap = Sampler::Wrap::Repeat;
  else if (key == "vflip" && value == "true") s->vflip = true;
  else if (key == "vflip" && value == "false") s->vflip = false;
  else {
    *error = "unknown channel setting '" + brief(word) +
             "' (cube, volume, filter=nearest|linear|mipmap, wrap=clamp|repeat, vflip=true|false, size=N for a cube pass, size=WxH or scale=F for a buffer)";
    return false;
  }
  return true;
}

}  // namespace

std::optional<BufferSize> parse_buffer_size(std::string_view text, bool fixed, std::string* error) {
  BufferSize size;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  if (fixed) {
    // Digits, 'x', digits: from_chars alone would take a sign.
    const auto [x, ex] = std::from_chars(begin, end, size.width);
    const bool by = ex == std::errc() && lexing::is_digit(*begin) && x + 1 < end && *x == 'x' && lexing::is_digit(x[1]);
    const auto [y, ey] =
        by ? std::from_chars(x + 1, end, size.height) : std::from_chars_result{x, std::errc::invalid_argument};
    const bool ok = ey == std::errc() && y == end && size.width >= 1 && size.height >= 1 &&
                    size.width <= BufferSize::kMaxSide && size.height <= BufferSize::kMaxSide;
    if (ok) return size;
    *error = "WxH expects a width and a height from 1 to " + std::to_string(BufferSize::kMaxSide) + ", not '" + brief(text) +
             "'";
    return std::nullopt;
  }
  auto [last, ec] = std::from_chars(begin, end, size.scale);
  if (ec == std::errc() && last == end && !text.empty() && (lexing::is_digit(*begin) || *begin == '.') &&
      size.scale > 0 && size.scale <= 1)
    return size;
  *error = "F expects a share of the picture's size above 0 and at most 1, not '" + brief(text) + "'";
  return std::nullopt;
}

std::string to_string(const BufferSize& size) {
  if (size.width > 0) return "size=" + std::to_string(size.width) + "x" + std::to_string(size.height);
  if (size.scale <= 0) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "scale=%g", size.scale);
  return buf;
}

Sampler default_sampler(ChannelSpec::Kind kind, ChannelSpec::Shape shape) {
  using K = ChannelSpec::Kind;
  Sampler s;
  // Cube maps are not flipped (GL's faces put their first row at the top),
  // and volumes have no up.
  if (shape != ChannelSpec::Shape::Flat) s.vflip = false;
  if (kind == K::Image && shape == ChannelSpec::Shape::Volume) s.filter = Sampler::Filter::Linear;
  if (kind == K::Pass || kind == K::Self) {
    s.filter = Sampler::Filter::Linear;
    s.wrap = Sampler::Wrap::Clamp;
  } else if (kind == K::Keyboard) {
    s.filter = Sampler::Filter::Nearest;
    s.wrap = Sampler::Wrap::Clamp;
  }
  return s;
}

int channel_of_sampler(std::string_view name) {
  for (const std::string_view prefix : {std::string_view("iChannel"), std::string_view("u_tex")})
    if (name.size() == prefix.size() + 1 && name.substr(0, prefix.size()) == prefix && name.back() >= '0' &&
        name.back() <= '3')
      return name.back() - '0';
  return -1;
}

bool is_shader_file(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  return ext == ".frag" || ext == ".glsl" || ext == ".fs";
}

std::optional<ChannelSpec> parse_channel_spec(std::string_view text, const std::filesystem::path& relative_to,
                                              std::string* error) {
  ChannelSpec spec;
  size_t at = lexing::skip_blanks(text, 0);
  if (at < text.size() && text[at] == '"') {
    const size_t end = text.find('"', at + 1);
    if (end == std::string_view::npos || end == at + 1) {
      *error = "expects \"FILE\", self, keyboard or black";
      return std::nullopt;
    }
    spec.path = (relative_to / std::string(text.substr(at + 1, end - at - 1))).lexically_normal();
    spec.kind = is_shader_file(spec.path) ? ChannelSpec::Kind::Pass : ChannelSpec::Kind::Image;
    at = end + 1;
    if (at < text.size() && !lexing::is_blank(text[at]) && !lexing::nothing_but_comment(text.substr(at))) {
      *error = "expects blanks after the file name";
      return std::nullopt;
    }
  } else {
    const std::string_view word = next_word(text, &at);
    if (word == "self") spec.kind = ChannelSpec::Kind::Self;
    else if (word == "keyboard") spec.kind = ChannelSpec::Kind::Keyboard;
    else if (word == "black") spec.kind = ChannelSpec::Kind::Black;
    else {
      *error = "expects \"FILE\", self, keyboard or black";
      return std::nullopt;
    }
  }
  spec.sampler = default_sampler(spec.kind);
  bool first = true;
  while (true) {
    const size_t before = at;
    const std::string_view word = next_word(text, &at);
    if (word.empty() || lexing::nothing_but_comment(text.substr(before))) break;
    // The shape comes first: a cube map's default sampler differs from an image's.
    const bool shape_word = word == "cube" || word == "volume";
    if (shape_word && !first) {
      *error = "'" + std::string(word) + "' goes right after the file name";
      return std::nullopt;
    }
    if (shape_word && spec.kind == ChannelSpec::Kind::Black) {
      spec.shape = word == "cube" ? ChannelSpec::Shape::Cube : ChannelSpec::Shape::Volume;  // a black cube or volume
      first = false;
      continue;
    }
    if (shape_word && (spec.kind == ChannelSpec::Kind::Keyboard ||
                       (word == "volume" && spec.kind != ChannelSpec::Kind::Image))) {
      *error = word == "cube" ? "the keyboard is not a cube map" : "a volume is read from a file (.bin or stacked slices)";
      return std::nullopt;
    }
    first = false;
    if (shape_word) {
      spec.shape = word == "cube" ? ChannelSpec::Shape::Cube : ChannelSpec::Shape::Volume;
      spec.sampler = default_sampler(spec.kind, spec.shape);
      continue;
    }
    if (!read_setting(word, &spec, error)) return std::nullopt;
  }
  return spec;
}

std::string channel_spec_text(const ChannelSpec& spec, const std::string& file) {
  using K = ChannelSpec::Kind;
  std::string out = spec.kind == K::Self       ? "self"
                    : spec.kind == K::Keyboard ? "keyboard"
                    : spec.kind == K::Black    ? "black"
                                               : "\"" + file + "\"";
  if (spec.shape == ChannelSpec::Shape::Cube) out += " cube";
  if (spec.shape == ChannelSpec::Shape::Volume) out += " volume";
  if (spec.cube_size > 0) out += " size=" + std::to_string(spec.cube_size);
  if (spec.buffer_size.given()) out += " " + to_string(spec.buffer_size);
  const Sampler d = default_sampler(spec.kind, spec.shape), s = spec.sampler;
  if (s.filter != d.filter)
    out += s.filter == Sampler::Filter::Nearest ? " filter=nearest"
           : s.filter == Sampler::Filter::Linear ? " filter=linear" : " filter=mipmap";
  if (s.wrap != d.wrap) out += s.wrap == Sampler::Wrap::Clamp ? " wrap=clamp" : " wrap=repeat";
  if (s.vflip != d.vflip) out += s.vflip ? " vflip=true" : " vflip=false";
  return out;
}

std::vector<std::filesystem::path> cube_face_files(const std::filesystem::path& first,
                                                   const std::function<bool(const std::filesystem::path&)>& exists) {
  std::vector<std::filesystem::path> files{first};
  for (int i = 1; i < 6; ++i) {
    std::filesystem::path face = first;
    face.replace_filename(first.stem().string() + "_" + std::to_string(i) + first.extension().string());
    if (!exists(face)) return i == 1 ? std::vector<std::filesystem::path>{} : files;
    files.push_back(face);
  }
  return files;
}

const char* glsl_sampler_type(ChannelSpec::Shape shape) {
  switch (shape) {
    case ChannelSpec::Shape::Cube: return "samplerCube";
    case ChannelSpec::Shape::Volume: return "sampler3D";
    default: return "sampler2D";
  }
}

const char* to_string(ChannelSpec::Kind kind) {
  switch (kind) {
    case ChannelSpec::Kind::None: return "nothing";
    case ChannelSpec::Kind::Image: return "image";
    case ChannelSpec::Kind::Pass: return "buffer";
    case ChannelSpec::Kind::Self: return "self";
    case ChannelSpec::Kind::Keyboard: return "keyboard";
    case ChannelSpec::Kind::Black: return "black";
  }
  return "?";
}

}  // namespace rm
