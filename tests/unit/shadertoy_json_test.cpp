// Shadertoy's JSON export read into project files: pass names, sparse and
// unordered inputs, sampler settings, media, unknown types, malformed JSON.
#include <gtest/gtest.h>

#include "core/project.h"
#include "core/shadertoy_json.h"
#include "support.h"

namespace rm {
namespace {

// The error as "LINE:COL: why".
std::optional<ShadertoyProject> read(const std::string& text, std::string* error, const fs::path& media = {}) {
  Diagnostic why;
  auto project = read_shadertoy_json(text, media, &why);
  *error = std::to_string(why.line) + ":" + std::to_string(why.column) + ": " + why.message;
  return project;
}

const char* kProject = R"({"Shader": {
  "info": {"id": "x", "name": "Two buffers"},
  "renderpass": [
    {"type": "image", "name": "Image", "code": "void mainImage(out vec4 c, in vec2 f) { c = vec4(1); }",
     "inputs": [
       {"id": 258, "ctype": "buffer", "channel": 3, "sampler": {"filter": "mipmap", "wrap": "repeat", "vflip": "false"}},
       {"id": 257, "src": "/media/previz/buffer00.png", "ctype": "buffer", "channel": 1},
       {"id": 33, "ctype": "keyboard", "channel": 0}],
     "outputs": [{"id": 37, "channel": 0}]},
    {"type": "buffer", "name": "Buffer B", "code": "B", "inputs": [], "outputs": [{"id": 258, "channel": 0}]},
    {"type": "buffer", "name": "Buf A", "code": "A", "inputs": [], "outputs": [{"id": 257, "channel": 0}]},
    {"type": "common", "name": "Common", "code": "const float K = 1.0;"}
  ]}})";

TEST(ShadertoyJson, ReadsEveryPassAndInputInBothSpellings) {
  std::string error;
  auto p = read(kProject, &error);
  ASSERT_TRUE(p) << error;
  EXPECT_EQ(p->name, "Two buffers");
  EXPECT_TRUE(p->warnings.empty());
  ASSERT_EQ(p->files.size(), 4u);
  EXPECT_TRUE(p->has_common);
  EXPECT_EQ(p->files["common.glsl"], "const float K = 1.0;");
  EXPECT_EQ(p->files["buffer_a.frag"], "A\n");
  EXPECT_EQ(p->files["buffer_b.frag"], "B\n");
  // The code first, line for line (Common is a forced include); the inputs
  // as pragmas, only the settings that differ from the default.
  EXPECT_EQ(p->files["image.frag"],
            "void mainImage(out vec4 c, in vec2 f) { c = vec4(1); }\n"
            "#pragma channel3 \"buffer_b.frag\" filter=mipmap wrap=repeat vflip=false\n"
            "#pragma channel1 \"buffer_a.frag\"\n"
            "#pragma channel0 keyboard\n");
  // What import writes includes Common on each pass's first line.
  const auto files = p->files_to_import();
  EXPECT_EQ(files.at("buffer_a.frag"), "#include \"common.glsl\"\nA\n");
  EXPECT_EQ(files.at("common.glsl"), "const float K = 1.0;");
}

TEST(ShadertoyJson, AcceptsTheBareShaderAndAListOfShaders) {
  std::string error;
  const std::string bare = R"({"renderpass": [{"type": "image", "code": "x"}]})";
  auto p = read(bare, &error);
  ASSERT_TRUE(p) << error;
  EXPECT_EQ(p->files["image.frag"], "x\n");
  EXPECT_TRUE(read("[" + bare + "]", &error)) << error;
}

TEST(ShadertoyJson, MediaComeFromTheMediaDirectoryOrAStandIn) {
  test::TempDir media;
  test::write_file(media / "abc.png", "not read here");
  const std::string json = R"({"renderpass": [{"type": "image", "code": "x", "inputs": [
      {"ctype": "texture", "src": "/media/a/abc.png", "channel": 0},
      {"ctype": "texture", "src": "/media/a/missing.jpg", "channel": 2}]}]})";
  std::string error;
  auto p = read(json, &error, media.path());
  ASSERT_TRUE(p) << error;
  EXPECT_NE(p->files["image.frag"].find("#pragma channel0 \"" + (media / "abc.png").string() + "\"\n"), std::string::npos);
  EXPECT_NE(p->files["image.frag"].find("#pragma channel2 \"standin_noise.frag\" filter=mipmap wrap=repeat\n"),
            std::string::npos);
  EXPECT_EQ(p->files.count("standin_noise.frag"), 1u);
  ASSERT_EQ(p->warnings.size(), 1u);
  EXPECT_NE(p->warnings[0].find("'/media/a/missing.jpg' is not in --media"), std::string::npos) << p->warnings[0];
}

