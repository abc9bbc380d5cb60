#include "core/channel_spec.h"

#include "core/lexing.h"

namespace rm {

namespace {

// The next blank-separated word of `text` from *at, or "" at the end.
std::string_view next_word(std::string_view text, size_t* at) {
  *at = lexing::skip_blanks(text, *at);
  const size_t begin = *at;
  while (*at < text.size() && !lexing::is_blank(text[*at])) ++*at;
  return text.substr(begin, *at - begin);
}

bool read_setting(std::string_view word, Sampler* s, std::string* error) {
  const size_t eq = word.find('=');
  const std::string_view key = word.substr(0, eq), value = eq == std::string_view::npos ? "" : word.substr(eq + 1);
  if (key == "filter" && value == "nearest") s->filter = Sampler::Filter::Nearest;
  else if (key == "filter" && value == "linear") s->filter = Sampler::Filter::Linear;
  else if (key == "filter" && value == "mipmap") s->filter = Sampler::Filter::Mipmap;
  else if (key == "wrap" && value == "clamp") s->wrap = Sampler::Wrap::Clamp;
  else if (key == "wrap" && value == "repeat") s->wrap = Sampler::Wrap::Repeat;
  else if (key == "vflip" && value == "true") s->vflip = true;
  else if (key == "vflip" && value == "false") s->vflip = false;
  else {
    *error = "unknown channel setting '" + std::string(word) +
             "' (filter=nearest|linear|mipmap, wrap=clamp|repeat, vflip=true|false)";
    return false;
  }
  return true;
}

}  // namespace

Sampler default_sampler(ChannelSpec::Kind kind) {
  using K = ChannelSpec::Kind;
  Sampler s;
  if (kind == K::Pass || kind == K::Self) {
    s.filter = Sampler::Filter::Linear;
    s.wrap = Sampler::Wrap::Clamp;
  } else if (kind == K::Keyboard) {
    s.filter = Sampler::Filter::Nearest;
    s.wrap = Sampler::Wrap::Clamp;
  }
  return s;
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
      *error = "expects \"FILE\", self or keyboard";
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
    else {
      *error = "expects \"FILE\", self or keyboard";
      return std::nullopt;
    }
  }
  spec.sampler = default_sampler(spec.kind);
  while (true) {
    const size_t before = at;
    const std::string_view word = next_word(text, &at);
    if (word.empty() || lexing::nothing_but_comment(text.substr(before))) break;
    if (!read_setting(word, &spec.sampler, error)) return std::nullopt;
  }
  return spec;
}

std::string channel_spec_text(const ChannelSpec& spec, const std::string& file) {
  using K = ChannelSpec::Kind;
  std::string out = spec.kind == K::Self ? "self" : spec.kind == K::Keyboard ? "keyboard" : "\"" + file + "\"";
  const Sampler d = default_sampler(spec.kind), s = spec.sampler;
  if (s.filter != d.filter)
    out += s.filter == Sampler::Filter::Nearest ? " filter=nearest"
           : s.filter == Sampler::Filter::Linear ? " filter=linear" : " filter=mipmap";
  if (s.wrap != d.wrap) out += s.wrap == Sampler::Wrap::Clamp ? " wrap=clamp" : " wrap=repeat";
  if (s.vflip != d.vflip) out += s.vflip ? " vflip=true" : " vflip=false";
  return out;
}

const char* to_string(ChannelSpec::Kind kind) {
  switch (kind) {
    case ChannelSpec::Kind::None: return "nothing";
    case ChannelSpec::Kind::Image: return "image";
    case ChannelSpec::Kind::Pass: return "buffer";
    case ChannelSpec::Kind::Self: return "self";
    case ChannelSpec::Kind::Keyboard: return "keyboard";
  }
  return "?";
}

}  // namespace rm
