// The program as a user runs it: exit status 0/1/2 and one clear line on
// stderr that names the problem and the path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "support.h"

namespace rm {
namespace {

using test::TempDir;
using test::write_file;

class Cli : public ::testing::Test {
 protected:
  static test::Outcome run(const std::string& args) { return test::run_binary(args); }
  std::string good() {
    write_file(dir_ / "good.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
    return (dir_ / "good.frag").string();
  }
  // A shaderlib scene (a ball on a floor, seen from above the floor) whose
  // first line is `first_line`, written to NAME; returns its path.
  std::string ball_on_floor(const std::string& name, const std::string& first_line) {
    write_file(dir_ / name, first_line + "\n#include <rm/sdf.glsl>\n#include <rm/render.glsl>\n"
                            "float map(vec3 p) { return min(sdSphere(p, 1.0), p.y + 1.0); }\n"
                            "RmMaterial material(vec3 p, vec3 n) { return rmMaterial(vec3(0.8)); }\n"
                            "void mainImage(out vec4 c, in vec2 f) {\n"
                            "  RmCamera cam = rmLookAt(vec3(0.0, 1.0, 5.0), vec3(0.0), 0.8);\n"
                            "  c = vec4(rmRenderPixel(cam, f, iResolution), 1.0);\n}\n");
    return (dir_ / name).string();
  }
  static int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }
  // The red of pixel (0, 0) of `scene` drawn at 2x2 with `options`, into red.exr.
  float red_of(const std::string& scene, const std::string& options) {
    const test::Outcome r = run("render " + scene + " -o " + (dir_ / "red.exr").string() + " --size 2x2" + options);
    EXPECT_EQ(r.status, 0) << r.err;
    return test::read_pixels(dir_ / "red.exr").at(0);
  }
  static std::string command_of(const std::filesystem::path& picture) {
    return OIIO::ImageInput::open(picture.string())->spec().get_string_attribute("ImageDescription");
  }
  TempDir dir_;
};

TEST_F(Cli, HelpAndVersionExitZero) {
  EXPECT_EQ(run("--help").status, 0);
  EXPECT_EQ(run("--version").status, 0);
  EXPECT_EQ(run("render --help").status, 0);
}

// OpenImageIO and the 240 libraries under it cost a process 0.4 s to load:
// only what reads or writes a picture loads them (core/image_codecs.h). The
// dynamic loader's own log (LD_DEBUG=files) names every library it loads.
TEST_F(Cli, OnlyWhatReadsOrWritesAPictureLoadsOpenImageIO) {
  const auto loads_oiio = [&](const std::string& args) {
    const test::Outcome r = test::run_binary(args, "LD_DEBUG=files ");
    EXPECT_EQ(r.status, 0) << args << '\n' << r.err.substr(r.err.size() - std::min<size_t>(r.err.size(), 2000));
    EXPECT_NE(r.err.find("file=libc.so"), std::string::npos) << "no loader log for " << args;
    return r.err.find("file=libOpenImageIO.so") != std::string::npos;
  };
  EXPECT_FALSE(loads_oiio("--version"));
  EXPECT_FALSE(loads_oiio("check " + good()));
  EXPECT_FALSE(loads_oiio("render " + good() + " --size 4x4 -o " + (dir_ / "clip.mp4").string() + " --frames 2"));
  EXPECT_TRUE(loads_oiio("render " + good() + " --size 4x4 -o " + (dir_ / "still.png").string()));
  EXPECT_TRUE(std::filesystem::exists(dir_ / "still.png"));
}

// Each command's help shows what that command takes: the window's keys
// only in the window's (the default command's) help.
TEST_F(Cli, EachHelpShowsItsOwnCommand) {
  auto help = [&](const std::string& args) {
    const std::string out = (dir_ / "help.txt").string();
    EXPECT_EQ(std::system((std::string(RM_BINARY) + " " + args + " > " + out).c_str()), 0);
    return test::read_file(out);
  };
  EXPECT_NE(help("--help").find("left drag"), std::string::npos);
  for (const char* command : {"render", "check", "accuracy", "import"}) {
    const std::string text = help(std::string(command) + " --help");
    EXPECT_EQ(text.find("left drag"), std::string::npos) << command << "\n" << text;
    EXPECT_NE(text.find("exit status: 0 ok"), std::string::npos) << command << "\n" << text;
  }
}

// A channel the code reads with nothing bound is one warning at the first
// line that reads it (at the read, not at a comment before it); a --channelN file or `#pragma channelN black` binds it.
TEST_F(Cli, ReadingAnUnboundChannelIsOneWarningAtItsLine) {
  write_file(dir_ / "u.frag", "void mainImage(out vec4 c, in vec2 f) {\n  // iChannel2 in a comment is no read\n"
                              "  c = /* iChannel1 */ texture(iChannel1, f) + texture(iChannel1, f);\n}\n");
  const std::string scene = (dir_ / "u.frag").string();
  test::Outcome r = run("check " + scene);
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.err, scene + ":3:31: warning: iChannel1 is read but nothing is bound to it, so it reads transparent "
                           "black (#pragma channel1 \"FILE\" names an input)\n");
  r = run("render " + scene + " -o " + (dir_ / "o.png").string() + " --size 4x4 --channel1 " +
          std::string(RM_TEST_DATA_DIR) + "/../../examples/textures/phone_screen.png");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  write_file(dir_ / "u.frag", "#pragma channel1 black\n"
                              "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel1, f); }\n");
  r = run("check " + scene);
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.err, "");
}

// Only a read the compiler sees warns: not one in an #if branch it drops; a
// read through a macro does, at the line that uses it. `check` and
// `render` (the window's path) say the same.
TEST_F(Cli, OnlyAReadTheCompilerSeesWarnsOfAnUnboundChannel) {
  write_file(dir_ / "if.frag", "#define TEX iChannel2\nuniform sampler2D myTex;\n"
                               "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(0.0);\n#ifdef FANCY\n"
                               "  c = texture(iChannel1, f) + texture(myTex, f);\n#endif\n#if 0\n"
                               "  c += texture(iChannel0, f);\n#endif\n  c += /* TEX */ texture(TEX, f);\n}\n");
  const std::string scene = (dir_ / "if.frag").string();
  const std::string unbound = " is read but nothing is bound to it, so it reads transparent black (#pragma channel";
  const std::string macro = scene + ":11:26: warning: iChannel2" + unbound + "2 \"FILE\" names an input)\n";
  for (const std::string& command : {"check " + scene, "render " + scene + " --size 4x4 -o " + (dir_ / "if.png").string()}) {
    test::Outcome r = run(command);
    EXPECT_EQ(r.status, 0) << command << '\n' << r.err;
    EXPECT_EQ(r.err, macro) << command;
    r = run(command + " -D FANCY");
    EXPECT_EQ(r.status, 0) << command << '\n' << r.err;
    EXPECT_EQ(r.err, scene + ":6:15: warning: iChannel1" + unbound + "1 \"FILE\" names an input)\n" + macro + scene +
                         ":2:19: warning: 'myTex' is read, but the host binds nothing to it, so it reads black (it "
                         "binds iChannel0-3 and u_tex0-3, to what #pragma channelN \"FILE\" names)\n")
        << command;
  }
}

