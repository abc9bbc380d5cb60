// Headless rendering through EGL: inputs reach the shader exactly, every kind
// of shader renders, failures keep the last good program, tiles match.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdio>
#include <cstdlib>

#include "core/capture.h"
#include "core/renderer.h"
#include "core/scene.h"
#include "egl_fixture.h"
#include "support.h"

namespace rm {
namespace {

using test::TempDir;
using test::write_file;

using test::read_pixels;
using test::run_binary;

class Gpu : public test::EglTest {
 protected:
  Image render(Scene& scene, glm::ivec2 size, FrameInputs in = {}) {
    in.resolution = glm::vec3(size, 1.0f);
    return renderer_.render_image(*scene.program(), in, channels_, size);
  }

  // The scene `name` in dir_ draws (0.25, 0.5, its pixel's x from 0 to 1) at 4x2.
  void expect_test_pattern(const char* name) {
    Scene scene(dir_ / name, {});
    ASSERT_EQ(scene.reload(), ReloadStatus::Swapped) << name << "\n" << join(scene.diagnostics());
    Image img = render(scene, {4, 2});
    EXPECT_FLOAT_EQ(img.pixel(0, 0)[0], 0.25f) << name;
    EXPECT_FLOAT_EQ(img.pixel(0, 0)[1], 0.5f) << name;
    EXPECT_FLOAT_EQ(img.pixel(3, 1)[2], 3.5f / 4.0f) << name;
  }