// Cube A is read through its output id (or Shadertoy's previz name) as a
// cube pass; cube map and volume media come from --media, and a missing
// cube map is a sky drawn by a stand-in cube pass.
TEST(ShadertoyJson, CubeAAndCubeMapAndVolumeInputs) {
  test::TempDir media;
  test::write_file(media / "lights.png", "not read here");
  test::write_file(media / "noise.bin", "not read here");
  const std::string json = R"({"renderpass": [
      {"type": "cubemap", "name": "Cube A", "code": "C", "outputs": [{"id": 41, "channel": 0}]},
      {"type": "image", "code": "x", "inputs": [
        {"id": 41, "ctype": "cubemap", "src": "/media/previz/cubemap00.png", "channel": 0},
        {"ctype": "cubemap", "src": "/media/a/lights.png", "channel": 1},
        {"ctype": "cubemap", "src": "/media/a/gone.png", "channel": 2},
        {"ctype": "volume", "src": "/media/a/noise.bin", "channel": 3}]}]})";
  std::string error;
  auto p = read(json, &error, media.path());
  ASSERT_TRUE(p) << error;
  EXPECT_EQ(p->files["cube_a.frag"], "C\n");
  EXPECT_EQ(p->files["image.frag"], "x\n#pragma channel0 \"cube_a.frag\" cube\n"
                                    "#pragma channel1 \"" + (media / "lights.png").string() + "\" cube\n"
                                    "#pragma channel2 \"standin_sky.frag\" cube filter=mipmap wrap=repeat\n"
                                    "#pragma channel3 \"" + (media / "noise.bin").string() + "\" volume\n");
  EXPECT_EQ(p->files.count("standin_sky.frag"), 1u);
  ASSERT_EQ(p->warnings.size(), 1u);
  EXPECT_NE(p->warnings[0].find("'/media/a/gone.png' is not in --media"), std::string::npos) << p->warnings[0];
  EXPECT_NE(p->warnings[0].find("a sky stands in for it"), std::string::npos) << p->warnings[0];
}

TEST(ShadertoyJson, UnknownPassAndInputTypesAreOneWarningEachAndTheRestRuns) {
  const std::string json = R"({"renderpass": [
      {"type": "sound", "name": "Sound", "code": "s"},
      {"type": "image", "code": "x", "inputs": [
        {"ctype": "webcam", "channel": 0}, {"ctype": "music", "channel": 1}, {"ctype": "video", "channel": 2}]}]})";
  std::string error;
  auto p = read(json, &error);
  ASSERT_TRUE(p) << error;
  // Each reads black on purpose, so the unbound-channel warning stays quiet.
  EXPECT_EQ(p->files["image.frag"], "x\n#pragma channel0 black\n#pragma channel1 black\n#pragma channel2 black\n");
  ASSERT_EQ(p->warnings.size(), 4u);
  EXPECT_NE(p->warnings[0].find("type 'sound' is not supported"), std::string::npos);
  EXPECT_NE(p->warnings[1].find("input type 'webcam' is not supported"), std::string::npos);
}