// A sampler the code declares and reads that no channel binds (glslViewer's
// scene pass, in a shader with no POSTPROCESSING pass to read it, or a name
// of its own)
// is one warning at its declaration, and reads black, not iChannel0's
// texture, which every sampler read by default. A sampler declared and not
// read says nothing.
TEST_F(Cli, ASamplerNoChannelBindsIsAWarningAndReadsBlack) {
  write_file(dir_ / "gv.frag",
             "#ifdef GL_ES\nprecision mediump float;\n#endif\n"
             "uniform highp sampler2D u_scene;\nuniform sampler2D myTex;\nuniform sampler2D unused;\n"
             "uniform sampler2D u_tex0;\nuniform sampler2D u_tex1;\nuniform vec2 u_resolution;\n"
             "void main() {\n  vec2 st = gl_FragCoord.xy / u_resolution;\n"
             "  gl_FragColor = texture2D(u_scene, st) + texture2D(myTex, st) + 0.25 * texture2D(u_tex0, st)\n"
             "               + texture2D(u_tex1, st);\n}\n");
  const std::string scene = (dir_ / "gv.frag").string();
  auto image = OIIO::ImageOutput::create("white.png");
  const std::vector<unsigned char> white(4 * 4 * 3, 255);
  ASSERT_TRUE(image && image->open((dir_ / "white.png").string(), OIIO::ImageSpec(4, 4, 3, OIIO::TypeDesc::UINT8)));
  image->write_image(OIIO::TypeDesc::UINT8, white.data());
  image->close();
  const test::Outcome r = run("check " + scene);
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.err,
            scene + ":4:25: warning: 'u_scene' is read, but it is glslViewer's scene pass, which only a "
                    "POSTPROCESSING pass reads (#ifdef POSTPROCESSING), so it reads black\n" +
                scene +
                ":5:19: warning: 'myTex' is read, but the host binds nothing to it, so it reads black (it binds "
                "iChannel0-3 and u_tex0-3, to what #pragma channelN \"FILE\" names)\n" +
                scene + ":7:19: warning: u_tex0 is read but nothing is bound to it, so it reads transparent black "
                        "(#pragma channel0 \"FILE\" names an input)\n" +
                scene + ":8:19: warning: u_tex1 is read but nothing is bound to it, so it reads transparent black "
                        "(#pragma channel1 \"FILE\" names an input)\n");
  // With white on channel 0, only u_tex0's quarter shows.
  EXPECT_NEAR(red_of(scene, " --channel0 " + (dir_ / "white.png").string()), 0.25f, 0.01f);
}

// glslViewer's buffers, from one file: u_buffer0 reads what the file draws
// with BUFFER_0 defined, this frame; u_doubleBuffer0 what it draws with
// DOUBLE_BUFFER_0, which reads its own previous frame. Each is a pass of the
// graph, on a channel the code leaves free (u_tex0 keeps channel 0, and
// --channel0 binds it; --channel3 does not replace u_buffer0 there), and a
// problem in code two buffers compile names its line once.
TEST_F(Cli, GlslViewerBuffersAreDrawnAsPassesOfTheirOwn) {
  const std::string code =
      "uniform sampler2D u_buffer0;\nuniform sampler2D u_doubleBuffer0;\nuniform sampler2D u_tex0;\n"
      "uniform vec2 u_resolution;\n"
      "void main() {\n"
      "#if defined(BUFFER_0)\n"
      "  gl_FragColor = vec4(0.5, 0.25, 0.0, 1.0);\n"
      "#elif defined(DOUBLE_BUFFER_0)\n"
      "  gl_FragColor = texture2D(u_doubleBuffer0, gl_FragCoord.xy / u_resolution) + vec4(0.125);\n"
      "#else\n"
      "  vec2 st = gl_FragCoord.xy / u_resolution;\n"
      "  gl_FragColor = vec4(texture2D(u_buffer0, st).rg, texture2D(u_doubleBuffer0, st).r,\n"
      "                      texture2D(u_tex0, st).r);\n"
      "#endif\n}\n";
  write_file(dir_ / "buffers.frag", code);
  const std::string scene = (dir_ / "buffers.frag").string();
  EXPECT_EQ(run("check " + scene).err,
            scene + ":3:19: warning: u_tex0 is read but nothing is bound to it, so it reads transparent black "
                    "(#pragma channel0 \"FILE\" names an input)\n");
  auto image = OIIO::ImageOutput::create("white.png");
  const std::vector<unsigned char> white(4 * 4 * 3, 255);
  ASSERT_TRUE(image && image->open((dir_ / "white.png").string(), OIIO::ImageSpec(4, 4, 3, OIIO::TypeDesc::UINT8)));
  image->write_image(OIIO::TypeDesc::UINT8, white.data());
  image->close();
  for (int frame : {0, 3}) {
    const test::Outcome r = run("render " + scene + " -o " + (dir_ / "b.exr").string() + " --size 4x4 --frame " +
                                std::to_string(frame) + " --channel0 " + (dir_ / "white.png").string() +
                                " --channel3 " + (dir_ / "white.png").string());  // u_buffer0's channel: kept
    ASSERT_EQ(r.status, 0) << r.err;
    const std::vector<float> px = test::read_pixels(dir_ / "b.exr");
    ASSERT_EQ(px.size(), 64u);
    for (size_t i = 0; i < px.size(); i += 4) {
      EXPECT_FLOAT_EQ(px[i], 0.5f) << frame;
      EXPECT_FLOAT_EQ(px[i + 1], 0.25f) << frame;
      EXPECT_FLOAT_EQ(px[i + 2], 0.125f * static_cast<float>(frame + 1)) << frame;  // frames 0..frame drawn
      EXPECT_FLOAT_EQ(px[i + 3], 1.0f) << frame;
    }
  }
  // An error in code that both buffers compile, and the image does not, is
  // said once, at its line.
  std::string broken = code;
  broken.insert(broken.find("void main()"),
                "#if defined(BUFFER_0) || defined(DOUBLE_BUFFER_0)\nvec4 shared() { return vec3(0.5); }\n#endif\n");
  write_file(dir_ / "buffers.frag", broken);
  const test::Outcome r = run("check " + scene);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, scene + ":3:19: warning: u_tex0 is read but nothing is bound to it, so it reads transparent "
                           "black (#pragma channel0 \"FILE\" names an input)\n" +
                       scene + ":6:17: error: 'return' : cannot convert return value to function return type\n");
}

// glslViewer draws its buffers in the order of their numbers: BUFFER_10
// reads BUFFER_2 of this frame (it would read 0 of the frame before).
TEST_F(Cli, GlslViewerBuffersDrawInTheOrderOfTheirNumbers) {
  write_file(dir_ / "order.frag",
             "uniform sampler2D u_buffer2;\nuniform sampler2D u_buffer10;\nvoid main() {\n#if defined(BUFFER_2)\n"
             "  gl_FragColor = vec4(0.5);\n#elif defined(BUFFER_10)\n"
             "  gl_FragColor = texture2D(u_buffer2, vec2(0.5)) + 0.25;\n#else\n"
             "  gl_FragColor = texture2D(u_buffer10, vec2(0.5));\n#endif\n}\n");
  EXPECT_FLOAT_EQ(red_of((dir_ / "order.frag").string(), ""), 0.75f);
}