  Renderer renderer_;
  ChannelInputs channels_{};  // nothing bound
  TempDir dir_;
};

TEST_F(Gpu, InputsReachTheShaderExactly) {
  write_file(dir_ / "inputs.frag", R"(
void mainImage(out vec4 c, in vec2 f) {
  int x = int(f.x);
  if (x == 0) c = vec4(iResolution, 0.0);
  else if (x == 1) c = vec4(iTime, iTimeDelta, iFrameRate, float(iFrame));
  else if (x == 2) c = iMouse;
  else if (x == 3) c = iDate;
  else if (x == 4) c = vec4(iChannelResolution[0], iSampleRate);
  else c = texture(iChannel1, vec2(0.5));
}
)");
  const auto out = dir_ / "inputs.exr";
  test::Outcome r = run_binary("render " + (dir_ / "inputs.frag").string() + " -o " + out.string() +
              " --size 6x2 --time 1.5 --frame 7 --mouse 10,20,-3,-4 --date 2024-02-29T13:14:15.5");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto px = read_pixels(out);
  ASSERT_EQ(px.size(), 6u * 2 * 4);
  auto pixel = [&](int x) { return glm::vec4(px[x * 4], px[x * 4 + 1], px[x * 4 + 2], px[x * 4 + 3]); };
  EXPECT_EQ(pixel(0), glm::vec4(6, 2, 1, 0));
  EXPECT_EQ(pixel(1), glm::vec4(1.5f, 1.0f / 60.0f, 60.0f, 7.0f));
  EXPECT_EQ(pixel(2), glm::vec4(10, 20, -3, -4));
  EXPECT_EQ(pixel(3), glm::vec4(2024, 1, 29, 13 * 3600 + 14 * 60 + 15.5f));
  EXPECT_EQ(pixel(4), glm::vec4(0, 0, 0, 44100));  // unset channel: resolution 0
  EXPECT_EQ(pixel(5), glm::vec4(0, 0, 0, 0));      // unset channel: transparent black
}

TEST_F(Gpu, ChannelImageIsSampledRightSideUpWithItsResolution) {
  Image img{2, 2, {1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 1}};  // top row red, bottom row blue
  std::string error;
  ASSERT_TRUE(write_image(dir_ / "tex.png", img, {}, Overwrite::Replace, &error)) << error;
  write_file(dir_ / "ch.frag", R"(
void mainImage(out vec4 c, in vec2 f) {
  c = f.x < 1.0 ? vec4(iChannelResolution[0], 1.0)
                : texelFetch(iChannel0, ivec2(0, f.y < 1.0 ? 0 : 1), 0);
}
)");
  test::Outcome r = run_binary("render " + (dir_ / "ch.frag").string() + " -o " + (dir_ / "ch.exr").string() + " --size 2x2 --channel0 " +
              (dir_ / "tex.png").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto px = read_pixels(dir_ / "ch.exr");
  EXPECT_EQ(glm::vec3(px[0], px[1], px[2]), glm::vec3(2, 2, 1));
  EXPECT_EQ(glm::vec3(px[4], px[5], px[6]), glm::vec3(1, 0, 0));     // file row 0 (top): texel row 1
  EXPECT_EQ(glm::vec3(px[12], px[13], px[14]), glm::vec3(0, 0, 1));  // file row 1 (bottom): texel row 0
}

// glslViewer's names for the same: u_tex0 and u_tex0Resolution.
TEST_F(Gpu, GlslViewersTextureAndItsResolutionAreChannelZero) {
  Image img{3, 2, {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1}};
  std::string error;
  ASSERT_TRUE(write_image(dir_ / "tex.png", img, {}, Overwrite::Replace, &error)) << error;
  write_file(dir_ / "viewer.frag", "uniform sampler2D u_tex0;\nuniform vec2 u_tex0Resolution;\n"
                                   "void main() { gl_FragColor = gl_FragCoord.x < 1.0 ? vec4(u_tex0Resolution, 0.0, 1.0)\n"
                                   "                                   : texelFetch(u_tex0, ivec2(0), 0); }\n");
  test::Outcome r = run_binary("render " + (dir_ / "viewer.frag").string() + " -o " + (dir_ / "v.exr").string() +
                               " --size 2x1 --channel0 " + (dir_ / "tex.png").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto px = read_pixels(dir_ / "v.exr");
  EXPECT_EQ(glm::vec2(px[0], px[1]), glm::vec2(3, 2));
  EXPECT_EQ(glm::vec3(px[4], px[5], px[6]), glm::vec3(0, 0, 1));  // the file's bottom row
}

// A scene's #pragma channel0 is its default image; --channel0 still wins.
TEST_F(Gpu, SceneDefaultChannelIsUsedUnlessTheCommandLineGivesOne) {
  std::string error;
  std::filesystem::create_directories(dir_ / "textures");
  ASSERT_TRUE(write_image(dir_ / "textures/green.png", Image{1, 1, {0, 1, 0, 1}}, {}, Overwrite::Replace, &error));
  ASSERT_TRUE(write_image(dir_ / "red.png", Image{1, 1, {1, 0, 0, 1}}, {}, Overwrite::Replace, &error));
  write_file(dir_ / "ch.frag", "#pragma channel0 \"textures/green.png\"\n"
                               "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(0), 0); }\n");
  const std::string render = "render " + (dir_ / "ch.frag").string() + " --size 1x1 -o ";
  test::Outcome r = run_binary(render + (dir_ / "default.exr").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_pixels(dir_ / "default.exr")[1], 1.0f);
  r = run_binary(render + (dir_ / "given.exr").string() + " --channel0 " + (dir_ / "red.png").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_pixels(dir_ / "given.exr")[0], 1.0f);
  EXPECT_EQ(read_pixels(dir_ / "given.exr")[1], 0.0f);
}

TEST_F(Gpu, AllThreeKindsOfShaderRender) {
  write_file(dir_ / "toy.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.25, 0.5, f.x / iResolution.x, 1.0); }\n");
  write_file(dir_ / "full.frag",
             "#version 330 core\nuniform vec3 iResolution;\nout vec4 o;\n"
             "void main() { o = vec4(0.25, 0.5, gl_FragCoord.x / iResolution.x, 1.0); }\n");
  write_file(dir_ / "legacy.frag",
             "#ifdef GL_ES\nprecision mediump float;\n#endif\nuniform vec2 u_resolution;\nuniform float u_time;\n"
             "uniform sampler2D u_tex0;\n"
             "void main() { gl_FragColor = vec4(0.25, 0.5, gl_FragCoord.x / u_resolution.x, 1.0)"
             " + 0.0 * texture2D(u_tex0, vec2(u_time)); }\n");
  write_file(dir_ / "es.frag",
             "#version 300 es\nprecision highp float;\nuniform vec3 iResolution;\nout vec4 o;\n"
             "void main() { o = vec4(0.25, 0.5, gl_FragCoord.x / iResolution.x, 1.0); }\n");
  for (const char* name : {"toy.frag", "full.frag", "legacy.frag", "es.frag"}) expect_test_pattern(name);
}

// Names Shadertoy's and glslViewer's dialects allow and 4.50 core reserves
// (core/dialect_names.h) reach the driver renamed, and draw what they say.
TEST_F(Gpu, NamesTheOlderDialectsAllowDraw) {
  write_file(dir_ / "toy.frag",
             "void mainImage(out vec4 c, in vec2 f) {\n  vec4 buffer = vec4(0.25, 0.5, f.x / iResolution.x, 1.0);\n"
             "  float shared = 1.0, precise = 2.0;\n  c = buffer * shared * precise / 2.0;\n}\n");
  write_file(dir_ / "legacy.frag",
             "uniform vec2 u_resolution;\nvec4 sample(float smooth) { return vec4(0.25, 0.5, smooth, 1.0); }\n"
             "void main() {\n  float flat = gl_FragCoord.x / u_resolution.x, layout = 1.0;\n"
             "  gl_FragColor = sample(flat) * layout;\n}\n");
  // A sampler named `texture`, read by texture2D: nothing binds it, so it reads (0, 0, 0, 1).
  write_file(dir_ / "texture.frag",
             "uniform vec2 u_resolution;\nuniform sampler2D texture;\nvoid main() {\n"
             "  vec4 black = texture2D(texture, vec2(0.5));\n"
             "  gl_FragColor = vec4(0.25, 0.5, gl_FragCoord.x / u_resolution.x, 1.0) * black.a + vec4(black.rgb, 0.0);\n}\n");
  for (const char* name : {"toy.frag", "legacy.frag", "texture.frag"}) expect_test_pattern(name);
}

// The driver's refusal of too many uniform components names no line: the
// scene's largest uniform is the place.
TEST_F(Gpu, TooManyUniformComponentsNameTheLargestUniform) {
  write_file(dir_ / "big.frag", "uniform float gain;\nuniform vec4 table[100000];\n"
                                "void mainImage(out vec4 c, in vec2 f) { c = gain * table[int(f.x)]; }\n");
  Scene scene(dir_ / "big.frag", {});
  ASSERT_EQ(scene.reload(), ReloadStatus::Failed);
  // One error, though Mesa says it three ways; the driver's words (its limits) follow in parentheses.
  ASSERT_EQ(scene.diagnostics().size(), 1u) << join(scene.diagnostics());
  EXPECT_EQ(scene.diagnostics()[0].str().substr(0, scene.diagnostics()[0].str().find(" (")),
            (dir_ / "big.frag").string() +
                ":2:14: error: 'table' : its 400000 components take the fragment shader's uniforms past what the driver "
                "allows");
}

// WebGL 1 shaders open with #extension GL_OES_standard_derivatives; the
// driver takes it only before every declaration, the host's included.
TEST_F(Gpu, AnExtensionAtTheTopOfEveryKindOfShaderBuilds) {
  const std::string extension = "#extension GL_OES_standard_derivatives : enable\n";
  write_file(dir_ / "toy.frag", extension + "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.25, dFdx(f.x), 0.0, 1.0); }\n");
  write_file(dir_ / "legacy.frag", extension + "void main() { gl_FragColor = vec4(0.25, dFdx(gl_FragCoord.x), 0.0, 1.0); }\n");
  write_file(dir_ / "es.frag", "#version 300 es\n" + extension +
                                   "precision highp float;\nout vec4 o;\n"
                                   "void main() { o = vec4(0.25, dFdx(gl_FragCoord.x), 0.0, 1.0); }\n");
  for (const char* name : {"toy.frag", "legacy.frag", "es.frag"}) {
    Scene scene(dir_ / name, {});
    ASSERT_EQ(scene.reload(), ReloadStatus::Swapped) << name << "\n" << join(scene.diagnostics());
    Image img = render(scene, {4, 2});
    EXPECT_FLOAT_EQ(img.pixel(0, 0)[0], 0.25f) << name;
    EXPECT_FLOAT_EQ(img.pixel(0, 0)[1], 1.0f) << name;
  }
}

// glslViewer's v_texcoord is the pixel's place from 0 to 1, whole pictures,
// tiles and supersamples alike.
TEST_F(Gpu, GlslViewersTexcoordIsThePixelsPlace) {
  write_file(dir_ / "legacy.frag", "varying vec2 v_texcoord;\nvoid main() { gl_FragColor = vec4(v_texcoord, 0.0, 1.0); }\n");
  Scene scene(dir_ / "legacy.frag", {});
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped) << join(scene.diagnostics());
  FrameInputs in;
  in.resolution = glm::vec3(20.0f, 4.0f, 1.0f);
  const Image whole = renderer_.render_image(*scene.program(), in, channels_, {20, 4}, 1);
  EXPECT_FLOAT_EQ(whole.pixel(0, 0)[0], 0.5f / 20.0f);
  EXPECT_FLOAT_EQ(whole.pixel(19, 3)[0], 19.5f / 20.0f);
  EXPECT_FLOAT_EQ(whole.pixel(19, 0)[1], 3.5f / 4.0f) << "the first row is the top";
  Renderer small;
  small.limit_tile(8);
  EXPECT_EQ(small.render_image(*scene.program(), in, channels_, {20, 4}, 1).rgba, whole.rgba);
  const Image many = renderer_.render_image(*scene.program(), in, channels_, {20, 4}, 16);
  EXPECT_NEAR(many.pixel(7, 1)[0], 7.5f / 20.0f, 0.1f / 20.0f) << "samples spread over the pixel";
  EXPECT_NE(many.pixel(7, 1)[0], whole.pixel(7, 1)[0]) << "and move v_texcoord";
}

TEST_F(Gpu, BrokenReloadKeepsTheLastGoodProgram) {
  const auto path = dir_ / "scene.frag";
  write_file(path, "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.0, 1.0, 0.0, 1.0); }\n");
  Scene scene(path, {});
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped);
  write_file(path, "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(1.0, 0.0, 0.0, 1.0) +;\n}\n");
  EXPECT_EQ(scene.reload(), ReloadStatus::Failed);
  ASSERT_FALSE(scene.diagnostics().empty());
  EXPECT_EQ(scene.diagnostics()[0].line, 2);
  EXPECT_EQ(render(scene, {2, 2}).pixel(0, 0)[1], 1.0f);  // still green
  EXPECT_EQ(scene.generation(), 1);
  write_file(path, "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.0, 0.0, 1.0, 1.0); }\n");
  EXPECT_EQ(scene.reload(), ReloadStatus::Swapped);
  EXPECT_TRUE(scene.diagnostics().empty());
  EXPECT_EQ(render(scene, {2, 2}).pixel(0, 0)[2], 1.0f);
}

// The window reloads through Scene: a save that includes a FIFO or a device,
// grows past the size limit, nests too deep, expands a macro without end or
// holds more code than glslang can parse in its memory fails with its
// reason, and the last good picture stays.
TEST_F(Gpu, PathologicalSavesKeepTheLastGoodProgram) {
  const auto path = dir_ / "scene.frag";
  ASSERT_EQ(mkfifo((dir_ / "fifo.glsl").c_str(), 0644), 0);
  write_file(path, "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.0, 1.0, 0.0, 1.0); }\n");
  Scene scene(path, {});
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped);
  std::string sum = "x";
  for (int i = 0; i < 20000; ++i) sum += "+x";
  std::string bomb = "float x = 1.0;\n#define A0 x+x\n";
  for (int i = 1; i <= 25; ++i)
    bomb += "#define A" + std::to_string(i) + " A" + std::to_string(i - 1) + "+A" + std::to_string(i - 1) + "\n";
  const std::vector<std::pair<std::string, std::string>> saves = {
      {"#include \"fifo.glsl\"\n", "is a named pipe (FIFO)"},
      {"#include \"/dev/zero\"\n", "is a character device"},
      {std::string(16u << 20, ' ') + "\n", "over the 16 MiB limit"},
      {"float x = 1.0;\nfloat y = " + sum + ";\n", "levels deep"},
      {bomb + "float y = A25;\n", "a macro that expands without end?"},
      {test::many_lines_of_code(6u << 20), "this shader of 6.0 MiB in 2"},  // 2xxxxx lines; of its memory, or under ASan its time
  };
  for (const auto& [prefix, says] : saves) {
    write_file(path, prefix + "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0, 0.0, 0.0, 1.0); }\n");
    EXPECT_EQ(scene.reload(), ReloadStatus::Failed) << says;
    ASSERT_FALSE(scene.diagnostics().empty()) << says;
    EXPECT_NE(scene.diagnostics()[0].str().find(says), std::string::npos) << scene.diagnostics()[0].str();
    EXPECT_EQ(render(scene, {2, 2}).pixel(0, 0)[1], 1.0f) << says;  // still green
  }
  EXPECT_EQ(scene.generation(), 1);
}

TEST_F(Gpu, FailureOnlyTheDriverFindsKeepsTheLastGoodProgram) {
  const auto path = dir_ / "scene.frag";
  write_file(path, "#version 450 core\nout vec4 o;\nvoid main() { o = vec4(0.0, 1.0, 0.0, 1.0); }\n");
  Scene scene(path, {});
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped);
  // glslang checks one stage without linking; only the driver's link sees
  // that f() is declared but never defined.
  write_file(path, "#version 450 core\nout vec4 o;\nfloat f(float x);\nvoid main() { o = vec4(f(1.0)); }\n");
  ASSERT_EQ(scene.reload(), ReloadStatus::Failed);
  ASSERT_EQ(count_errors(scene.diagnostics()), 1) << join(scene.diagnostics());
  EXPECT_EQ(scene.diagnostics()[0].path, path.string());
  EXPECT_NE(scene.diagnostics()[0].message.find("f"), std::string::npos);
  EXPECT_EQ(render(scene, {2, 2}).pixel(0, 0)[1], 1.0f);
}

