#include "core/shadertoy_json.h"

#include <algorithm>
#include <memory>

#include <nlohmann/json.hpp>

#include "core/channel_spec.h"
#include "core/files.h"
#include "core/json_depth.h"
#include "core/json_errors.h"
#include "core/one_line.h"

namespace rm {

namespace {

using nlohmann::json;

// What a missing texture shows instead: value noise, drawn by a pass.
const char* const kStandInNoise = R"(// Stand-in for a texture that only shadertoy.com serves: value noise.
float rm_hash(vec2 p) { return fract(sin(dot(p, vec2(127.1, 311.7))) * 43758.5453); }
void mainImage(out vec4 c, in vec2 f) {
  vec2 cell = floor(f / 4.0);
  c = vec4(rm_hash(cell), rm_hash(cell + 17.0), rm_hash(cell + 31.0), 1.0);
}
)";

// What a missing cube map shows instead: a sky, drawn by a Cube A pass.
const char* const kStandInSky = R"(// Stand-in for a cube map that only shadertoy.com serves: a sky over grey ground.
void mainCubemap(out vec4 c, in vec2 f, in vec3 ro, in vec3 rd) {
  vec3 sky = mix(vec3(0.75, 0.85, 1.0), vec3(0.25, 0.45, 0.85), clamp(rd.y, 0.0, 1.0));
  vec3 sun = vec3(1.0, 0.9, 0.7) * pow(max(dot(rd, normalize(vec3(0.6, 0.5, -0.6))), 0.0), 64.0);
  c = vec4(rd.y > 0.0 ? sky + sun : vec3(0.35), 1.0);
}
)";

std::string text_of(const json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_unsigned()) return std::to_string(v.get<unsigned long long>());
  if (v.is_number_integer()) return std::to_string(v.get<long long>());
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  return "";
}

// The input's "channel", 0 to 3, or -1. Compared as JSON: get<int>() would
// wrap 2^32 to 0.
int channel_of(const json& input) {
  const auto it = input.find("channel");
  if (it == input.end() || !it->is_number_integer()) return -1;
  for (int channel = 0; channel < 4; ++channel)
    if (*it == channel) return channel;
  return -1;
}

// What stands in for media that is not in --media, by input type: a pass
// that draws something like it, or (no file) black. A new stand-in is a row.
struct StandIn {
  const char* ctype;
  const char* what;  // "value noise stands in for it"
  const char* file;
  const char* text;
};
const StandIn kStandIns[] = {
    {"texture", "value noise", "standin_noise.frag", kStandInNoise},
    {"cubemap", "a sky", "standin_sky.frag", kStandInSky},
    {"volume", nullptr, nullptr, nullptr},
};

const StandIn& stand_in_for(const std::string& ctype) {
  for (const StandIn& s : kStandIns)
    if (ctype == s.ctype) return s;
  return kStandIns[0];
}

// "Buffer A", "Buf A", "BufferA" -> 0; -1 for anything else.
int buffer_index_of_name(const std::string& name) {
  std::string letters;
  for (char c : name)
    if (c != ' ') letters += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const std::string prefix : {"buffer", "buf"})
    if (letters.size() == prefix.size() + 1 && letters.compare(0, prefix.size(), prefix) == 0 &&
        letters.back() >= 'a' && letters.back() <= 'd')
      return letters.back() - 'a';
  return -1;
}

constexpr const char* kCubeFile = "cube_a.frag";

std::string buffer_file(int index) { return std::string("buffer_") + static_cast<char>('a' + index) + ".frag"; }