// A buffer of a size of its own: glslViewer's comment after the
// declaration (`// 2x1` fixed, `// 0.5` half the picture's) or a pragma's
// size=WxH. The buffer pass draws at that size, its u_resolution and
// iResolution are that size, and its readers' textureSize and
// iChannelResolution say so. Two readers that give two sizes are an error.
TEST_F(Cli, ABufferDrawsAtASizeOfItsOwn) {
  write_file(dir_ / "sized.frag",
             "uniform sampler2D u_buffer0; // 2x1\nuniform sampler2D u_buffer1; // 0.5\n"
             "uniform vec2 u_resolution;\nvoid main() {\n#if defined(BUFFER_0)\n"
             "  gl_FragColor = gl_FragCoord.x < 1.0 ? vec4(1.0, 0.0, 0.0, 1.0) : vec4(0.0, 1.0, 0.0, 1.0);\n"
             "#elif defined(BUFFER_1)\n  gl_FragColor = vec4(u_resolution / 255.0, 0.0, 1.0);\n#else\n"
             "  vec2 st = gl_FragCoord.xy / u_resolution;\n"
             "  gl_FragColor = gl_FragCoord.y < 45.0 ? texture2D(u_buffer0, st)\n"
             "      : vec4(vec2(textureSize(u_buffer1, 0)) / 255.0, texture2D(u_buffer1, st).g, 1.0);\n#endif\n}\n");
  test::Outcome r = run("render " + (dir_ / "sized.frag").string() + " -o " + (dir_ / "s.exr").string() + " --size 160x90");
  ASSERT_EQ(r.status, 0) << r.err;
  std::vector<float> px = test::read_pixels(dir_ / "s.exr");
  ASSERT_EQ(px.size(), 160u * 90u * 4u);
  auto at = [&](int x, int y) {  // y up, as gl_FragCoord
    const size_t i = (static_cast<size_t>(89 - y) * 160 + static_cast<size_t>(x)) * 4;
    return std::vector<float>(px.begin() + static_cast<long>(i), px.begin() + static_cast<long>(i) + 3);
  };
  EXPECT_EQ(at(10, 10), (std::vector<float>{1.0f, 0.0f, 0.0f})) << "the 2x1 buffer's left texel, stretched";
  EXPECT_EQ(at(150, 10), (std::vector<float>{0.0f, 1.0f, 0.0f})) << "its right one";
  EXPECT_EQ(at(80, 80), (std::vector<float>{80.0f / 255.0f, 45.0f / 255.0f, 45.0f / 255.0f}));

  write_file(dir_ / "buffer.frag", "#pragma channel0 self size=3x2\n"
                                   "void mainImage(out vec4 c, in vec2 f) {\n"
                                   "  c = vec4(iResolution.xy, iChannelResolution[0].xy) / 255.0;\n}\n");
  write_file(dir_ / "image.frag", "#pragma channel0 \"buffer.frag\"\n"
                                  "void mainImage(out vec4 c, in vec2 f) {\n"
                                  "  c = texelFetch(iChannel0, ivec2(2, 1), 0) + vec4(0.0, 0.0, 0.0, iChannelResolution[0].x);\n}\n");
  r = run("render " + (dir_ / "image.frag").string() + " -o " + (dir_ / "i.exr").string() + " --size 8x8");
  ASSERT_EQ(r.status, 0) << r.err;
  px = test::read_pixels(dir_ / "i.exr");
  ASSERT_EQ(px.size(), 8u * 8u * 4u);
  EXPECT_EQ(std::vector<float>(px.begin(), px.begin() + 4),
            (std::vector<float>{3.0f / 255.0f, 2.0f / 255.0f, 3.0f / 255.0f, 2.0f / 255.0f + 3.0f}));

  write_file(dir_ / "image.frag", "#pragma channel0 \"buffer.frag\" scale=0.5\n"
                                  "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, f); }\n");
  r = run("check " + (dir_ / "image.frag").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, (dir_ / "buffer.frag").string() +
                       ": error: 'buffer.frag' is read here with size=3x2 and elsewhere with scale=0.5: a buffer has "
                       "one size\n");
}

// A glslViewer shader with a POSTPROCESSING branch is drawn so on screen,
// and its u_scene reads the scene pass (the file with no define) of this
// frame, which may read a buffer of its own.
TEST_F(Cli, AGlslViewerPostprocessingPassDrawsOverItsScene) {
  write_file(dir_ / "post.frag",
             "uniform sampler2D u_scene;\nuniform sampler2D u_buffer0;\nuniform vec2 u_resolution;\n"
             "void main() {\n  vec2 st = gl_FragCoord.xy / u_resolution;\n#ifdef BUFFER_0\n"
             "  gl_FragColor = vec4(0.5);\n#elif defined(POSTPROCESSING)\n"
             "  gl_FragColor = vec4(1.0 - texture2D(u_scene, st).rgb, 1.0);\n#else\n"
             "  gl_FragColor = vec4(0.25, texture2D(u_buffer0, st).r, 0.0, 1.0);\n#endif\n}\n");
  const std::string scene = (dir_ / "post.frag").string();
  const test::Outcome r = run("render " + scene + " -o " + (dir_ / "p.exr").string() + " --size 4x4");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::vector<float> px = test::read_pixels(dir_ / "p.exr");
  ASSERT_EQ(px.size(), 64u);
  for (size_t i = 0; i < px.size(); i += 4) {
    EXPECT_FLOAT_EQ(px[i], 0.75f);
    EXPECT_FLOAT_EQ(px[i + 1], 0.5f);
    EXPECT_FLOAT_EQ(px[i + 2], 1.0f);
  }
}

// docs/shadertoy.md's glslViewer shader renders with no warning: the
// vignette of its POSTPROCESSING pass darkens the scene's background in the
// corner, and the dot that BUFFER_0 draws shows through the other passes.
TEST_F(Cli, TheDocsGlslViewerShaderRendersItsFourPasses) {
  const test::Outcome r = run("render " + std::string(RM_TEST_DATA_DIR) + "/glslviewer/trails.frag -o " +
                              (dir_ / "t.exr").string() + " --size 32x18 --time 2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::vector<float> px = test::read_pixels(dir_ / "t.exr");
  ASSERT_EQ(px.size(), 32u * 18u * 4u);
  const float st = 0.5f / 32.0f - 0.5f, tt = 17.5f / 18.0f - 0.5f;  // the top left pixel
  EXPECT_NEAR(px[0], 0.05f * (1.0f - 0.8f * (st * st + tt * tt)), 1e-4f);
  float brightest = 0.0f;
  for (size_t i = 0; i < px.size(); i += 4) brightest = std::max(brightest, px[i]);
  EXPECT_GT(brightest, 0.7f);
}

// A buffer's pass takes a channel the code leaves free; with all four read
// (u_tex0-3), there is none, and that is an error at the buffer's declaration.
TEST_F(Cli, AGlslViewerBufferWithNoChannelFreeIsAnError) {
  write_file(dir_ / "full.frag",
             "uniform sampler2D u_tex0, u_tex1;\nuniform sampler2D u_tex2;\nuniform sampler2D u_tex3;\n"
             "uniform sampler2D u_buffer0;\n"
             "void main() {\n#ifdef BUFFER_0\n  gl_FragColor = vec4(1.0);\n#else\n"
             "  gl_FragColor = texture2D(u_tex0, vec2(0.5)) + texture2D(u_tex1, vec2(0.5)) +\n"
             "      texture2D(u_tex2, vec2(0.5)) + texture2D(u_tex3, vec2(0.5)) + texture2D(u_buffer0, vec2(0.5));\n"
             "#endif\n}\n");
  const std::string scene = (dir_ / "full.frag").string();
  const test::Outcome r = run("check " + scene);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, scene + ":4:19: error: 'u_buffer0' is read, and glslViewer's BUFFER_0 pass it reads needs a "
                           "channel of its own, but the code takes all four (iChannel0-3, u_tex0-3 and #pragma "
                           "channelN)\n");
}

// render draws a shader's HW_PERFORMANCE == 1 branch on any renderer (the
// window gives one on the CPU 0): frames of a sequence split across
// machines must match, and an offline picture may take its time. A -D wins.
TEST_F(Cli, RenderGivesHwPerformanceOneOnAnyRenderer) {
  write_file(dir_ / "hw.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(float(HW_PERFORMANCE), 0.5, 0.0, 1.0); }\n");
  const std::string scene = (dir_ / "hw.frag").string();
  EXPECT_EQ(red_of(scene, ""), 1.0f);
  EXPECT_EQ(command_of(dir_ / "red.exr").find("HW_PERFORMANCE"), std::string::npos) << command_of(dir_ / "red.exr");
  EXPECT_EQ(red_of(scene, " -D HW_PERFORMANCE=0"), 0.0f);
}