TEST_F(Gpu, UnchangedSourceIsNotRecompiled) {
  const auto path = dir_ / "scene.frag";
  write_file(path, "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
  Scene scene(path, {});
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped);
  write_file(path, "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
  EXPECT_EQ(scene.reload(), ReloadStatus::Unchanged);
  EXPECT_EQ(scene.generation(), 1);
}

// A save that changes only comments would compile to the program on screen:
// nothing is built, and the picture stays. A comment that ends in a
// backslash swallows the next line (the compiler splices them): a change.
// After a failed save, a comment-only edit of the good text is built, so
// that the errors go.
TEST_F(Gpu, ACommentOnlyEditIsNotRecompiled) {
  const auto path = dir_ / "scene.frag";
  write_file(path, "// one\nvoid mainImage(out vec4 c, in vec2 f) {\n  c = vec4(1.0);\n  c.g = 0.5;\n}\n");
  Scene scene(path, {});
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped);
  write_file(path, "// one, and more\nvoid mainImage(out vec4 c, in vec2 f) {\n  c = /* white */ vec4(1.0);\n"
                   "  c.g = 0.5;  // half\n}\n");
  EXPECT_EQ(scene.reload(), ReloadStatus::Unchanged);
  EXPECT_EQ(scene.times().validate, 0.0) << "no glslang";
  EXPECT_EQ(scene.times().driver, 0.0) << "no compile";
  EXPECT_EQ(scene.generation(), 1);
  // And back to the text on screen: no build either.
  write_file(path, "// one\nvoid mainImage(out vec4 c, in vec2 f) {\n  c = vec4(1.0);\n  c.g = 0.5;\n}\n");
  EXPECT_EQ(scene.reload(), ReloadStatus::Unchanged);
  EXPECT_EQ(scene.generation(), 1);

  write_file(path, "// one\nvoid mainImage(out vec4 c, in vec2 f) {\n  c = vec4(1.0);  // \\\n  c.g = 0.5;\n}\n");
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped);
  EXPECT_EQ(render(scene, {2, 2}).pixel(0, 0)[1], 1.0f) << "c.g = 0.5 is part of the comment";

  write_file(path, "// one\nvoid mainImage(out vec4 c, in vec2 f) { nope; }\n");
  ASSERT_EQ(scene.reload(), ReloadStatus::Failed);
  write_file(path, "// two\nvoid mainImage(out vec4 c, in vec2 f) {\n  c = vec4(1.0);  // \\\n  c.g = 0.5;\n}\n");
  EXPECT_EQ(scene.reload(), ReloadStatus::Swapped);
  EXPECT_EQ(count_errors(scene.diagnostics()), 0) << join(scene.diagnostics());
}