// Only channels 0 to 3 exist: a larger number, even one that a cast to int
// would wrap to 0 (2^32) or -1 (2^64 - 1), binds nothing, and says so.
TEST(ShadertoyJson, AChannelPastThreeBindsNothingWithAWarning) {
  const std::string json = R"({"renderpass": [{"type": "image", "code": "x", "inputs": [
      {"ctype": "keyboard", "channel": 4294967296}, {"ctype": "keyboard", "channel": 18446744073709551615},
      {"ctype": "keyboard", "channel": -4294967295}, {"ctype": "keyboard", "channel": 4},
      {"ctype": "keyboard", "channel": "1"}, {"ctype": "keyboard"},
      {"ctype": "keyboard", "channel": "0123456789012345678901234567890123456789 and more"},
      {"ctype": "keyboard", "channel": 2}]}]})";
  std::string error;
  auto p = read(json, &error);
  ASSERT_TRUE(p) << error;
  EXPECT_EQ(p->files["image.frag"], "x\n#pragma channel2 keyboard\n");
  EXPECT_EQ(p->warnings, (std::vector<std::string>{
                             "image.frag: an input on channel 4294967296, not 0 to 3; it is left out",
                             "image.frag: an input on channel 18446744073709551615, not 0 to 3; it is left out",
                             "image.frag: an input on channel -4294967295, not 0 to 3; it is left out",
                             "image.frag: an input on channel 4, not 0 to 3; it is left out",
                             "image.frag: an input on channel \"1\", not 0 to 3; it is left out",
                             "image.frag: an input with no channel; it is left out",
                             "image.frag: an input on channel \"012345678901234567890123456789012345678..., not 0 to 3; "
                             "it is left out",
                         }));
}

// Shadertoy has one pass of each kind; in a JSON edited by hand, the first
// of two stands and the second is one warning, whatever their order.
TEST(ShadertoyJson, ASecondPassOfOneKindIsLeftOutWithAWarning) {
  const std::string json = R"({"renderpass": [
      {"type": "buffer", "name": "Buffer A", "code": "A1", "outputs": [{"id": 257, "channel": 0}]},
      {"type": "image", "name": "Image", "code": "first",
       "inputs": [{"ctype": "buffer", "id": 257, "channel": 0}, {"ctype": "buffer", "id": 999, "channel": 1}]},
      {"type": "common", "name": "Common", "code": "C1"},
      {"type": "image", "name": "Image 2", "code": "second"},
      {"type": "buffer", "name": "Buf A", "code": "A2", "outputs": [{"id": 999, "channel": 0}]},
      {"type": "common", "name": "Common", "code": "C2"},
      {"type": "cubemap", "name": "Cube A", "code": "K1"},
      {"type": "cubemap", "name": "Cube A", "code": "K2"}]})";
  std::string error;
  auto p = read(json, &error);
  ASSERT_TRUE(p) << error;
  EXPECT_EQ(p->files["buffer_a.frag"], "A1\n");
  EXPECT_EQ(p->files["common.glsl"], "C1");
  EXPECT_EQ(p->files["cube_a.frag"], "K1\n");
  // The second Buffer A's output names no buffer: it was left out.
  EXPECT_EQ(p->files["image.frag"], "first\n#pragma channel0 \"buffer_a.frag\"\n#pragma channel1 black\n");
  EXPECT_EQ(p->warnings, (std::vector<std::string>{
                             "pass 'Image 2' is a second image.frag; it is left out",
                             "pass 'Buf A' is a second buffer_a.frag; it is left out",
                             "pass 'Common' is a second common.glsl; it is left out",
                             "pass 'Cube A' is a second cube_a.frag; it is left out",
                             "image.frag iChannel1: a buffer input that names no buffer; it reads black",
                         }));
}

// Two buffers that write one output id (a JSON edited by hand): an input of
// that id reads the first, and the second's claim is one warning, however
// often it lists the id (and an id it lists twice alone is no conflict).
TEST(ShadertoyJson, AnOutputIdTwoBuffersWriteReadsTheFirst) {
  const std::string json = R"({"renderpass": [
      {"type": "buffer", "name": "Buffer B", "code": "B", "outputs": [{"id": 258, "channel": 0}]},
      {"type": "buffer", "name": "Buffer A", "code": "A", "outputs": [{"id": 258, "channel": 0}, {"id": 257},
                                                                       {"id": 257}, {"id": 258}]},
      {"type": "image", "name": "Image", "code": "img", "inputs": [{"ctype": "buffer", "id": 258, "channel": 0}]}]})";
  std::string error;
  auto p = read(json, &error);
  ASSERT_TRUE(p) << error;
  EXPECT_EQ(p->files["buffer_a.frag"], "A\n");
  EXPECT_EQ(p->files["image.frag"], "img\n#pragma channel0 \"buffer_b.frag\"\n");
  EXPECT_EQ(p->warnings, (std::vector<std::string>{
                             "buffer pass 'Buffer A' writes output 258, as buffer_b.frag does; an input of 258 reads "
                             "buffer_b.frag",
                         }));
}