// -U NAME, as a compiler's: the scene's own #define of NAME is read as a
// blank line (a shader's unconditional `#define AA` turned off). The
// picture's command line records it; a bad name, or a -D of the same name,
// is one line and exit 2.
TEST_F(Cli, RenderUndefinesAScenesOwnMacroAndRecordsIt) {
  write_file(dir_ / "aa.frag", "#define AA\nvoid mainImage(out vec4 c, in vec2 f) {\n#ifdef AA\n  c = vec4(1.0);\n"
                               "#else\n  c = vec4(0.5);\n#endif\n}\n");
  const std::string scene = (dir_ / "aa.frag").string(), exr = (dir_ / "red.exr").string();
  EXPECT_EQ(red_of(scene, ""), 1.0f);
  EXPECT_EQ(red_of(scene, " -U AA"), 0.5f);
  const std::string command = command_of(exr);
  EXPECT_NE(command.find(" -U AA"), std::string::npos) << command;
  const test::Outcome again = run(command.substr(std::string("raymarching ").size()) + " -o " + exr);
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(test::read_pixels(exr).at(0), 0.5f);
  EXPECT_EQ(run("check " + scene + " -U AA").status, 0);

  test::Outcome bad = run("render " + scene + " -o " + exr + " -U 2x");
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.err, "raymarching: error: -U '2x': not a macro name\n");
  bad = run("render " + scene + " -o " + exr + " -D \"$(printf 'AA=1\\n#error x')\"");  // each -D is one line of the source
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.err, "raymarching: error: -D 'AA=1\\x0a#error x': its value is not one line\n");
  bad = run("render " + scene + " -o " + exr + " -D AA=2 -U AA");
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.err, "raymarching: error: -U AA: -D gives AA a value; give one of them\n");
  bad = run("render " + scene + " -o " + exr + " --quality draft -U RM_QUALITY");
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.err, "raymarching: error: -U RM_QUALITY: --quality gives RM_QUALITY a value; give one of them\n");
}

// render --set gives the shader's own uniforms their values; the picture's
// metadata records every value, so its own command line renders it again.
TEST_F(Cli, RenderSetGivesUniformsAndTheMetadataReproducesThem) {
  write_file(dir_ / "u.frag", "uniform float gain;  // ui: min=0 max=2 default=0.5\n"
                              "uniform vec3 tint;   // ui: color default=1,1,1\n"
                              "void mainImage(out vec4 c, in vec2 f) { c = vec4(gain * tint, 1.0); }\n");
  const std::string scene = (dir_ / "u.frag").string(), first = (dir_ / "a.exr").string();
  test::Outcome r = run("render " + scene + " -o " + (dir_ / "default.exr").string() + " --size 2x2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(test::read_pixels(dir_ / "default.exr")[0], 0.5f) << "the declared default";
  r = run("render " + scene + " -o " + first + " --size 2x2 --set gain=2 --set tint=0.25,0.5,1");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<float> pixels = test::read_pixels(first);
  ASSERT_EQ(pixels.size(), 16u);
  EXPECT_EQ(std::vector<float>(pixels.begin(), pixels.begin() + 3), (std::vector<float>{0.5f, 1.0f, 2.0f}));
  const std::string command = command_of(first);
  EXPECT_NE(command.find("--set gain=2 --set tint=0.25,0.5,1"), std::string::npos) << command;
  ASSERT_EQ(command.rfind("raymarching render ", 0), 0u) << command;
  r = run(command.substr(std::string("raymarching ").size()) + " -o " + (dir_ / "again.exr").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(test::read_pixels(dir_ / "again.exr"), test::read_pixels(first));
  r = run("render " + scene + " -o " + first + " --set gian=0.5");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "raymarching: error: --set 'gian=0.5': the shader declares no uniform 'gian' of its own (it has gain, tint)\n");
}

// A uniform named with a word 4.50 core reserves (glslViewer's `smooth`,
// Shadertoy's `buffer`) reaches the driver renamed, and still takes its
// default and its --set value by the name the code gives it.
TEST_F(Cli, RenderSetReachesAUniformTheDialectRenames) {
  write_file(dir_ / "legacy.frag", "uniform float smooth;  // ui: default=0.5\n"
                                   "void main() { gl_FragColor = vec4(smooth, 0.0, 0.0, 1.0); }\n");
  write_file(dir_ / "toy.frag", "uniform float buffer;  // ui: default=0.5\n"
                                "void mainImage(out vec4 c, in vec2 f) { c = vec4(buffer, 0.0, 0.0, 1.0); }\n");
  for (const auto& [file, name] : {std::pair{"legacy.frag", "smooth"}, std::pair{"toy.frag", "buffer"}}) {
    const std::string scene = (dir_ / file).string(), out = (dir_ / "out.exr").string();
    test::Outcome r = run("render " + scene + " -o " + out + " --size 2x2");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(test::read_pixels(out)[0], 0.5f) << file << ": the declared default";
    r = run("render " + scene + " -o " + out + " --size 2x2 --set " + name + "=0.25");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(test::read_pixels(out)[0], 0.25f) << file;
  }
}

// Silent on success, as compilers and linters are: exit 0 and no output.
TEST_F(Cli, CheckOfAGoodShaderIsSilent) {
  test::Outcome r = run("check " + good());
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.err, "");
}