TEST_F(Gpu, TiledRenderEqualsOnePass) {
  write_file(dir_ / "t.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(f / iResolution.xy, fract(f.x * 0.37 + f.y * 0.11), 1.0); }\n");
  Scene scene(dir_ / "t.frag", {});
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped);
  Image whole = render(scene, {37, 23});
  renderer_.limit_tile(8);
  Image tiled = render(scene, {37, 23});
  EXPECT_EQ(whole.rgba, tiled.rgba);
}

// A pass is drawn under the logic op COPY (llvmpipe then generates its code
// once): it must write exactly what the shader writes into an 8-bit target,
// and leave no logic op behind, which would turn off the blending that
// supersamples and the interface draw with.
TEST_F(Gpu, APassWritesWhatTheShaderWritesAndLeavesNoLogicOpBehind) {
  write_file(dir_ / "grey.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.25, 0.4, 0.75, 1.0); }\n");
  Scene scene(dir_ / "grey.frag", {});
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped);
  const gl::Texture texture = gl::make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(texture.get(), 1, GL_RGBA8, 4, 4);
  const gl::Framebuffer target = gl::make_framebuffer();
  glNamedFramebufferTexture(target.get(), GL_COLOR_ATTACHMENT0, texture.get(), 0);
  const float red[4] = {1, 0, 0, 1};
  glClearNamedFramebufferfv(target.get(), GL_COLOR, 0, red);
  glBindFramebuffer(GL_FRAMEBUFFER, target.get());
  FrameInputs in;
  in.resolution = glm::vec3(4, 4, 1);
  renderer_.draw(*scene.program(), in, channels_, {4, 4});
  EXPECT_FALSE(glIsEnabled(GL_COLOR_LOGIC_OP));
  unsigned char px[4] = {0, 0, 0, 0};
  glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(px[0], 64);
  EXPECT_EQ(px[1], 102);
  EXPECT_EQ(px[2], 191);
  EXPECT_EQ(px[3], 255);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// A pixel the edge x = 10.3 cuts is covered 0.3: the mean of 16 samples