// The input's sampler; a setting the export spells in a way Shadertoy does
// not is one warning, and the default stands.
Sampler sampler_of(const json& input, ChannelSpec::Kind kind, ChannelSpec::Shape shape, const std::string& where,
                   std::vector<std::string>* warnings) {
  Sampler s = default_sampler(kind, shape);
  if (!input.contains("sampler") || !input["sampler"].is_object()) return s;
  const json& j = input["sampler"];
  auto setting = [&](const char* key, const char* spellings, auto&& take) {
    if (!j.contains(key)) return;
    const std::string value = text_of(j[key]);
    if (!take(value))
      warnings->push_back(where + ": sampler " + key + " '" + brief(value.empty() ? j[key].dump() : value) +
                          "' is not " + spellings + "; the default is used");
  };
  setting("filter", "nearest, linear or mipmap", [&](const std::string& v) {
    if (v == "nearest") s.filter = Sampler::Filter::Nearest;
    else if (v == "linear") s.filter = Sampler::Filter::Linear;
    else if (v == "mipmap") s.filter = Sampler::Filter::Mipmap;
    else return false;
    return true;
  });
  setting("wrap", "clamp or repeat", [&](const std::string& v) {
    if (v == "clamp") s.wrap = Sampler::Wrap::Clamp;
    else if (v == "repeat") s.wrap = Sampler::Wrap::Repeat;
    else return false;
    return true;
  });
  setting("vflip", "true or false", [&](const std::string& v) {
    if (v != "true" && v != "false") return false;
    s.vflip = v == "true";
    return true;
  });
  return s;
}

// An error at the line and column of `byte` of the text.
Diagnostic error_at(const std::string& text, size_t byte, std::string message) {
  Diagnostic d;
  d.line = d.column = 1;
  for (size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++d.line;
      d.column = 1;
    } else {
      ++d.column;
    }
  }
  d.message = std::move(message);
  return d;
}

// A pass's "code": its text, "" when there is none (null, or no key), or
// nullopt with `error` saying so when it is something else: `"code": 42`
// read as the shader "42" failed as a scene with no mainImage. The place is
// the first "code" key whose value is not a string (the shaders' own quotes
// are escaped in theirs); with none found, the JSON file is named alone.
std::optional<std::string> code_of(const json& pass, const std::string& file, const std::string& text, Diagnostic* error) {
  const auto it = pass.find("code");
  if (it == pass.end() || it->is_null()) return "";
  if (it->is_string()) return it->get<std::string>();
  const char* what = it->is_number() ? "a number" : it->is_boolean() ? "true or false" : it->is_array() ? "a list" : "an object";
  const std::string message = file + "'s \"code\" is " + what + ", not the shader's text";
  for (size_t key = text.find("\"code\""); key != std::string::npos; key = text.find("\"code\"", key + 1)) {
    if (key > 0 && text[key - 1] == '\\') continue;
    const size_t colon = text.find_first_not_of(" \t\r\n", key + 6);
    if (colon == std::string::npos || text[colon] != ':') continue;
    const size_t value = text.find_first_not_of(" \t\r\n", colon + 1);
    if (value != std::string::npos && text[value] != '"') {
      *error = error_at(text, value, message);
      return std::nullopt;
    }
  }
  *error = Diagnostic{};
  error->message = message;
  return std::nullopt;
}

}  // namespace

bool is_media_stand_in(const std::filesystem::path& pass) {
  const std::string name = pass.filename().string();
  return std::any_of(std::begin(kStandIns), std::end(kStandIns),
                     [&](const StandIn& s) { return s.file && name == s.file; });
}

bool is_shadertoy_json(const std::filesystem::path& path) { return path.extension() == ".json"; }

