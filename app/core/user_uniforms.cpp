#include "core/user_uniforms.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/check.h"
#include "core/host_inputs.h"
#include "core/lexing.h"
#include "core/one_line.h"

namespace rm {

namespace {

// The types a control can hold.
struct TypeName {
  const char* glsl;
  UserUniform::Type type;
};
constexpr TypeName kTypes[] = {{"float", UserUniform::Type::Float}, {"int", UserUniform::Type::Int},
                               {"bool", UserUniform::Type::Bool},   {"vec2", UserUniform::Type::Vec2},
                               {"vec3", UserUniform::Type::Vec3},   {"vec4", UserUniform::Type::Vec4}};

std::string_view next_word(std::string_view text, size_t* at) {
  *at = lexing::skip_blanks(text, *at);
  const size_t begin = *at;
  while (*at < text.size() && lexing::is_word_char(text[*at])) ++*at;
  return text.substr(begin, *at - begin);
}

bool host_supplies(std::string_view name) {
  for (const HostInput& input : host_inputs())
    if (input.name == name) return true;
  return name.substr(0, 8) == "iChannel" || name.substr(0, 5) == "u_tex";
}

// shaderlib's own uniforms (rm/common.glsl's rm_Zero, which no one sets):
// the library's, not the scene's to control.
bool library_uniform(std::string_view name) { return name.substr(0, 3) == "rm_"; }

std::optional<float> number(std::string_view text) {
  const std::string s(text);
  char* end = nullptr;
  const float v = std::strtof(s.c_str(), &end);
  // nan, inf and what overflows a float (1e39) are no value a control can hold.
  if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// Reads "ui: min=0 max=4 step=0.1 default=1 color" into `u`; one warning
// per word it cannot read.
void read_annotation(std::string_view text, UserUniform* u, Diagnostics* warnings) {
  auto warn = [&](const std::string& why) {
    Diagnostic d;
    d.severity = Severity::Warning;
    d.path = u->path;
    d.line = u->line;
    d.message = "uniform " + u->name + ": " + why + " (ui: min=A max=B step=S default=V color)";
    warnings->push_back(std::move(d));
  };
  size_t at = 0;
  while (true) {
    at = lexing::skip_blanks(text, at);
    if (at >= text.size()) break;
    size_t end = at;
    while (end < text.size() && !lexing::is_blank(text[end])) ++end;
    const std::string_view word = text.substr(at, end - at);
    at = end;
    if (word == "color" || word == "colour") {
      if (u->components < 3) warn("only a vec3 or vec4 can be a colour");
      else u->color = true;
      continue;
    }
    const size_t eq = word.find('=');
    const std::string_view key = word.substr(0, eq);
    const std::string value = eq == std::string_view::npos ? "" : std::string(word.substr(eq + 1));
    if (key == "default") {
      std::string why;
      if (auto v = parse_uniform_value(*u, value, &why)) u->initial = *v;
      else warn("default=" + brief(value) + ": " + why);
    } else if (key == "min" || key == "max" || key == "step") {
      auto v = number(value);
      if (!v) warn(std::string(key) + "=" + brief(value) + " is not a number");
      else (key == "min" ? u->min : key == "max" ? u->max : u->step) = *v;
    } else {
      warn("'" + brief(word) + "' is not understood");
    }
  }
  if (u->min > u->max) {
    warn("min is above max");
    std::swap(u->min, u->max);
  }
}

}  // namespace

const UserUniform* UserUniforms::find(const std::string& name) const {
  for (const UserUniform& u : uniforms)
    if (u.name == name) return &u;
  return nullptr;
}

std::optional<std::vector<float>> parse_uniform_value(const UserUniform& u, const std::string& text,
                                                      std::string* error) {
  std::vector<float> out;
  if (u.type == UserUniform::Type::Bool) {
    if (text == "true" || text == "1") return std::vector<float>{1.0f};
    if (text == "false" || text == "0") return std::vector<float>{0.0f};
    *error = "a bool is true or false";
    return std::nullopt;
  }
  size_t at = 0;
  while (at <= text.size()) {
    size_t comma = text.find(',', at);
    if (comma == std::string::npos) comma = text.size();
    auto v = number(std::string_view(text).substr(at, comma - at));
    if (!v) {
      *error = "'" + brief(text) + "' is not " + (u.components == 1 ? "a number" : std::to_string(u.components) + " numbers");
      return std::nullopt;
    }
    // An int's value as an int: past its range the cast is undefined.
    if (u.type == UserUniform::Type::Int && !(*v >= -2147483648.0f && *v < 2147483648.0f)) {
      *error = "'" + brief(std::string_view(text).substr(at, comma - at)) + "' is out of an int's range";
      return std::nullopt;
    }
    out.push_back(u.type == UserUniform::Type::Int ? static_cast<float>(static_cast<int>(*v)) : *v);
    at = comma + 1;
  }
  if (static_cast<int>(out.size()) != u.components) {
    *error = "'" + brief(text) + "' has " + std::to_string(out.size()) + " numbers; " + u.name + " takes " +
             std::to_string(u.components);
    return std::nullopt;
  }
  return out;
}

std::string uniform_value_text(const UserUniform::Type type, const std::vector<float>& value) {
  if (type == UserUniform::Type::Bool) return !value.empty() && value[0] != 0.0f ? "true" : "false";
  std::string out;
  for (float v : value) {
    char buf[48];  // a float written whole is at most 40 characters
    // Never "-0"; an int whole ("%.9g" wrote 1073741824 as 1.07374182e+09).
    std::snprintf(buf, sizeof buf, type == UserUniform::Type::Int ? "%.0f" : "%.9g", v == 0.0f ? 0.0f : v);
    out += (out.empty() ? "" : ",") + std::string(buf);
  }
  return out;
}

UserUniforms find_user_uniforms(const Source& source, const std::string* given) {
  UserUniforms found;
  // Candidates first, from the text with its comments; then the preprocessor
  // says which lines are live (its output keeps the source's lines).
  struct Candidate {
    size_t line;  // 0-based line of source.text
    std::string_view text;
  };
  std::vector<Candidate> candidates;
  size_t line = 0;
  for (size_t at = 0; at < source.text.size(); ++line) {
    size_t end = source.text.find('\n', at);
    if (end == std::string::npos) end = source.text.size();
    const std::string_view text(source.text.data() + at, end - at);
    at = end + 1;
    if (line >= source.line_map.size() || source.line_map[line].file < 0) continue;  // the host's lines
    size_t p = 0;
    if (next_word(text, &p) == "uniform") candidates.push_back({line, text});
  }
  if (candidates.empty()) return found;
  std::vector<bool> live(source.line_map.size(), true);
  const auto active =
      given && !given->empty() ? std::optional<std::string>(*given) : active_code(source.text, source.version_line);
  if (active) {
    size_t l = 0;
    for (size_t at = 0; at <= active->size() && l < live.size(); ++l) {
      size_t end = active->find('\n', at);
      if (end == std::string::npos) end = active->size();
      live[l] = active->find_first_not_of(" \t\r", at) < end;
      at = end + 1;
    }
    if (l != live.size()) live.assign(live.size(), true);  // not line for line: trust the text
  }

  for (const Candidate& c : candidates) {
    if (!live[c.line]) continue;
    const std::string_view code = c.text.substr(0, c.text.find("//"));
    size_t p = 0;
    next_word(code, &p);  // "uniform"
    std::string_view type = next_word(code, &p);
    if (lexing::is_precision(type)) type = next_word(code, &p);
    const TypeName* t = nullptr;
    for (const TypeName& candidate : kTypes)
      if (type == candidate.glsl) t = &candidate;
    if (!t) continue;  // samplers are channels; matrices and the rest get no control
    auto [path, at_line] = source.locate(static_cast<int>(c.line) + 1);
    const size_t comment = c.text.find("//");
    std::string_view note = comment == std::string_view::npos ? "" : c.text.substr(comment + 2);
    note = note.substr(lexing::skip_blanks(note, 0));
    // Each name of the declaration ("uniform float a, b;").
    while (true) {
      const std::string_view name = next_word(code, &p);
      if (name.empty()) break;
      p = lexing::skip_blanks(code, p);
      const bool array = p < code.size() && code[p] == '[';
      while (p < code.size() && code[p] != ',' && code[p] != ';') ++p;
      const bool more = p < code.size() && code[p] == ',';
      ++p;
      if (host_supplies(name) || library_uniform(name) || found.find(std::string(name))) {
        if (!more) break;
        continue;
      }
      UserUniform u;
      u.name = std::string(name);
      u.type = t->type;
      u.components = *lexing::components_of(t->glsl);
      if (u.type == UserUniform::Type::Int) u.max = 10.0f, u.step = 1.0f;
      u.initial.assign(static_cast<size_t>(u.components), 0.0f);
      u.path = path;
      u.line = at_line;
      if (array) {
        Diagnostic d;
        d.severity = Severity::Warning;
        d.path = path;
        d.line = at_line;
        d.message = "uniform " + u.name + " is an array: it gets no control";
        found.warnings.push_back(std::move(d));
      } else {
        if (note.substr(0, 3) == "ui:") read_annotation(note.substr(3), &u, &found.warnings);
        found.uniforms.push_back(std::move(u));
      }
      if (!more) break;
    }
  }
  return found;
}

std::optional<std::vector<UniformValue>> uniform_values(const UserUniforms& uniforms,
                                                        const std::vector<std::string>& sets, std::string* error) {
  std::vector<UniformValue> out;
  for (const UserUniform& u : uniforms.uniforms)
    out.push_back({u.name, u.initial, uniform_value_text(u.type, u.initial)});
  for (const std::string& set : sets) {
    const size_t eq = set.find('=');
    const std::string name = set.substr(0, eq);
    const UserUniform* u = uniforms.find(name);
    if (eq == std::string::npos || !u) {
      std::string names;
      for (const UserUniform& known : uniforms.uniforms) names += (names.empty() ? "" : ", ") + known.name;
      *error = "'" + set + "': " +
               (eq == std::string::npos ? "not NAME=VALUE"
                                        : "the shader declares no uniform '" + name + "' of its own (" +
                                              (names.empty() ? std::string("it has none") : "it has " + names) + ")");
      return std::nullopt;
    }
    std::string why;
    auto value = parse_uniform_value(*u, set.substr(eq + 1), &why);
    if (!value) {
      *error = "'" + set + "': " + why;
      return std::nullopt;
    }
    for (UniformValue& v : out)
      if (v.name == name) v = {name, *value, uniform_value_text(u->type, *value)};
  }
  return out;
}

void merge_user_uniforms(UserUniforms* into, const UserUniforms& more) {
  for (const UserUniform& u : more.uniforms)
    if (!into->find(u.name)) into->uniforms.push_back(u);
  into->warnings.insert(into->warnings.end(), more.warnings.begin(), more.warnings.end());
}

}  // namespace rm