// A sampler setting Shadertoy does not spell so keeps the default, and says so.
TEST(ShadertoyJson, ASamplerSettingShadertoyDoesNotHaveIsAWarning) {
  const std::string json = R"({"renderpass": [{"type": "image", "code": "x", "inputs": [
      {"ctype": "keyboard", "channel": 0, "sampler": {"filter": "bogus", "wrap": "mirror", "vflip": null}},
      {"ctype": "keyboard", "channel": 1, "sampler": {"filter": "linear", "wrap": "repeat", "vflip": false,
                                                      "srgb": "false", "internal": "byte"}}]}]})";
  std::string error;
  auto p = read(json, &error);
  ASSERT_TRUE(p) << error;
  EXPECT_EQ(p->files["image.frag"], "x\n#pragma channel0 keyboard\n#pragma channel1 keyboard filter=linear wrap=repeat vflip=false\n");
  EXPECT_EQ(p->warnings, (std::vector<std::string>{
                             "image.frag iChannel0: sampler filter 'bogus' is not nearest, linear or mipmap; the default is used",
                             "image.frag iChannel0: sampler wrap 'mirror' is not clamp or repeat; the default is used",
                             "image.frag iChannel0: sampler vflip 'null' is not true or false; the default is used",
                         }));
}

TEST(ShadertoyJson, MalformedJsonNamesItsLineAndColumn) {
  std::string error;
  EXPECT_FALSE(read("{\"Shader\": {\n  \"renderpass\": [,]}}", &error));
  EXPECT_EQ(error.substr(0, 5), "2:18:") << error;  // the comma
  EXPECT_FALSE(read("{\"renderpass\": [{\"type\": \"buffer\", \"name\": \"Buf A\", \"code\": \"\"}]}", &error));
  EXPECT_EQ(error, "1:1: the shader has no image pass");
  EXPECT_FALSE(read("[1, 2]", &error));
  EXPECT_EQ(error, "1:1: not a Shadertoy shader: no \"renderpass\" list");
  // nlohmann throws out_of_range, not a parse error, for this one (found by json_fuzz: an abort).
  EXPECT_FALSE(read("{\"renderpass\": [],\n \"ver\": 5e55555}", &error));
  EXPECT_EQ(error, "2:9: the number 5e55555 is too large for a double");
  // Saved half-written inside a pass's code: the place, and the code's ends, not all of it.
  EXPECT_FALSE(read("{\"renderpass\": [{\"type\": \"image\", \"code\": \"void mainImage(" + std::string(5000, ' '),
                    &error));
  EXPECT_EQ(error,
            "1:5059: syntax error while parsing value - invalid string: missing closing quote; "
            "last read: '\"void mainImage(        ...                '");
}

// A pass's code that is not text is an error at the value: `"code": 42` was
// read as the shader "42", which failed as a scene with no mainImage. A
// string in a shader that reads `"code": 1` is the shader's, and null is no code.
TEST(ShadertoyJson, CodeThatIsNotTextIsAnErrorAtItsValue) {
  std::string error;
  EXPECT_FALSE(read(R"({"renderpass": [{"type": "image", "code": 42}]})", &error));
  EXPECT_EQ(error, "1:43: image.frag's \"code\" is a number, not the shader's text");
  EXPECT_FALSE(read("{\"renderpass\": [\n {\"type\": \"common\", \"code\": \"// \\\"code\\\": 1\"},\n"
                    " {\"type\": \"image\", \"code\" :\n  [\"void mainImage(out vec4 c, in vec2 f) {}\"]}]}",
                    &error));
  EXPECT_EQ(error, "4:3: image.frag's \"code\" is a list, not the shader's text");
  EXPECT_FALSE(read(R"({"renderpass": [{"type": "common", "code": {}}, {"type": "image", "code": ""}]})", &error));
  EXPECT_EQ(error, "1:44: common.glsl's \"code\" is an object, not the shader's text");
  auto p = read(R"({"renderpass": [{"type": "image", "code": null}]})", &error);
  ASSERT_TRUE(p) << error;
  EXPECT_EQ(p->files.at(ShadertoyProject::kImage), "");
}