std::optional<ShadertoyProject> read_shadertoy_json(const std::string& text, const std::filesystem::path& media_dir,
                                                    Diagnostic* error) {
  if (const auto deep = json_nested_too_deep(text)) {
    *error = Diagnostic{};
    error->line = deep->line;
    error->column = deep->column;
    error->message = deep->message;
    return std::nullopt;
  }
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    const std::string what = short_json_error(e.what());
    const size_t colon = what.find("syntax error");
    *error = error_at(text, e.byte > 0 ? e.byte - 1 : 0, colon == std::string::npos ? what : what.substr(colon));
    return std::nullopt;
  } catch (const json::out_of_range& e) {
    // A number past a double's range: "number overflow parsing '1e999'", which names no place.
    const std::string what = e.what();
    const size_t open = what.find('\''), close = what.rfind('\'');
    const std::string number = open < close ? what.substr(open + 1, close - open - 1) : "";
    *error = error_at(text, number.empty() ? 0 : text.find(number), "the number " + number + " is too large for a double");
    return std::nullopt;
  }
  // {"Shader": {...}}, the shader itself, or a list of shaders (the first).
  if (doc.is_array() && !doc.empty()) doc = doc[0];
  if (doc.is_object() && doc.contains("Shader")) doc = doc["Shader"];
  if (!doc.is_object() || !doc.contains("renderpass") || !doc["renderpass"].is_array()) {
    *error = error_at(text, 0, "not a Shadertoy shader: no \"renderpass\" list");
    return std::nullopt;
  }
  ShadertoyProject project;
  if (doc.contains("info") && doc["info"].is_object() && doc["info"].contains("name"))
    project.name = text_of(doc["info"]["name"]);

  // First: which output id is which buffer, and which pass is which file.
  std::map<std::string, int> buffer_of_output;
  std::vector<std::string> cube_outputs;  // the ids of Cube A's output
  struct PassText {
    std::string file;
    const json* pass;
  };
  std::vector<PassText> passes;
  project.files[ShadertoyProject::kCommon] = "";
  // Shadertoy has one pass of each; a second one (a JSON edited by hand) is
  // left out, so the first stands whatever the order of the rest.
  auto taken = [&](const std::string& file, const std::string& name) {
    const bool second = file == ShadertoyProject::kCommon
                            ? project.has_common
                            : std::any_of(passes.begin(), passes.end(), [&](const PassText& p) { return p.file == file; });
    if (second) project.warnings.push_back("pass '" + brief(name) + "' is a second " + file + "; it is left out");
    return second;
  };
  for (const json& pass : doc["renderpass"]) {
    if (!pass.is_object()) continue;
    const std::string type = pass.contains("type") ? text_of(pass["type"]) : "";
    const std::string name = pass.contains("name") ? text_of(pass["name"]) : "";
    if (type == "common") {
      if (taken(ShadertoyProject::kCommon, name)) continue;
      const auto code = code_of(pass, ShadertoyProject::kCommon, text, error);
      if (!code) return std::nullopt;
      project.files[ShadertoyProject::kCommon] = *code;
      project.has_common = true;
    } else if (type == "cubemap") {
      if (taken(kCubeFile, name)) continue;
      if (pass.contains("outputs") && pass["outputs"].is_array())
        for (const json& out : pass["outputs"])
          if (out.is_object() && out.contains("id")) cube_outputs.push_back(text_of(out["id"]));
      passes.push_back({kCubeFile, &pass});
    } else if (type == "image") {
      if (taken(ShadertoyProject::kImage, name)) continue;
      passes.push_back({ShadertoyProject::kImage, &pass});
    } else if (type == "buffer") {
      int index = buffer_index_of_name(name);
      if (index < 0 && pass.contains("outputs") && pass["outputs"].is_array() && !pass["outputs"].empty() &&
          pass["outputs"][0].is_object()) {
        const std::string id = text_of(pass["outputs"][0].value("id", json()));
        if (id >= "257" && id <= "260" && id.size() == 3) index = id[2] - '7';
      }
      if (index < 0) {
        project.warnings.push_back("buffer pass '" + name + "' is not Buffer A to D; it is left out");
        continue;
      }
      if (taken(buffer_file(index), name)) continue;
      // An id two buffers write (a JSON edited by hand) reads the first, as a second pass of a kind is left
      // out; one warning a pass, however many ids it shares.
      bool shared = false;
      if (pass.contains("outputs") && pass["outputs"].is_array())
        for (const json& out : pass["outputs"]) {
          if (!out.is_object() || !out.contains("id")) continue;
          const std::string id = text_of(out["id"]);
          const auto [first, fresh] = buffer_of_output.emplace(id, index);
          if (fresh || first->second == index || shared) continue;
          shared = true;
          project.warnings.push_back("buffer pass '" + brief(name) + "' writes output " + brief(id) + ", as " +
                                     buffer_file(first->second) + " does; an input of " + brief(id) + " reads " +
                                     buffer_file(first->second));
        }
      passes.push_back({buffer_file(index), &pass});
    } else {
      project.warnings.push_back("pass '" + name + "' of type '" + type + "' is not supported yet; it is left out");
    }
  }
  bool has_image = false;
  for (const PassText& p : passes) has_image = has_image || p.file == ShadertoyProject::kImage;
  if (!has_image) {
    *error = error_at(text, 0, "the shader has no image pass");
    return std::nullopt;
  }

  for (const PassText& p : passes) {
    auto code = code_of(*p.pass, p.file, text, error);
    if (!code) return std::nullopt;
    std::string pass_text = std::move(*code);
    if (!pass_text.empty() && pass_text.back() != '\n') pass_text += '\n';
    const json& inputs = p.pass->contains("inputs") ? (*p.pass)["inputs"] : json::array();
    for (const json& input : inputs) {
      if (!input.is_object()) continue;
      const int channel = channel_of(input);
      if (channel < 0) {
        const auto it = input.find("channel");
        project.warnings.push_back(p.file + (it == input.end() ? ": an input with no channel"
                                                              : ": an input on channel " + brief(it->dump()) + ", not 0 to 3") +
                                   "; it is left out");
        continue;
      }
      const std::string ctype = input.contains("ctype") ? text_of(input["ctype"]) : input.contains("type") ? text_of(input["type"]) : "";
      const std::string src = input.contains("src") ? text_of(input["src"]) : input.contains("filepath") ? text_of(input["filepath"]) : "";
      const std::string where = p.file + " iChannel" + std::to_string(channel);
      ChannelSpec spec;
      std::string file;
      bool stand_in = false;  // a pass standing in for media keeps the media's sampler
      if (ctype == "buffer") {
        int index = -1;
        if (auto it = buffer_of_output.find(text_of(input.value("id", json()))); it != buffer_of_output.end()) index = it->second;
        const size_t previz = src.find("buffer0");
        if (index < 0 && previz != std::string::npos && previz + 7 < src.size()) index = src[previz + 7] - '0';
        if (index < 0 || index > 3) {
          project.warnings.push_back(where + ": a buffer input that names no buffer; it reads black");
          spec.kind = ChannelSpec::Kind::Black;
        } else {
          spec.kind = ChannelSpec::Kind::Pass;
          file = buffer_file(index);
        }
      } else if (ctype == "cubemap" &&
                 (std::find(cube_outputs.begin(), cube_outputs.end(), text_of(input.value("id", json()))) !=
                      cube_outputs.end() ||
                  src.find("previz/cubemap") != std::string::npos)) {
        if (cube_outputs.empty()) {
          project.warnings.push_back(where + ": reads Cube A, which the JSON does not hold; it reads black");
          spec.kind = ChannelSpec::Kind::Black;
        } else {
          spec.kind = ChannelSpec::Kind::Pass;
          file = kCubeFile;
        }
        spec.shape = ChannelSpec::Shape::Cube;
      } else if (ctype == "keyboard") {
        spec.kind = ChannelSpec::Kind::Keyboard;
      } else if (ctype == "texture" || ctype == "cubemap" || ctype == "volume") {
        spec.kind = ChannelSpec::Kind::Image;
        spec.shape = ctype == "cubemap" ? ChannelSpec::Shape::Cube
                     : ctype == "volume" ? ChannelSpec::Shape::Volume : ChannelSpec::Shape::Flat;
        const std::string base = std::filesystem::path(src).filename().string();
        const std::filesystem::path local = media_dir.empty() || base.empty() ? std::filesystem::path() : media_dir / base;
        std::error_code ec;
        if (!local.empty() && std::filesystem::is_regular_file(local, ec)) {
          file = std::filesystem::absolute(local).lexically_normal().string();
        } else {
          const std::string missing = where + ": '" + src + "' is not in --media" +
                                      (media_dir.empty() ? "" : " '" + media_dir.string() + "'");
          const StandIn& instead = stand_in_for(ctype);
          if (!instead.file) {
            project.warnings.push_back(missing + "; it reads black");
            spec.kind = ChannelSpec::Kind::Black;
          } else {
            project.warnings.push_back(missing + "; " + instead.what + " stands in for it");
            spec.kind = ChannelSpec::Kind::Pass;
            stand_in = true;
            file = instead.file;
            project.files[file] = instead.text;
          }
        }
      } else {
        project.warnings.push_back(where + ": input type '" + ctype + "' is not supported; it reads black");
        spec.kind = ChannelSpec::Kind::Black;
      }
      spec.sampler = sampler_of(input, stand_in ? ChannelSpec::Kind::Image : spec.kind, spec.shape, where, &project.warnings);
      pass_text += "#pragma channel" + std::to_string(channel) + " " + channel_spec_text(spec, file) + "\n";
    }
    project.files[p.file] = pass_text;
  }
  return project;
}