// comes near that in every kind of shader, drawn whole or in tiles, and one
// sample is the pixel centre alone.
TEST_F(Gpu, SupersamplesAverageWhatAPixelCoversInEveryKindOfShader) {
  write_file(dir_ / "toy.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(f.x < 10.3 ? 1.0 : 0.0); }\n");
  write_file(dir_ / "full.frag", "#version 330 core\nout vec4 o;\n"
                                 "void main() { o = vec4(gl_FragCoord.x < 10.3 ? 1.0 : 0.0); }\n");
  write_file(dir_ / "legacy.frag", "void main() { gl_FragColor = vec4(gl_FragCoord.x < 10.3 ? 1.0 : 0.0); }\n");
  for (const char* name : {"toy.frag", "full.frag", "legacy.frag"}) {
    Scene scene(dir_ / name, {});
    ASSERT_EQ(scene.reload(), ReloadStatus::Swapped) << name << "\n" << join(scene.diagnostics());
    const Image one = renderer_.render_image(*scene.program(), {}, channels_, {20, 4}, 1);
    EXPECT_EQ(one.pixel(10, 1)[0], 0.0f) << name;
    const Image many = renderer_.render_image(*scene.program(), {}, channels_, {20, 4}, 16);
    EXPECT_EQ(many.pixel(9, 1)[0], 1.0f) << name;
    EXPECT_NEAR(many.pixel(10, 1)[0], 0.3f, 0.05f) << name;
    EXPECT_EQ(many.pixel(11, 1)[0], 0.0f) << name;
    Renderer small;
    small.limit_tile(8);
    EXPECT_EQ(small.render_image(*scene.program(), {}, channels_, {20, 4}, 16).rgba, many.rgba) << name;
  }
}