TEST_F(Cli, SyntaxErrorIsExitOneWithFileLineColumn) {
  write_file(dir_ / "bad.frag", "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(1.0) +;\n}\n");
  test::Outcome r = run("check " + (dir_ / "bad.frag").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err.rfind((dir_ / "bad.frag").string() + ":2:", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(": error: "), std::string::npos);
}

// check validates every pass a project reads, without a GL context.
TEST_F(Cli, CheckValidatesEveryPassOfAProject) {
  write_file(dir_ / "buffer_a.frag", "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(missing);\n}\n");
  write_file(dir_ / "image.frag", "#pragma channel0 \"buffer_a.frag\"\n"
                                  "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, f); }\n");
  test::Outcome r = run("check " + (dir_ / "image.frag").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err.rfind((dir_ / "buffer_a.frag").string() + ":2:", 0), 0u) << r.err;
  write_file(dir_ / "buffer_a.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(1); }\n");
  r = run("check " + (dir_ / "image.frag").string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
}

TEST_F(Cli, DefinesAndIncludeDirsWorkAsInACompiler) {
  write_file(dir_ / "d.frag", "#include \"extra.glsl\"\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(LEVEL + EXTRA); }\n");
  write_file(dir_ / "inc/extra.glsl", "const float EXTRA = 1.0;\n");
  const std::string scene = (dir_ / "d.frag").string(), inc = (dir_ / "inc").string();
  EXPECT_EQ(run("check " + scene + " -I " + inc).status, 1);                 // LEVEL undefined
  EXPECT_EQ(run("check " + scene + " -I " + inc + " -DLEVEL=2.0").status, 0);
  EXPECT_EQ(run("check " + scene + " -I" + inc + " -D LEVEL").status, 0);    // NAME alone is 1
  EXPECT_EQ(run("check " + scene + " -DLEVEL=2.0").status, 1);              // include not found
}

// A -D of a knob the example sets itself (cubes: `#define RM_MAX_STEPS 200`)
// takes its place, as a control of the window does, instead of a
// redefinition error; the picture is the knob's.
TEST_F(Cli, DefineOverridesAnExamplesOwnKnob) {
  const std::string cubes = std::string(RM_TEST_DATA_DIR) + "/../../examples/cubes.frag";
  const std::string plain = (dir_ / "plain.png").string(), few = (dir_ / "few.png").string();
  const test::Outcome shipped = run("render " + cubes + " --size 64x36 --time 1 -o " + plain);
  ASSERT_EQ(shipped.status, 0) << shipped.err;
  const test::Outcome overridden = run("render " + cubes + " --size 64x36 --time 1 -D RM_MAX_STEPS=4 -o " + few);
  ASSERT_EQ(overridden.status, 0) << overridden.err;
  EXPECT_EQ(overridden.err, "");
  EXPECT_NE(test::read_file(plain), test::read_file(few));  // 4 steps reach fewer cubes
}

// `check -E` prints what the compiler sees, as a compiler's -E does: macros
// (including -D ones) expanded, branches not taken gone.
// -E marks where lines come from as cpp does, drops blank runs, and takes a
// scene named relative to the working directory.
TEST_F(Cli, CheckExpandMarksFilesAndLinesAndDropsBlankRuns) {
  write_file(dir_ / "lib.glsl", "float f() { return 1.0; }\n\n\n\n\n\n\n\n\n\n\n\nfloat g() { return 2.0; }\n");
  write_file(dir_ / "s.frag", "#include \"lib.glsl\"\n#if 0\nnot this\n#endif\n"
                              "void mainImage(out vec4 c, in vec2 p) { c = vec4(f() + g()); }\n");
  const std::string out = (dir_ / "expanded.glsl").string();
  const std::string cmd = "cd " + dir_.path().string() + " && " + RM_BINARY + " check -E s.frag > " + out;
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string text = test::read_file(out);
  const std::string lib = (dir_ / "lib.glsl").string(), scene = (dir_ / "s.frag").string();
  EXPECT_NE(text.find("# 1 \"" + lib + "\"\nfloat f()"), std::string::npos) << text;
  EXPECT_NE(text.find("# 13 \"" + lib + "\"\nfloat g()"), std::string::npos) << "a gap of 11 lines is a marker\n" << text;
  EXPECT_NE(text.find("# 5 \"" + scene + "\"\nvoid mainImage"), std::string::npos) << text;
  EXPECT_EQ(text.find("\n\n"), std::string::npos) << "no blank lines\n" << text;
}

// -P, as cpp -P: the same lines with no markers, which glslangValidator
// takes as they are; -P without -E is a usage error.
TEST_F(Cli, CheckExpandWithoutLineMarkersIsTextGlslangValidatorTakes) {
  write_file(dir_ / "lib.glsl", "float f() { return 1.0; }\n\n\n\n\n\n\n\n\n\n\n\nfloat g() { return 2.0; }\n");
  write_file(dir_ / "s.frag", "#include \"lib.glsl\"\nvoid mainImage(out vec4 c, in vec2 p) { c = vec4(f() + g()); }\n");
  const std::string out = (dir_ / "expanded.frag").string();
  const std::string cmd = std::string(RM_BINARY) + " check -E -P " + (dir_ / "s.frag").string() + " > " + out;
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string text = test::read_file(out);
  EXPECT_EQ(text.rfind("#version 450 core\n", 0), 0u) << text;
  const size_t f = text.find("float f()");
  ASSERT_NE(f, std::string::npos) << text;
  EXPECT_EQ(text.compare(text.find('\n', f) + 1, 9, "float g()"), 0) << "g follows f, with no gap\n" << text;
  EXPECT_EQ(text.find("\n# "), std::string::npos) << "no line markers\n" << text;
  EXPECT_EQ(text.find("\n\n"), std::string::npos) << "no blank lines\n" << text;
  const std::string validator = "glslangValidator -S frag " + out + " > /dev/null";
  EXPECT_EQ(std::system(validator.c_str()), 0) << text;

  const test::Outcome r = run("check -P " + (dir_ / "s.frag").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--no-line-markers requires --expand"), std::string::npos) << r.err;
}

TEST_F(Cli, CheckExpandPrintsThePreprocessedSource) {
  write_file(dir_ / "e.frag", "#ifdef FANCY\nfloat fancy_marker;\n#endif\n"
                              "void mainImage(out vec4 c, in vec2 f) { c = vec4(LEVEL); }\n");
  const std::string out = (dir_ / "expanded.glsl").string();
  const std::string cmd = std::string(RM_BINARY) + " check -E " + (dir_ / "e.frag").string() + " -DLEVEL=2.5 > " + out;
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string text = test::read_file(out);
  EXPECT_NE(text.find("c = vec4(2.5)"), std::string::npos) << text;
  EXPECT_EQ(text.find("fancy_marker"), std::string::npos) << text;
}

// `accuracy` sweeps the knobs of a shaderlib scene and writes its report.
TEST_F(Cli, AccuracyWritesATableACsvAChartAndPictures) {
  const std::string scene = ball_on_floor("sphere.frag", "#define RM_SHADOWS 2");
  const auto out = dir_ / "report";
  const test::Outcome r = run("accuracy " + scene + " --size 32x18 --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("[1/"), std::string::npos) << "no progress shown";
  const std::string csv = test::read_file(out / "accuracy.csv");
  EXPECT_EQ(csv.rfind("knob,value,ms,wall_ms,evaluations_mean", 0), 0u) << csv;
  EXPECT_GT(lines(csv), 40);
  EXPECT_NE(csv.find("textbook,textbook,"), std::string::npos);
  EXPECT_NE(csv.find("RM_SHADOW_STEPS,8,"), std::string::npos);
  EXPECT_EQ(test::read_file(out / "accuracy.svg").rfind("<svg", 0), 0u);
  EXPECT_EQ(test::read_pixels(out / "reference.png").size(), 32u * 18u * 4u);
  EXPECT_EQ(test::read_pixels(out / "steps.png").size(), 32u * 18u * 4u);
  EXPECT_NE(r.err.find("accuracy.svg, reference.png, steps.png\n"), std::string::npos) << r.err;
}

// A scene whose steps view does not build still gets its report, and the
// run says so: an older report's steps.png is not passed off as this one's.
TEST_F(Cli, AccuracyWithoutAStepsViewSaysSo) {
  const std::string scene = ball_on_floor("nosteps.frag", "#if RM_VIEW == 1\n#error no steps view here\n#endif");
  const auto out = dir_ / "report";
  std::filesystem::create_directories(out);
  write_file(out / "steps.png", "an earlier run's");
  const test::Outcome r = run("accuracy " + scene + " --size 32x18 --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("the steps view does not build, so no steps.png is written:\n" + scene + ":2:"),
            std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no steps view here"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the steps.png in " + out.string() + " is an earlier run's"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("accuracy.svg, reference.png\n"), std::string::npos) << r.err;
  EXPECT_EQ(test::read_file(out / "steps.png"), "an earlier run's");
  EXPECT_EQ(test::read_pixels(out / "reference.png").size(), 32u * 18u * 4u);
}

// The reference is the scene at the reference preset's knobs, whatever the
// scene's own #defines of them say: two march steps cannot reach the floor,
// and the yardstick must show that as an error, not take the two steps too.
TEST_F(Cli, AccuracyReferenceIgnoresTheScenesOwnKnobs) {
  const std::string scene = ball_on_floor("short.frag", "#define RM_MAX_STEPS 2");
  const auto out = dir_ / "report";
  const test::Outcome r = run("accuracy " + scene + " --size 32x18 --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  // It failed once in about five full runs of the suite, and never alone: on
  // a failure, say everything the command said and wrote.
  SCOPED_TRACE("stderr:\n" + r.err + "\naccuracy.csv:\n" + test::read_file(out / "accuracy.csv"));
  // knob,value,ms,wall_ms,evaluations_mean,evaluations_max,rmse,psnr_db,hit_miss_share,depth_error,
  // nan_pixels,no_effect,bound_evaluations_mean
  auto row = [&](const std::string& prefix) {
    const std::string csv = test::read_file(out / "accuracy.csv");
    const size_t at = csv.find("\n" + prefix);
    EXPECT_NE(at, std::string::npos) << csv;
    std::vector<std::string> fields;
    std::stringstream line(csv.substr(at + 1, csv.find('\n', at + 1) - at - 1));
    for (std::string f; std::getline(line, f, ',');) fields.push_back(f);
    return fields;
  };
  const auto base = row("default,default,"), long_march = row("RM_MAX_STEPS,512,");
  ASSERT_EQ(base.size(), 13u);
  ASSERT_EQ(long_march.size(), 13u);
  EXPECT_GT(std::stod(base[8]), 0.1) << "the default's misses match the reference's: it took the scene's 2 steps";
  EXPECT_LT(std::stod(base[7]), 30.0);
  EXPECT_LT(std::stod(long_march[8]), 0.02);  // a silhouette pixel or two
  EXPECT_GT(std::stod(long_march[7]), std::stod(base[7]) + 10.0);
}

TEST_F(Cli, AccuracyNeedsAShaderlibScene) {
  const test::Outcome r = run("accuracy " + good() + " --out " + (dir_ / "x").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("needs a scene that marches with shaderlib"), std::string::npos) << r.err;
}

TEST_F(Cli, UsageAndIoErrorsAreExitTwoWithOneLine) {
  const std::string g = good();
  const std::string out = (dir_ / "o.png").string();
  write_file(dir_ / "a_file", "");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"render " + (dir_ / "missing.frag").string() + " -o " + out, "no such file"},
      {"render " + dir_.path().string() + " -o " + out, "is a directory"},
      {"check " + (dir_ / "missing.frag").string(), "no such file"},
      {"--no-such-option", "--no-such-option"},
      {"render " + g + " -o " + out + " --size 0x0", "--size '0x0'"},
      {"render " + g + " -o " + out + " --size -5x3", "--size '-5x3'"},
      {"render " + g + " -o " + out + " --size 100000x100000", "--size '100000x100000'"},
      {"render " + g + " -o " + out + " --size big", "--size 'big'"},
      {"render " + g + " -o " + out + " --mouse 1,2,3", "--mouse '1,2,3'"},
      {"render " + g + " -o " + out + " --mouse a,b", "--mouse 'a'"},
      // A date mktime would carry into another one is none.
      {"render " + g + " -o " + out + " --date 2020-02-30T00:00:00", "--date '2020-02-30T00:00:00': no such day"},
      {"render " + g + " -o " + out + " --date 2021-13-01T00:00:00", "--date '2021-13-01T00:00:00': no such day"},
      {"render " + g + " -o " + out + " --date 2020-01-01T24:00:00", "--date '2020-01-01T24:00:00': no such time of day"},
      {"render " + g + " -o " + out + " --date 2020-01-01T12:00:60.5", "--date '2020-01-01T12:00:60.5': no such time of day"},
      {"render " + g + " -o " + out + " --time soon", "--time 'soon'"},
      {"render " + g + " -o " + out + " --time nan", "--time 'nan'"},
      // The formats named are the ones that work: .jpg among them, not only .png and .exr;
      // and .gif among the videos, which render writes it as, not among the pictures.
      {"render " + g + " -o " + (dir_ / "o.xyz").string(), "cannot write files of type '.xyz' (pictures: .exr, .tif, .jpg, .bmp, .dpx, .hdr"},
      {"render " + g + " -o " + (dir_ / "o.xyz").string(), "; videos: .mp4, .mov, .webm, .gif)"},
      {"render " + g + " -o " + (dir_ / "noext").string(), "has no extension to choose a format (pictures: .exr"},
      {"render " + g + " -o " + (dir_ / "f_%04d.xyz").string() + " --frames 2", "f_0000.xyz': cannot write files of type '.xyz' (pictures"},
      {"render " + g + " -o " + (dir_ / "nodir/o.png").string(), "does not exist"},
      {"render " + g + " -o " + (dir_ / "frame.png").string() + " --frames 3", "counter"},
      {"render " + g + " -o " + out + " --channel0 " + (dir_ / "none.png").string(), "--channel0 '" + (dir_ / "none.png").string() + "': no such file"},
      // Unreadable even for root: a directory where the image should be.
      {"render " + g + " -o " + out + " --channel1 " + dir_.path().string(), "--channel1 '" + dir_.path().string() + "': is a directory"},
      // Unwritable even for root: /proc takes no new files; a file is no directory.
      {"render " + g + " -o /proc/rm-cli-test.png", "'/proc/rm-cli-test.png'"},
      {"render " + g + " -o " + (dir_ / "a_file/o.png").string(), "is not a directory"},
      {"render " + g + " -o " + out + " -D 9bad=1", "-D '9bad=1'"},
      {"render " + g, "--output is required"},
      // A mistyped option is named, not the required one it may have meant;
      // the unexpected arguments in the order given.
      {"render " + g + " --ouptut " + out, "not expected: --ouptut " + out + " ("},
      {"render " + g + " -o " + out + " -x 3 -y", "not expected: -x 3 -y (see raymarching render --help)"},
      {"render " + g + " -o " + out + " -o " + out, "--output was given 2 times; it takes one value (see raymarching render --help)"},
      {"--size 10x10 --size 20x20 " + g, "--size was given 2 times; it takes one value (see raymarching --help)"},
      {"render " + g + " -o " + out + " --size", "--size needs a value: WxH (see raymarching render --help)"},
      {"render " + g + " -o " + out + " --timeout 0", "--timeout"},
      // NaN passes CLI11's Range; a number past the clock's reach overflowed it.
      {"render " + g + " -o " + out + " --timeout nan", "--timeout: 'nan' is not a number from 0.001 to 1e+08"},
      {"render " + g + " -o " + out + " --timeout 1e300", "--timeout: '1e300' is not a number"},
      {"render " + g + " -o " + out + " --fps nan", "--fps: 'nan' is not a number"},
      {"--target-fps nan", "--target-fps: 'nan' is not a number from 0 to 1000"},
      {"--tile-limit inf", "--tile-limit: 'inf' is not a number"},
      {"render " + g + " -o " + out + " --samples 0", "--samples"},
      {"render " + g + " -o " + out + " --samples 5000", "--samples"},
      {"--refine -1", "--refine: '-1' is not a whole number from 0 to 1024"},
      // CLI11 said "Could not convert: --frame = 99999999999", and printed DBL_MAX in full for 'abc'.
      {"render " + g + " -o " + out + " --frame 99999999999", "--frame: '99999999999' is not a whole number from 0 to 2147483647"},
      {"render " + g + " -o " + out + " --frame abc", "--frame: 'abc' is not a whole number from 0 to 2147483647"},
      {"render " + g + " -o " + out + " --samples 1.5", "--samples: '1.5' is not a whole number from 1 to 1024"},
      // iFrame is an int: the frame that --time or --frame and --frames reach must be one (an undefined cast).
      {"accuracy " + g + " --time nan", "--time 'nan': not a finite number"},
      {"accuracy " + g + " --time 1e300", "--time 1e+300: iFrame would be 6e+301, past what an int holds (-2147483648 to 2147483647)"},
      {"render " + g + " -o " + out + " --mouse 1e300,0", "--mouse '1e300,0': 1e300 is out of a float's range"},
      {"render " + g + " -o " + out + " --time 1e300", "iFrame would be 6e+301, past what an int holds (-2147483648 to 2147483647): give a smaller --time"},
      {"render " + g + " -o " + (dir_ / "f_%d.png").string() + " --frame 2147483647 --frames 10", "iFrame would be 2147483656, past what an int holds"},
      {"render " + g + " -o " + (dir_ / "f_%d.png").string() + " --frames 4 --frame-range 2:4", "--frame-range 2:4: the sequence has frames 0 to 3"},
      {"render " + g + " -o " + (dir_ / "f_%d.png").string() + " --frames 4 --frame-range 3:1", "--frame-range '3:1': FIRST comes after LAST"},
      {"render " + g + " -o " + (dir_ / "f_%d.png").string() + " --frames 4 --frame-range 1-2", "--frame-range '1-2': expected FIRST:LAST"},
      {"render " + g + " -o " + out + " --frame-range 0:0", "--frame-range is a slice of a sequence: give --frames COUNT"},
      {"render " + g + " -o " + (dir_ / "v.mp4").string() + " --frames 4 --frame-range 0:1", "--frame-range writes frames, not a video"},
      {"render " + g + " -o " + (dir_ / "v.mp4").string(), "a video needs --frames COUNT or --duration SECONDS"},
      {"render " + g + " -o " + (dir_ / "v.mp4").string() + " --frames 4 --skip-existing", "--skip-existing goes on with frames already written, and a video is one file"},
      {"render " + std::string(RM_TEST_DATA_DIR) + "/../../examples/progressive/image.frag -o " + (dir_ / "f_%d.png").string() + " --frames 4 --skip-existing --size 8x8", "--skip-existing: this project feeds each frame into the next"},
      {"render " + g + " -o " + (dir_ / "v.mp4").string() + " --frames 2 --size 161x90", "needs an even width and height"},
      {"render " + g + " -o " + out + " --crf 20", "--codec and --crf are for a video (.mp4, .mov, .webm, .gif)"},
      {"render " + g + " -o " + (dir_ / "v.gif").string() + " --frames 2 --crf 20", "--crf does not apply to .gif"},
      {"render " + g + " -o " + (dir_ / "v.mp4").string() + " --frames 2 --duration 1", "--frames excludes --duration"},
      {"render " + g + " -o " + (dir_ / "v.mp4").string() + " --duration 1e6 --fps 1e5", "--duration 1e+06 at --fps 100000 is 100000000000 frames; at most 1000000"},
  };
  for (const auto& [args, expected] : cases) {
    test::Outcome r = run(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_EQ(lines(r.err), 1) << args << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("raymarching: error: ", 0), 0u) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << args << "\n" << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(out));
}

// A shader of half a million loop steps per pixel: tens of seconds at
// 320x180 on llvmpipe, which ends any loop after 65535 iterations, so each
// does eight steps.
constexpr const char* kHeavy =
    "#define STEP a = fract(a * 1.37 + sin(a + float(i) * 0.001 + f.x * 0.01));\n"
    "void mainImage(out vec4 c, in vec2 f) {\n  float a = 0.0;\n"
    "  for (int i = 0; i < STEPS; ++i) { STEP STEP STEP STEP STEP STEP STEP STEP }\n"
    "  c = vec4(a, f / iResolution.xy, 1.0);\n}\n";

std::vector<std::string> names_in(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// render --motion-samples N [--shutter F]: each frame is the mean of N times
// spread evenly over the open shutter, centred on the frame's time; iFrame
// stays the frame's. A step at t = 0.21 seen by frame 2 at 10 fps (t = 0.2):
// shut, no time past it; open for half the interval (0.175 to 0.225), one of
// 4 steps; open for the whole (0.15 to 0.25), two of 4. The metadata's
// command renders the same frame again.
TEST_F(Cli, RenderMotionBlurAveragesTimesOverTheOpenShutter) {
  write_file(dir_ / "step.frag", "void mainImage(out vec4 c, in vec2 f) {\n"
                                 "  c = vec4(iTime > 0.21 ? 1.0 : 0.0, float(iFrame) / 10.0, 0.0, 1.0);\n}\n");
  auto red = [&](const std::string& blur) {
    const auto out = dir_ / "step.exr";
    const test::Outcome r = run("render " + (dir_ / "step.frag").string() + " -o " + out.string() +
                                " --size 8x4 --time 0.2 --fps 10 " + blur);
    EXPECT_EQ(r.status, 0) << r.err;
    const std::vector<float> px = test::read_pixels(out);
    EXPECT_EQ(px.size(), 8u * 4u * 4u);
    for (size_t i = 0; i < px.size(); i += 4) EXPECT_FLOAT_EQ(px[i + 1], 0.2f) << "iFrame moved with the shutter";
    return px.empty() ? -1.0f : px[0];
  };
  EXPECT_EQ(red(""), 0.0f);
  EXPECT_FLOAT_EQ(red("--motion-samples 4"), 0.25f);
  EXPECT_FLOAT_EQ(red("--motion-samples 4 --shutter 0.5"), 0.25f);
  EXPECT_FLOAT_EQ(red("--motion-samples 4 --shutter 1"), 0.5f);
  EXPECT_FLOAT_EQ(red("--motion-samples 4 --shutter 0"), 0.0f);

  const auto png = dir_ / "blurred.png";
  ASSERT_EQ(run("render " + (dir_ / "step.frag").string() + " -o " + png.string() +
                " --size 8x4 --time 0.2 --fps 10 --motion-samples 4 --shutter 1").status, 0);
  const std::string command = command_of(png);
  EXPECT_NE(command.find(" --fps 10 --shutter 1 --motion-samples 4"), std::string::npos) << command;

  const test::Outcome lone = run("render " + (dir_ / "step.frag").string() + " -o " + png.string() + " --shutter 0.5");
  EXPECT_EQ(lone.status, 2);
  EXPECT_NE(lone.err.find("--shutter requires --motion-samples"), std::string::npos) << lone.err;
}

// render --timeout: a render that runs too long ends at the limit with exit
// status 124, one line, and no file left (no output, no temporary); the
// frames a sequence had written are removed. One that fits is untouched.
TEST_F(Cli, RenderTimeoutEndsALongRenderWith124AndLeavesNothing) {
  write_file(dir_ / "heavy.frag", "#define STEPS 60000\n" + std::string(kHeavy));
  test::Outcome r = run("render " + (dir_ / "heavy.frag").string() + " -o " + (dir_ / "out.png").string() +
                        " --size 320x180 --timeout 2");
  EXPECT_EQ(r.status, 124) << r.err;
  EXPECT_EQ(r.err, "raymarching: error: the render ran past --timeout 2 s and was stopped; nothing was written\n");
  EXPECT_GE(r.seconds, 2.0);
  EXPECT_LT(r.seconds, 5.0) << "the limit is 2 s";
  EXPECT_EQ(names_in(dir_.path()), std::vector<std::string>{"heavy.frag"});

  // A sequence of frames of about a tenth of a second each. Its limit leaves
  // room for the first frames to be written: under the sanitizers on a loaded
  // machine, start-up alone once took 2 s, and nothing had been written yet.
  test::TempDir seq;
  write_file(seq / "light.frag", "#define STEPS 300\n" + std::string(kHeavy));
  r = run("render " + (seq / "light.frag").string() + " -o " + (seq / "f%03d.png").string() +
          " --size 320x180 --frames 100000 --timeout 8");
  EXPECT_EQ(r.status, 124) << r.err;
  EXPECT_EQ(r.err, "raymarching: error: the render ran past --timeout 8 s and was stopped; the frames it wrote are "
                   "removed\n");
  EXPECT_EQ(names_in(seq.path()), std::vector<std::string>{"light.frag"});

  r = run("render " + (seq / "light.frag").string() + " -o " + (seq / "one.png").string() +
          " --size 32x18 --timeout 60");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(seq / "one.png"));
}

// OUT with a counter and no --frames is a sequence of one frame, numbered as
// --frames 1 numbers it; it used to be written as a file named f_%04d.png.
TEST_F(Cli, RenderOfOneFrameFillsTheCounterOfItsOutput) {
  write_file(dir_ / "red.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0, 0.0, 0.0, 1.0); }\n");
  const test::Outcome r =
      run("render " + (dir_ / "red.frag").string() + " -o " + (dir_ / "f_%04d.png").string() + " --size 8x8");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(names_in(dir_.path()), (std::vector<std::string>{"f_0000.png", "red.frag"}));
}

// import writes a project's files, which then check clean; it replaces
// nothing without --force, and writes nothing where it cannot write all.
TEST_F(Cli, ImportWritesTheProjectAndReplacesNothingUnasked) {
  const std::string json = std::string(RM_TEST_DATA_DIR) + "/shadertoy/pingpong.json";
  const std::filesystem::path project = dir_ / "pingpong";
  test::Outcome r = run("import " + json + " " + project.string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(names_in(project), (std::vector<std::string>{"buffer_a.frag", "buffer_b.frag", "image.frag"}));
  r = run("check " + (project / "image.frag").string());
  EXPECT_EQ(r.status, 0) << r.err;

  write_file(project / "buffer_a.frag", "// edited\n");
  r = run("import " + json + " " + project.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "raymarching: error: '" + (project / "buffer_a.frag").string() + "' exists (--force replaces it)\n");
  EXPECT_EQ(test::read_file(project / "buffer_a.frag"), "// edited\n");
  r = run("import " + json + " " + project.string() + " --force");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(test::read_file(project / "buffer_a.frag"), "// edited\n");

  write_file(dir_ / "afile", "");
  r = run("import " + json + " " + (dir_ / "afile").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "raymarching: error: '" + (dir_ / "afile").string() +
                       "': cannot create the directory: a file of that name is there\n");
  r = run("import " + json + " " + (dir_ / "afile" / "sub").string());
  EXPECT_NE(r.err.find("cannot create the directory: not a directory"), std::string::npos) << r.err;
  write_file(dir_ / "broken.json", "{\"renderpass\": [,]}");
  r = run("import " + (dir_ / "broken.json").string() + " " + (dir_ / "never").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("broken.json:1:17: syntax error"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "never"));
}

// Bad shader files: each is exit 1 (a shader problem) or 2 (I/O), with one
// line on stderr naming the problem and the path, never a crash or a hang.
TEST_F(Cli, BadShaderFilesGetOneClearLine) {
  write_file(dir_ / "empty.frag", "");
  const char garbage[] = "\x7f" "ELF\x02\x01\x00\x00\xff\xfe binary";  // NULs inside: sized by the array
  write_file(dir_ / "garbage.frag", std::string(garbage, sizeof garbage - 1));
  write_file(dir_ / "missing_include.frag", "#include \"nowhere.glsl\"\nvoid mainImage(out vec4 c, in vec2 f) {}\n");
  std::filesystem::create_directories(dir_ / "adir");
  write_file(dir_ / "include_dir.frag", "#include \"adir\"\nvoid mainImage(out vec4 c, in vec2 f) {}\n");
  write_file(dir_ / "cycle.frag", "#include \"c1.glsl\"\nvoid mainImage(out vec4 c, in vec2 f) {}\n");
  write_file(dir_ / "c1.glsl", "#include \"c2.glsl\"\n");
  write_file(dir_ / "c2.glsl", "#include \"c1.glsl\"\n");
  // A chain 200 includes deep: deep but legal (the limit is 256).
  write_file(dir_ / "deep.frag", "#include \"d0.glsl\"\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(D199); }\n");
  for (int i = 0; i < 200; ++i)
    write_file(dir_ / ("d" + std::to_string(i) + ".glsl"),
               i < 199 ? "#include \"d" + std::to_string(i + 1) + ".glsl\"\n" : "#define D199 1.0\n");
  // Six megabytes of shader: a real function, padded with comment lines.
  std::string big = "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n";
  while (big.size() < 6u * 1024 * 1024) big += "// padding padding padding padding padding padding padding padding\n";
  write_file(dir_ / "big.frag", big);
  write_file(dir_ / "corrupt.png", "this is not a PNG");
  // A PNG with its pixels cut off, a JPEG within its header: libpng printed
  // a line of its own, and OIIO's message was three lines (JPEG's two).
  for (const std::string name : {"cut.png", "cut.jpg"}) {
    std::vector<unsigned char> noise(64 * 64 * 3);
    for (size_t i = 0; i < noise.size(); ++i) noise[i] = static_cast<unsigned char>((i * 2654435761u) >> 13);
    auto image = OIIO::ImageOutput::create(name);
    ASSERT_TRUE(image && image->open((dir_ / name).string(), OIIO::ImageSpec(64, 64, 3, OIIO::TypeDesc::UINT8)));
    image->write_image(OIIO::TypeDesc::UINT8, noise.data());
    image->close();
    std::filesystem::resize_file(dir_ / name, name == "cut.png" ? std::filesystem::file_size(dir_ / name) / 2 : 200);
  }
  const std::string out = " -o " + (dir_ / "o.png").string();
  struct Case {
    std::string args;
    int status;
    std::string says;  // part of the one line
  };
  const std::vector<Case> cases = {
      {"check " + (dir_ / "empty.frag").string(), 1, "empty.frag"},
      {"check " + (dir_ / "garbage.frag").string(), 1, "not a text file"},
      {"check " + (dir_ / "missing_include.frag").string(), 1, "missing_include.frag:1:10: error: cannot find include 'nowhere.glsl'"},
      {"check " + (dir_ / "include_dir.frag").string(), 1, "include_dir.frag:1:"},
      {"check " + (dir_ / "cycle.frag").string(), 1, "#include cycle"},
      {"render " + good() + out + " --channel0 " + (dir_ / "corrupt.png").string(), 2, "corrupt.png"},
      {"render " + good() + out + " --channel0 " + (dir_ / "cut.png").string(), 2,
       "cut.png': PNG read error: IDAT: Read error: hit end of file; PNG library error"},
      {"render " + good() + out + " --channel0 " + (dir_ / "cut.jpg").string(), 2, "cut.jpg': JPEG error: Premature end of JPEG file"},
  };
  for (const Case& c : cases) {
    const test::Outcome r = run(c.args);
    EXPECT_EQ(r.status, c.status) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_EQ(lines(r.err), 1) << c.args << "\n" << r.err;
  }
  EXPECT_EQ(run("check " + (dir_ / "deep.frag").string()).status, 0);
  const test::Outcome big_render = run("render " + (dir_ / "big.frag").string() + out + " --size 8x8");
  EXPECT_EQ(big_render.status, 0) << big_render.err;
}

// A window asked for where there is no display (over ssh, say): GLFW's
// reason and the way out, in the host's one line.
TEST_F(Cli, AWindowWithNoDisplayIsOneLine) {
  const test::Outcome r = test::run_binary(good(), "unset DISPLAY WAYLAND_DISPLAY; ");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("raymarching: error: cannot open a window (X11: The DISPLAY environment variable is missing); "
                        "`raymarching render` needs none", 0), 0u) << r.err;
}

TEST_F(Cli, ShaderErrorDoesNotTouchAnExistingOutput) {
  write_file(dir_ / "bad.frag", "void mainImage(out vec4 c, in vec2 f) { c = nope; }\n");
  write_file(dir_ / "keep.png", "previous picture");
  test::Outcome r = run("render " + (dir_ / "bad.frag").string() + " -o " + (dir_ / "keep.png").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(test::read_file(dir_ / "keep.png"), "previous picture");
}

}  // namespace
}  // namespace rm