std::map<std::string, std::string> ShadertoyProject::files_to_import() const {
  std::map<std::string, std::string> out;
  for (const auto& [name, text] : files) {
    if (name == kCommon) {
      if (has_common) out[name] = text;
    } else {
      out[name] = (has_common && is_shader_file(name) ? "#include \"common.glsl\"\n" : "") + text;
    }
  }
  return out;
}

Diagnostics ShadertoyProject::warnings_at(const std::filesystem::path& json) const {
  Diagnostics out;
  for (const std::string& warning : warnings) out.push_back(Diagnostic{Severity::Warning, json.string(), 0, 0, warning});
  return out;
}

std::optional<ShadertoyProject> read_shadertoy_file(const std::filesystem::path& json_path,
                                                    const std::filesystem::path& media_dir, std::string* error) {
  auto text = read_shader_file(json_path, error);
  if (!text) return std::nullopt;
  Diagnostic why;
  auto project = read_shadertoy_json(*text, media_dir, &why);
  why.path = json_path.string();
  if (!project) *error = why.place() + ": " + why.message;
  return project;
}

FileSystem shadertoy_file_system(const std::filesystem::path& json_path, const std::filesystem::path& media_dir) {
  const std::filesystem::path root = std::filesystem::absolute(json_path).lexically_normal();
  FileSystem disk = disk_file_system();
  auto inside = [root](const std::filesystem::path& path) {
    return std::filesystem::absolute(path).lexically_normal().parent_path() == root;
  };
  // The JSON parsed once per version of its text: a reload reads each pass
  // and checks each include, and all of them share one parse. Reading the
  // file again is cheap; comparing its text is exact where a time stamp
  // may not be.
  struct Parsed {
    std::string text;
    std::optional<ShadertoyProject> project;
    Diagnostic error;  // in the JSON, where it did not parse
  };
  auto cache = std::make_shared<Parsed>();
  auto project = [=]() -> const Parsed& {
    std::string error;
    std::optional<std::string> text = read_shader_file(root, &error);
    if (!text) {
      cache->text.clear();
      cache->project.reset();
      cache->error = scene_unreadable(root.string(), error);
    } else if (!cache->project || *text != cache->text) {
      cache->project = read_shadertoy_json(*text, media_dir, &cache->error);
      cache->text = std::move(*text);
    }
    cache->error.path = root.string();
    return *cache;
  };
  FileSystem files;
  files.read = [=](const std::filesystem::path& path, Diagnostic* why) -> std::optional<std::string> {
    if (!inside(path)) return disk.read(path, why);
    const Parsed& parsed = project();
    if (!parsed.project) {
      *why = parsed.error;
      return std::nullopt;
    }
    auto it = parsed.project->files.find(path.filename().string());
    if (it == parsed.project->files.end()) {
      why->message = "no such pass in the JSON";
      return std::nullopt;
    }
    return it->second;
  };
  files.exists = [=](const std::filesystem::path& path) {
    if (!inside(path)) return disk.exists(path);
    const Parsed& parsed = project();
    return parsed.project && parsed.project->files.count(path.filename().string()) > 0;
  };
  files.warnings = [=] {
    const Parsed& parsed = project();
    return parsed.project ? parsed.project->warnings_at(root) : Diagnostics{};
  };
  return files;
}

}  // namespace rm