// A JSON edited by hand may put anything where an object was: each such
// value is read as missing, never thrown out of the reader (a window saved
// with an output of null was ended by nlohmann's type_error).
TEST(ShadertoyJson, ANullWhereAnObjectWasIsReadAsMissing) {
  std::string error;
  const std::string image = R"({"type": "image", "code": "x", "inputs": [null, 3, {"channel": 0, "ctype": "buffer", "id": null}]})";
  for (const std::string outputs : {"[null]", "[3]", "[[]]", "null", "{}"}) {
    auto p = read(R"({"renderpass": [)" + image + R"(, {"type": "buffer", "name": "X", "outputs": )" + outputs + "}]}",
                  &error);
    ASSERT_TRUE(p) << outputs << ": " << error;
    EXPECT_EQ(p->warnings.front(), "buffer pass 'X' is not Buffer A to D; it is left out") << outputs;
  }
}

// A run from the JSON that is saved broken, or is gone, names the JSON at the
// place that did not parse, as a shader's error names its line: the pass's
// file (PROJECT.json/image.frag) exists only inside the JSON.
TEST(ShadertoyJson, AnEditThatDoesNotParseIsAnErrorAtTheJsonsLine) {
  test::TempDir dir;
  const fs::path json = dir.path() / "p.json";
  test::write_file(json, R"({"renderpass": [{"type": "image", "code": "void mainImage(out vec4 c, in vec2 f) { c = vec4(1); }"}]})");
  const FileSystem files = shadertoy_file_system(json, {});
  const fs::path image = json / ShadertoyProject::kImage;
  EXPECT_TRUE(preprocess(image, {}, files).ok());

  test::write_file(json, "{\"renderpass\": [\n  {\"type\": \"image\",, }]}");
  Source broken = preprocess(image, {}, files);
  ASSERT_EQ(broken.errors.size(), 1u);
  EXPECT_EQ(broken.errors[0].place(), json.string() + ":2:20") << broken.errors[0].str();
  EXPECT_EQ(broken.errors[0].message.rfind("syntax error", 0), 0u) << broken.errors[0].str();

  fs::remove(json);
  broken = preprocess(image, {}, files);
  ASSERT_EQ(broken.errors.size(), 1u);
  EXPECT_EQ(broken.errors[0].str(), json.string() + ": error: cannot read scene: no such file");
}

// A JSON's warnings (a stand-in, a left-out input) are diagnostics at the
// JSON of each build, read anew as the JSON is saved: `check`, `render` and
// the window say them through the one path, once each.
TEST(ShadertoyJson, WarningsComeWithEachBuildAtTheJson) {
  test::TempDir dir;
  const fs::path json = dir.path() / "p.json";
  const std::string image = R"({"type": "image", "code": "void mainImage(out vec4 c, in vec2 f) { c = vec4(1); }")";
  test::write_file(json, "{\"renderpass\": [" + image + R"(, "inputs": [{"ctype": "webcam", "channel": 0}]}]})");
  const ProjectFiles files = project_files(json);
  Diagnostics diags;
  check_project(files, {}, &diags);
  ASSERT_EQ(diags.size(), 1u);
  EXPECT_EQ(diags[0].str(), json.string() + ": warning: image.frag iChannel0: input type 'webcam' is not supported; it reads black");

  test::write_file(json, "{\"renderpass\": [" + image + "}]}");
  diags.clear();
  check_project(files, {}, &diags);
  EXPECT_TRUE(diags.empty()) << join(diags);

  test::write_file(json, "{\"renderpass\": [" + image + R"(, "inputs": [{"ctype": "webcam", "channel": 0}]},)");
  diags.clear();
  check_project(files, {}, &diags);
  ASSERT_EQ(diags.size(), 1u) << join(diags);
  EXPECT_EQ(diags[0].severity, Severity::Error) << "a JSON that does not parse has no warnings, only its error";
}

// A million '[' parsed, and the value copied, overflowed the stack (a crash).
TEST(ShadertoyJson, NestingTooDeepIsAnErrorNotACrash) {
  const size_t levels = 1000000;
  std::string error;
  EXPECT_FALSE(read(std::string(levels, '[') + std::string(levels, ']'), &error));
  EXPECT_EQ(error, "1:65: arrays and objects nested deeper than 64 levels");
}

}  // namespace
}  // namespace rm