TEST_F(Gpu, ErrorInsideAnIncludeIsReportedAtItsFileAndLine) {
  write_file(dir_ / "scene.frag", "#include \"lib/util.glsl\"\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(util()); }\n");
  write_file(dir_ / "lib/util.glsl", "// util\nfloat util() {\n  return 1.0 +;\n}\n");
  test::Outcome r = run_binary("render " + (dir_ / "scene.frag").string() + " -o " + (dir_ / "x.png").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err.rfind((dir_ / "lib/util.glsl").string() + ":3:", 0), 0u) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "x.png"));
}

TEST_F(Gpu, SequenceAdvancesTimeAndFrame) {
  write_file(dir_ / "s.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(iTime, float(iFrame), 0.0, 1.0); }\n");
  test::Outcome r = run_binary("render " + (dir_ / "s.frag").string() + " -o " + (dir_ / "f_%02d.exr").string() +
              " --size 2x2 --time 1 --frames 3 --fps 4");
  ASSERT_EQ(r.status, 0) << r.err;
  for (int i = 0; i < 3; ++i) {
    char name[16];
    std::snprintf(name, sizeof name, "f_%02d.exr", i);
    const auto px = read_pixels(dir_ / name);
    ASSERT_EQ(px.size(), 16u) << name;
    EXPECT_FLOAT_EQ(px[0], 1.0f + i * 0.25f);
    EXPECT_FLOAT_EQ(px[1], 4.0f + i);
  }
  EXPECT_FALSE(std::filesystem::exists(dir_ / "f_03.exr"));
}

TEST_F(Gpu, PngIsEightBitTopRowFirst) {
  write_file(dir_ / "p.frag", "void mainImage(out vec4 c, in vec2 f) { c = f.y > 1.0 ? vec4(1.0, 0.0, 0.0, 1.0) : vec4(2.0, -1.0, 1.0, 1.0); }\n");
  ASSERT_EQ(run_binary("render " + (dir_ / "p.frag").string() + " -o " + (dir_ / "p.png").string() + " --size 1x2").status, 0);
  const auto px = read_pixels(dir_ / "p.png");
  ASSERT_EQ(px.size(), 8u);
  EXPECT_EQ(glm::vec3(px[0], px[1], px[2]), glm::vec3(1, 0, 0));  // top row: y = 1.5
  EXPECT_EQ(glm::vec3(px[4], px[5], px[6]), glm::vec3(1, 0, 1));  // clamped
}

}  // namespace
}  // namespace rm
