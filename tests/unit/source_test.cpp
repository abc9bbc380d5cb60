// Preprocessor: includes, include-once, cycles, missing files, BOM, the
// three shader kinds, and the line map that keeps user line numbers true.
#include "core/check.h"
#include "core/source.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <algorithm>
#include <climits>

#include "core/files.h"
#include "core/glslang_client.h"
#include "core/glslviewer_passes.h"
#include "support.h"

namespace rm {
namespace {

using test::TempDir;
using test::write_file;

// The final line (1-based) whose text contains `needle`, or 0.
int final_line_of(const Source& s, const std::string& needle) {
  for (size_t i = 1; i <= s.line_map.size(); ++i)
    if (s.final_line_text(static_cast<int>(i)).find(needle) != std::string::npos) return static_cast<int>(i);
  return 0;
}

std::pair<std::string, int> origin_of(const Source& s, const std::string& needle) {
  return s.locate(final_line_of(s, needle));
}

const char* kMain = "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n";

TEST(Source, QuotedIncludeIsRelativeToTheIncludingFileAndNests) {
  TempDir dir;
  write_file(dir / "scene.frag", "// scene\n#include \"lib/a.glsl\"\nfloat s_marker;\n" + std::string(kMain));
  write_file(dir / "lib/a.glsl", "\n\nfloat a_marker;\n#include \"b.glsl\"\n");
  write_file(dir / "lib/b.glsl", "float b_marker;\n");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok()) << join(s.errors);
  EXPECT_EQ(origin_of(s, "a_marker"), std::make_pair((dir / "lib/a.glsl").string(), 3));
  EXPECT_EQ(origin_of(s, "b_marker"), std::make_pair((dir / "lib/b.glsl").string(), 1));
  EXPECT_EQ(origin_of(s, "s_marker"), std::make_pair((dir / "scene.frag").string(), 3));
  EXPECT_LT(final_line_of(s, "a_marker"), final_line_of(s, "b_marker"));
  EXPECT_LT(final_line_of(s, "b_marker"), final_line_of(s, "s_marker"));
  EXPECT_EQ(s.files.size(), 3u);
}

TEST(Source, IncludeDirsAndShaderlibAreSearched) {
  TempDir dir;
  write_file(dir / "scene.frag", "#include \"util.glsl\"\n#include <rm/lib.glsl>\n" + std::string(kMain));
  write_file(dir / "inc/util.glsl", "float util_marker;\n");
  write_file(dir / "shaderlib/rm/lib.glsl", "float lib_marker;\n");
  SourceOptions opts;
  opts.include_dirs = {dir / "inc"};
  opts.shaderlib_dir = dir / "shaderlib";
  Source s = preprocess(dir / "scene.frag", opts);
  ASSERT_TRUE(s.ok()) << join(s.errors);
  EXPECT_EQ(origin_of(s, "util_marker").first, (dir / "inc/util.glsl").string());
  EXPECT_EQ(origin_of(s, "lib_marker").first, (dir / "shaderlib/rm/lib.glsl").string());
}

TEST(Source, AngledIncludeDoesNotSearchTheIncludingDirectory) {
  TempDir dir;
  write_file(dir / "scene.frag", "#include <local.glsl>\n" + std::string(kMain));
  write_file(dir / "local.glsl", "float x;\n");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_EQ(s.errors.size(), 1u);
  EXPECT_EQ(s.errors[0].str(), (dir / "scene.frag").string() + ":1:10: error: cannot find include 'local.glsl'");
}

TEST(Source, EachFileIsIncludedOnce) {
  TempDir dir;
  write_file(dir / "scene.frag", "#include \"a.glsl\"\n#include \"b.glsl\"\n#include \"a.glsl\"\n" + std::string(kMain));
  write_file(dir / "a.glsl", "float once_marker;\n");
  write_file(dir / "b.glsl", "#include \"a.glsl\"\nfloat b_marker;\n");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok()) << join(s.errors);
  size_t first = s.text.find("once_marker");
  ASSERT_NE(first, std::string::npos);
  EXPECT_EQ(s.text.find("once_marker", first + 1), std::string::npos);
}

// The host expands includes before the compiler decides its #if branches:
// an include inside one is kept behind a guard of its own, so that the
// first one the compiler takes holds the file, and the rest are skipped.
TEST(Source, AnIncludeInAnIfBranchIsGuardedAndOneOutsideIsOnce) {
  TempDir dir;
  write_file(dir / "scene.frag", "#ifdef NOT_DEFINED\n#include \"a.glsl\"\n#endif\n#include \"a.glsl\"\n"
                                 "#include \"a.glsl\"\n#if 1\n#include \"a.glsl\"\n#endif\n" + std::string(kMain));
  write_file(dir / "a.glsl", "float a_marker;\n");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok()) << join(s.errors);
  // Twice: in the branch, and once more (guarded) outside it; then never.
  const size_t first = s.text.find("a_marker");
  ASSERT_NE(first, std::string::npos);
  const size_t second = s.text.find("a_marker", first + 1);
  ASSERT_NE(second, std::string::npos);
  EXPECT_EQ(s.text.find("a_marker", second + 1), std::string::npos) << s.text;
  EXPECT_EQ(std::count(s.files.begin(), s.files.end(), dir / "a.glsl"), 1) << "the file list names each file once";
  EXPECT_EQ(origin_of(s, "a_marker"), std::make_pair((dir / "a.glsl").string(), 1));
  EXPECT_EQ(s.locate(final_line_of(s, "#ifndef RM_INCLUDED_")), std::make_pair((dir / "scene.frag").string(), 2));
}

// A file's include guard is taken at its first include: what it includes
// is not in a branch, and is included once (shaderlib's modules all have one).
TEST(Source, AnIncludeGuardIsNoBranch) {
  TempDir dir;
  write_file(dir / "scene.frag", "#include \"a.glsl\"\n#include \"b.glsl\"\n" + std::string(kMain));
  write_file(dir / "a.glsl", "// a\n#ifndef A_GLSL\n#define A_GLSL\n#include \"common.glsl\"\n#endif\n");
  write_file(dir / "b.glsl", "/* b */\n  #  ifndef B_GLSL // why\n#define B_GLSL 1\n#include \"common.glsl\"\n#endif\n");
  write_file(dir / "common.glsl", "float common_marker;\n");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok()) << join(s.errors);
  const size_t first = s.text.find("common_marker");
  ASSERT_NE(first, std::string::npos);
  EXPECT_EQ(s.text.find("common_marker", first + 1), std::string::npos) << s.text;
  EXPECT_EQ(s.text.find("RM_INCLUDED_"), std::string::npos) << s.text;
}

// Lines inside a /* */ comment are no directives, however they look.
TEST(Source, AnIncludeInABlockCommentIsNone) {
  TempDir dir;
  write_file(dir / "scene.frag", "/* gone for now:\n#include \"gone.glsl\"\n  #include \"a.glsl\"\n*/\n" + std::string(kMain));
  write_file(dir / "a.glsl", "float a_marker;\n");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok()) << join(s.errors);
  EXPECT_EQ(s.text.find("a_marker"), std::string::npos);
  EXPECT_EQ(origin_of(s, "#include \"gone.glsl\""), std::make_pair((dir / "scene.frag").string(), 2));
}

TEST(Source, CycleIsAnErrorAtTheIncludingLine) {
  TempDir dir;
  write_file(dir / "scene.frag", "#include \"a.glsl\"\n" + std::string(kMain));
  write_file(dir / "a.glsl", "// a\n#include \"b.glsl\"\n");
  write_file(dir / "b.glsl", "\n\n  #include \"a.glsl\"\n");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_EQ(s.errors.size(), 1u);
  EXPECT_EQ(s.errors[0].str(), (dir / "b.glsl").string() + ":3:12: error: #include cycle: a.glsl -> b.glsl -> a.glsl");
}

TEST(Source, MissingIncludeNamesTheIncludingFileAndLineAndIsWatched) {
  TempDir dir;
  write_file(dir / "scene.frag", "\n#include \"lib/a.glsl\"\n" + std::string(kMain));
  write_file(dir / "lib/a.glsl", "float a;\n\n#include \"gone.glsl\"\n");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_EQ(s.errors.size(), 1u);
  EXPECT_EQ(s.errors[0].str(), (dir / "lib/a.glsl").string() + ":3:10: error: cannot find include 'gone.glsl'");
  // Creating the missing file must reload the scene, so it is watched.
  EXPECT_NE(std::find(s.watch.begin(), s.watch.end(), dir / "lib/gone.glsl"), s.watch.end());
}

// `#ifdef HAVE_NOISE` / `#include "noise.glsl"`: whether it is missing is
// for the compiler's branch to say (Check.AMissingIncludeIsAnErrorOnlyWhereItsBranchIsTaken).
TEST(Source, AMissingIncludeInAnIfBranchIsLeftToTheCompilerAndWatched) {
  TempDir dir;
  write_file(dir / "scene.frag", "#ifdef \\\nHAVE_NOISE\n  #include \"noise.glsl\"\n#endif\n" + std::string(kMain));
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok()) << join(s.errors);
  ASSERT_EQ(s.missing_includes.size(), 1u);
  EXPECT_EQ(s.missing_includes[0].str(), (dir / "scene.frag").string() + ":3:12: error: cannot find include 'noise.glsl'");
  EXPECT_EQ(origin_of(s, "#error rm_missing_include_0"), std::make_pair((dir / "scene.frag").string(), 3));
  EXPECT_NE(std::find(s.watch.begin(), s.watch.end(), dir / "noise.glsl"), s.watch.end());
}

TEST(Source, IncludingADirectoryIsAnError) {
  TempDir dir;
  write_file(dir / "scene.frag", "#include \"sub\"\n" + std::string(kMain));
  std::filesystem::create_directories(dir / "sub");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_EQ(s.errors.size(), 1u);
  EXPECT_EQ(s.errors[0].path, (dir / "scene.frag").string());
  EXPECT_EQ(s.errors[0].line, 1);
  EXPECT_NE(s.errors[0].message.find("is a directory"), std::string::npos);
}

TEST(Source, ByteOrderMarkIsStrippedAndVersionStillFound) {
  TempDir dir;
  write_file(dir / "scene.frag", "\xEF\xBB\xBF#version 330 core\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok()) << join(s.errors);
  EXPECT_EQ(s.kind, ShaderKind::Complete);
  EXPECT_EQ(s.text.find("\xEF\xBB\xBF"), std::string::npos);
  EXPECT_EQ(s.text.rfind("#version 330 core\n", 0), 0u);
  EXPECT_EQ(origin_of(s, "out vec4 o;").second, 2);
}

TEST(Source, ShadertoyWrapperDoesNotShiftUserLines) {
  TempDir dir;
  write_file(dir / "scene.frag", "// line 1\n// line 2\nfloat line3_marker;\n" + std::string(kMain));
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s.kind, ShaderKind::Shadertoy);
  EXPECT_GT(final_line_of(s, "line3_marker"), 3);  // host lines come first...
  EXPECT_EQ(origin_of(s, "line3_marker").second, 3);  // ...but the map says line 3
  EXPECT_NE(s.text.find("uniform vec3 iResolution;"), std::string::npos);
  EXPECT_NE(s.text.find("#define HW_PERFORMANCE 1"), std::string::npos);
  EXPECT_EQ(s.line_map.size(), static_cast<size_t>(std::count(s.text.begin(), s.text.end(), '\n')));
}

TEST(Source, DefinesFollowTheVersionLineAndMapToTheCommandLine) {
  TempDir dir;
  write_file(dir / "scene.frag", "#version 450\nout vec4 o;\nvoid main() { o = vec4(QUALITY); }\n");
  SourceOptions opts;
  opts.defines = {{"QUALITY", "2"}, {"FAST", ""}};
  Source s = preprocess(dir / "scene.frag", opts);
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s.final_line_text(1), "#version 450");
  EXPECT_EQ(origin_of(s, "#define QUALITY 2"), std::make_pair(std::string("<command-line>"), 1));
  EXPECT_EQ(origin_of(s, "#define FAST 1"), std::make_pair(std::string("<command-line>"), 2));
}

// GLSL makes a second #define of a macro an error, so -D STEPS=32 on a scene
// that says `#define STEPS 200` would only report a redefinition. The command
// line wins instead: the scene's #define (with the lines its backslash
// continues it onto) reads as blank lines, and every other line keeps its
// number.
TEST(Source, ADefineOnTheCommandLineTakesThePlaceOfTheScenesOwn) {
  TempDir dir;
  write_file(dir / "scene.frag",
             "#define STEPS 200\n#define WIDE \\\n  2.0\n#define KEEP 3\n"
             "void mainImage(out vec4 c, in vec2 f) { c = vec4(STEPS + KEEP, WIDE, 0.0, 1.0); }\n"
             "float broken = ;\n");
  SourceOptions opts;
  opts.defines = {{"STEPS", "32"}, {"WIDE", "1.0"}};
  Source s = preprocess(dir / "scene.frag", opts);
  ASSERT_TRUE(s.ok()) << join(s.errors);
  EXPECT_EQ(s.text.find("#define STEPS 200"), std::string::npos);
  EXPECT_EQ(s.text.find("2.0"), std::string::npos);
  EXPECT_NE(s.text.find("#define KEEP 3"), std::string::npos);
  EXPECT_EQ(origin_of(s, "float broken").second, 6);
  const Diagnostics diags = validate(s);
  ASSERT_EQ(count_errors(diags), 1) << join(diags);  // no redefinition: only the broken line
  EXPECT_EQ(diags[0].path, (dir / "scene.frag").string());
  EXPECT_EQ(diags[0].line, 6);
}

// The host's HW_PERFORMANCE (1, as Shadertoy on a desktop) gives way to a
// -D, so that a shader can be seen as a phone runs it, with no redefinition.
TEST(Source, HwPerformanceIsOneUnlessTheCommandLineSetsIt) {
  TempDir dir;
  write_file(dir / "scene.frag",
             "void mainImage(out vec4 c, in vec2 f) { c = vec4(HW_PERFORMANCE); }\n"
             "#if HW_PERFORMANCE == 0\nfloat phone;\n#endif\n");
  SourceOptions phone;
  phone.defines = {{"HW_PERFORMANCE", "0"}};
  const Source desktop_source = preprocess(dir / "scene.frag", {}), phone_source = preprocess(dir / "scene.frag", phone);
  ASSERT_TRUE(desktop_source.ok() && phone_source.ok());
  EXPECT_NE(desktop_source.text.find("#define HW_PERFORMANCE 1"), std::string::npos);
  EXPECT_EQ(phone_source.text.find("#define HW_PERFORMANCE 1"), std::string::npos);
  EXPECT_TRUE(validate(phone_source).empty()) << join(validate(phone_source));
  std::string desktop_active, phone_active;
  validate(desktop_source, &desktop_active);
  validate(phone_source, &phone_active);
  EXPECT_EQ(desktop_active.find("float phone"), std::string::npos);
  EXPECT_NE(phone_active.find("float phone"), std::string::npos);
}

// `undefines` drops a scene's #define without setting the macro (the
// accuracy report's textbook loop runs a scene without its bounds).
TEST(Source, UndefinesDropTheScenesDefinitionWithoutSettingIt) {
  TempDir dir;
  write_file(dir / "scene.frag",
             "#define RM_BOUNDING_SPHERE vec4(1.0)\n#ifdef RM_BOUNDING_SPHERE\nfloat bounded;\n#endif\n" +
                 std::string(kMain));
  SourceOptions opts;
  opts.undefines = {"RM_BOUNDING_SPHERE"};
  Source s = preprocess(dir / "scene.frag", opts);
  ASSERT_TRUE(s.ok()) << join(s.errors);
  EXPECT_EQ(s.text.find("#define RM_BOUNDING_SPHERE"), std::string::npos);
  EXPECT_EQ(origin_of(s, "float bounded").second, 3);
  EXPECT_TRUE(validate(s).empty());
}

// A -U reaches the scene's own files, not shaderlib's: its default for the
// macro holds, as if the scene had never defined it (a C compiler's -U,
// which undoes a definition given before it, leaves a header's own too).
TEST(Source, UndefinesLeaveShaderlibsOwnDefinitions) {
  TempDir dir;
  write_file(dir / "lib/rm/knob.glsl", "#ifndef KNOB\n#define KNOB 2.0\n#endif\nfloat knob() { return KNOB; }\n");
  write_file(dir / "scene.frag", "#define KNOB 3.0\n#include <rm/knob.glsl>\n" + std::string(kMain));
  SourceOptions opts;
  opts.shaderlib_dir = dir / "lib";
  opts.undefines = {"KNOB"};
  Source s = preprocess(dir / "scene.frag", opts);
  ASSERT_TRUE(s.ok()) << join(s.errors);
  EXPECT_EQ(s.text.find("#define KNOB 3.0"), std::string::npos);
  EXPECT_NE(s.text.find("#define KNOB 2.0"), std::string::npos);
  EXPECT_TRUE(validate(s).empty());
}

TEST(Source, LegacyGlslViewerShaderIsWrappedForCore) {
  TempDir dir;
  write_file(dir / "scene.frag",
             "#ifdef GL_ES\nprecision mediump float;\n#endif\nuniform vec2 u_resolution;\n"
             "void main() { gl_FragColor = texture2D(u_tex0, gl_FragCoord.xy / u_resolution); }\n");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s.kind, ShaderKind::Legacy);
  EXPECT_EQ(s.version_line, "#version 450 core");
  EXPECT_NE(s.text.find("#define gl_FragColor rm_FragColor"), std::string::npos);
  EXPECT_EQ(origin_of(s, "void main()").second, 5);
}

// glslViewer's passes are paths of their own: the file's, with the pass's name.
TEST(GlslViewerPasses, APassPathNamesItsFileAndDefine) {
  EXPECT_EQ(glslviewer_pass("/a/s.frag", "BUFFER_0"), fs::path("/a/s.frag#BUFFER_0"));
  const std::optional<GlslViewerPass> pass = glslviewer_pass_of("/a/s.frag#DOUBLE_BUFFER_12");
  ASSERT_TRUE(pass);
  EXPECT_EQ(pass->file, fs::path("/a/s.frag"));
  EXPECT_EQ(pass->name, "DOUBLE_BUFFER_12");
  EXPECT_EQ(pass->define, "DOUBLE_BUFFER_12");
  const std::optional<GlslViewerPass> scene = glslviewer_pass_of("/a/s.frag#SCENE");
  ASSERT_TRUE(scene);
  EXPECT_EQ(scene->name, "SCENE");
  EXPECT_EQ(scene->define, "");  // the scene pass is the file as it is
  for (const char* other :
       {"/a/s.frag", "/a/s.frag#FOO_0", "/a/s#BUFFER_0/t.frag", "/a/s.frag#BUFFER_", "/a/#BUFFER_0"})
    EXPECT_FALSE(glslviewer_pass_of(other)) << other;
  EXPECT_EQ(glslviewer_pass_read_by("u_buffer0"), "BUFFER_0");
  EXPECT_EQ(glslviewer_pass_read_by("u_doubleBuffer15"), "DOUBLE_BUFFER_15");
  EXPECT_EQ(glslviewer_pass_read_by("u_scene"), "SCENE");
  for (const char* other : {"u_buffer", "u_buffer0Resolution", "u_tex0", "u_sceneDepth", "buffer0"})
    EXPECT_EQ(glslviewer_pass_read_by(other), "") << other;
}

// Each buffer sampler a pass reads, in the #if branches its defines take,
// is bound on a free channel (from 3 down; u_tex1 keeps 1) to its pass; the
// pass that draws the file with BUFFER_0 has that define, after the -D ones.
TEST(Source, GlslViewerBufferReadsBindAFreeChannelToTheirPass) {
  TempDir dir;
  write_file(dir / "gv.frag",
             "uniform sampler2D u_buffer0;\nuniform sampler2D u_doubleBuffer1;\nuniform sampler2D u_buffer2;\n"
             "uniform sampler2D u_tex1;\n#pragma channel2 \"rock.png\"\n"
             "void main() {\n#ifdef BUFFER_0\n  gl_FragColor = texture2D(u_doubleBuffer1, vec2(0.5));\n#else\n"
             "  gl_FragColor = texture2D(u_buffer0, vec2(0.5)) + texture2D(u_tex1, vec2(0.5));\n#endif\n}\n");
  write_file(dir / "rock.png", "");
  const fs::path file = fs::absolute(dir / "gv.frag").lexically_normal();
  const Source image = preprocess(file, {});
  ASSERT_TRUE(image.ok()) << join(image.errors);
  EXPECT_EQ(image.channels[3].kind, ChannelSpec::Kind::Pass);
  EXPECT_EQ(image.channels[3].path, glslviewer_pass(file, "BUFFER_0"));
  EXPECT_EQ(image.channels[3].sampler_name, "u_buffer0");
  EXPECT_EQ(image.channels[3].sampler, (Sampler{Sampler::Filter::Linear, Sampler::Wrap::Clamp, false}));
  EXPECT_EQ(image.channels[0].kind, ChannelSpec::Kind::None);  // u_doubleBuffer1 and u_buffer2 are not read here
  EXPECT_EQ(image.channels[2].kind, ChannelSpec::Kind::Image);  // the pragma's
  SourceOptions options;
  options.defines = {{"A", "2"}};
  const Source buffer = preprocess(glslviewer_pass(file, "BUFFER_0"), options);
  ASSERT_TRUE(buffer.ok()) << join(buffer.errors);
  EXPECT_EQ(buffer.files.front(), file);
  EXPECT_LT(buffer.text.find("#define A 2\n"), buffer.text.find("#define BUFFER_0\n"));
  EXPECT_EQ(buffer.channels[3].path, glslviewer_pass(file, "DOUBLE_BUFFER_1"));
  EXPECT_EQ(buffer.channels[3].sampler_name, "u_doubleBuffer1");
  EXPECT_EQ(buffer.channels[0].kind, ChannelSpec::Kind::None);
  EXPECT_EQ(origin_of(buffer, "gl_FragColor = texture2D(u_doubleBuffer1"), std::make_pair(file.string(), 8));
  EXPECT_EQ(join(validate(buffer)), "");
}

// One declaration may name several samplers: each is bound as if it had a
// line of its own, and one no channel binds is warned of at its own column.
TEST(Source, EachSamplerOfOneDeclarationIsBound) {
  TempDir dir;
  write_file(dir / "gv.frag",
             "uniform sampler2D u_buffer0, u_buffer1 , stray[2];\nuniform highp sampler2D u_buffer2;\n"
             "void main() {\n  gl_FragColor = texture2D(u_buffer0, vec2(0.5)) + texture2D(u_buffer1, vec2(0.5))"
             " + texture2D(stray[1], vec2(0.5)) + texture2D(u_buffer2, vec2(0.5));\n}\n");
  const fs::path file = fs::absolute(dir / "gv.frag").lexically_normal();
  const Source image = preprocess(file, {});
  ASSERT_TRUE(image.ok()) << join(image.errors);
  EXPECT_EQ(image.channels[3].path, glslviewer_pass(file, "BUFFER_0"));
  EXPECT_EQ(image.channels[3].sampler_name, "u_buffer0");
  EXPECT_EQ(image.channels[2].path, glslviewer_pass(file, "BUFFER_1"));
  EXPECT_EQ(image.channels[2].sampler_name, "u_buffer1");
  EXPECT_EQ(image.channels[1].path, glslviewer_pass(file, "BUFFER_2"));  // after a precision
  EXPECT_EQ(image.channels[0].kind, ChannelSpec::Kind::None);
  std::array<bool, 4> bound{};
  for (size_t c = 0; c < 4; ++c) bound[c] = image.channels[c].kind != ChannelSpec::Kind::None;
  const std::string warnings = join(unbound_channel_reads(image, bound));
  EXPECT_NE(warnings.find(file.string() + ":1:42: warning: 'stray'"), std::string::npos) << warnings;
  EXPECT_EQ(warnings.find("u_buffer"), std::string::npos) << warnings;
}

// A declaration's names may go on over lines: each is bound, and a stray
// one is warned of on its own line. One without its ';' takes no names from
// the code after it.
TEST(Source, ASamplerDeclarationOverLinesBindsEachName) {
  TempDir dir;
  write_file(dir / "gv.frag",
             "uniform sampler2D u_buffer0,\n"
             "                  u_buffer1;\n"
             "uniform highp sampler2D\n"
             "  u_buffer2,\n"
             "  stray;\n"
             "void main() {\n  gl_FragColor = texture2D(u_buffer0, vec2(0.5)) + texture2D(u_buffer1, vec2(0.5))"
             " + texture2D(u_buffer2, vec2(0.5)) + texture2D(stray, vec2(0.5));\n}\n");
  const fs::path file = fs::absolute(dir / "gv.frag").lexically_normal();
  const Source image = preprocess(file, {});
  ASSERT_TRUE(image.ok()) << join(image.errors);
  EXPECT_EQ(image.channels[3].sampler_name, "u_buffer0");
  EXPECT_EQ(image.channels[2].sampler_name, "u_buffer1");
  EXPECT_EQ(image.channels[2].path, glslviewer_pass(file, "BUFFER_1"));
  EXPECT_EQ(image.channels[1].sampler_name, "u_buffer2");
  EXPECT_EQ(image.channels[1].path, glslviewer_pass(file, "BUFFER_2"));
  std::array<bool, 4> bound{};
  for (size_t c = 0; c < 4; ++c) bound[c] = image.channels[c].kind != ChannelSpec::Kind::None;
  const std::string warnings = join(unbound_channel_reads(image, bound));
  EXPECT_NE(warnings.find(file.string() + ":5:3: warning: 'stray'"), std::string::npos) << warnings;

  write_file(dir / "broken.frag",
             "uniform sampler2D u_tex0\n"
             "float a, b;\n"
             "void main() { gl_FragColor = texture2D(u_tex0, vec2(a, b)); }\n");
  const Source broken = preprocess(fs::absolute(dir / "broken.frag"), {});
  const std::string said = join(unbound_channel_reads(broken, {}));
  EXPECT_NE(said.find("broken.frag:1:19: warning: u_tex0 is read"), std::string::npos) << said;
  EXPECT_EQ(said.find("warning: 'b'"), std::string::npos) << said;
}

// A buffer's own size: `size=WxH` or `scale=F` in a #pragma channelN (for
// a buffer or `self`), and glslViewer's comment after a buffer's
// declaration, `// 512x512` or `// 0.5`; a comment that starts with a
// number and is neither is an error at it.
TEST(Source, ABufferHasASizeOfItsOwnByPragmaOrGlslViewerComment) {
  TempDir dir;
  write_file(dir / "a.frag", kMain);
  write_file(dir / "scene.frag", "#pragma channel0 \"a.frag\" size=256x128 filter=nearest\n"
                                 "#pragma channel1 self scale=0.25\n" + std::string(kMain));
  const Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok()) << join(s.errors);
  EXPECT_EQ(s.channels[0].buffer_size, (BufferSize{256, 128, 0}));
  EXPECT_EQ(s.channels[0].sampler.filter, Sampler::Filter::Nearest);
  EXPECT_EQ(s.channels[1].buffer_size, (BufferSize{0, 0, 0.25}));
  EXPECT_EQ(channel_spec_text(s.channels[0], "a.frag"), "\"a.frag\" size=256x128 filter=nearest");
  for (const auto& [pragma, message] : std::vector<std::pair<std::string, std::string>>{
           {"\"a.frag\" size=0x4", "size=WxH expects a width and a height from 1 to 4096, not '0x4'"},
           {"\"a.frag\" size=4097x4", "size=WxH expects a width and a height from 1 to 4096, not '4097x4'"},
           {"\"a.frag\" size=16", "size=WxH expects a width and a height from 1 to 4096, not '16'"},
           {"\"a.frag\" scale=1.5", "scale=F expects a share of the picture's size above 0 and at most 1, not '1.5'"},
           {"\"a.frag\" scale=nan", "scale=F expects a share of the picture's size above 0 and at most 1, not 'nan'"},
           {"\"rock.png\" size=4x4", "unknown channel setting 'size=4x4'"},
       }) {
    write_file(dir / "bad.frag", "#pragma channel0 " + pragma + "\n" + std::string(kMain));
    const Source bad = preprocess(dir / "bad.frag", {});
    ASSERT_EQ(bad.errors.size(), 1u) << pragma;
    EXPECT_NE(bad.errors[0].message.find(message), std::string::npos) << bad.errors[0].message;
  }

  write_file(dir / "gv.frag",
             "uniform sampler2D u_buffer0; // 512x256\n"
             "uniform sampler2D u_buffer1  ;  //  .5 of the window\n"
             "uniform sampler2D u_buffer2; // the trail, at the window's size\n"
             "void main() {\n  gl_FragColor = texture2D(u_buffer0, vec2(0.5)) + texture2D(u_buffer1, vec2(0.5))"
             " + texture2D(u_buffer2, vec2(0.5));\n}\n");
  const Source gv = preprocess(fs::absolute(dir / "gv.frag").lexically_normal(), {});
  ASSERT_TRUE(gv.ok()) << join(gv.errors);
  EXPECT_EQ(gv.channels[3].sampler_name, "u_buffer0");
  EXPECT_EQ(gv.channels[3].buffer_size, (BufferSize{512, 256, 0}));
  EXPECT_EQ(gv.channels[2].buffer_size, (BufferSize{0, 0, 0.5}));
  EXPECT_FALSE(gv.channels[1].buffer_size.given());
  write_file(dir / "gv.frag", "uniform sampler2D u_buffer0; // 512 x 512\n"
                              "void main() { gl_FragColor = texture2D(u_buffer0, vec2(0.5)); }\n");
  const Source wrong = preprocess(dir / "gv.frag", {});
  ASSERT_EQ(wrong.errors.size(), 1u);
  EXPECT_EQ(wrong.errors[0].line, 1);
  EXPECT_EQ(wrong.errors[0].column, 33);
  EXPECT_EQ(wrong.errors[0].message, "the size of 'u_buffer0' after its declaration is WxH (each from 1 to 4096) or a "
                                     "share of the picture's (above 0, at most 1), not '512'");
}

// A shader with a POSTPROCESSING branch is drawn so, and its u_scene reads
// the scene pass: the file with no define, which defines no POSTPROCESSING.
TEST(Source, AGlslViewerPostprocessingBranchReadsTheScenePass) {
  TempDir dir;
  write_file(dir / "post.frag",
             "uniform sampler2D u_scene;\nuniform vec2 u_resolution;\nvoid main() {\n"
             "  #if defined( POSTPROCESSING )\n  gl_FragColor = 1.0 - texture2D(u_scene, vec2(0.5));\n"
             "  #else\n  gl_FragColor = vec4(0.25);\n  #endif\n}\n");
  const fs::path file = fs::absolute(dir / "post.frag").lexically_normal();
  const Source image = preprocess(file, {});
  ASSERT_TRUE(image.ok()) << join(image.errors);
  EXPECT_NE(image.text.find("#define POSTPROCESSING\n"), std::string::npos);
  EXPECT_EQ(image.channels[3].path, glslviewer_pass(file, "SCENE"));
  EXPECT_EQ(image.channels[3].sampler_name, "u_scene");
  const Source scene = preprocess(glslviewer_pass(file, "SCENE"), {});
  ASSERT_TRUE(scene.ok()) << join(scene.errors);
  EXPECT_EQ(scene.text.find("#define POSTPROCESSING"), std::string::npos);
  EXPECT_EQ(scene.channels[3].kind, ChannelSpec::Kind::None);
  EXPECT_EQ(join(validate(image)), "");
  EXPECT_EQ(join(validate(scene)), "");
}

// GLSL 1.10's sampling functions, each form of each, on a 4.50 core profile.
TEST(Source, LegacySamplingFunctionsValidate) {
  TempDir dir;
  write_file(dir / "scene.frag",
             "uniform sampler2D a;\nuniform sampler3D b;\nuniform samplerCube c;\nvoid main() {\n"
             "  vec2 p = vec2(0.5);\n  vec4 v = texture2D(a, p) + texture2D(a, p, 1.0)\n"
             "    + texture2DProj(a, p.xyx) + texture2DProj(a, p.xyxy) + texture2DProj(a, p.xyx, 1.0)\n"
             "    + texture2DProj(a, p.xyxy, 1.0) + texture2DLod(a, p, 2.0) + texture2DProjLod(a, p.xyx, 2.0)\n"
             "    + texture2DProjLod(a, p.xyxy, 2.0) + texture3D(b, p.xyx) + texture3D(b, p.xyx, 1.0)\n"
             "    + texture3DLod(b, p.xyx, 2.0) + textureCube(c, p.xyx) + textureCube(c, p.xyx, 1.0)\n"
             "    + textureCubeLod(c, p.xyx, 2.0);\n  gl_FragColor = v;\n}\n");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok()) << join(s.errors);
  EXPECT_EQ(s.kind, ShaderKind::Legacy);
  EXPECT_EQ(join(validate(s)), "");
}

// Shadertoy's GLSL ES 3.00 and glslViewer's GLSL 1.10 leave words free
// that 4.50 core reserves: code that names a variable so runs as it does
// there, and an error about that variable names it as the code spells it.
TEST(Source, NamesTheOlderDialectsAllowCompile) {
  TempDir dir;
  write_file(dir / "toy.frag",
             "void mainImage(out vec4 c, in vec2 f) {\n  vec4 buffer = texture(iChannel0, f);\n"
             "  float precise = 0.5;\n  c = buffer * precise;\n}\n");
  Source toy = preprocess(dir / "toy.frag", {});
  ASSERT_TRUE(toy.ok()) << join(toy.errors);
  EXPECT_EQ(toy.renamed, (std::vector<std::string>{"buffer", "precise"}));
  EXPECT_EQ(join(validate(toy)), "");

  write_file(dir / "viewer.frag",
             "uniform sampler2D u_tex0;\nvoid main() {\n  vec4 sample = texture2D(u_tex0, vec2(0.5));\n"
             "  float smooth = 0.5, flat = 2.0;\n  gl_FragColor = sample * smooth * flat;\n}\n");
  Source viewer = preprocess(dir / "viewer.frag", {});
  ASSERT_TRUE(viewer.ok()) << join(viewer.errors);
  EXPECT_EQ(viewer.kind, ShaderKind::Legacy);
  EXPECT_EQ(join(validate(viewer)), "");

  // `texture` names a sampler, and its misuse is named as the code spells it.
  write_file(dir / "viewer.frag",
             "uniform sampler2D texture;\nvoid main() {\n  gl_FragColor = texture2D(texture, vec2(0.5));\n}\n");
  viewer = preprocess(dir / "viewer.frag", {});
  EXPECT_EQ(viewer.renamed, (std::vector<std::string>{"texture"}));
  EXPECT_EQ(join(validate(viewer)), "");
  write_file(dir / "viewer.frag",
             "uniform sampler2D texture;\nfloat texture;\nvoid main() {\n  gl_FragColor = texture2D(texture, vec2(0.5));\n}\n");
  EXPECT_EQ(join(validate(preprocess(dir / "viewer.frag", {}))),
            (dir / "viewer.frag").string() + ":2:7: error: 'texture' : redefinition\n");
  // A call of texture() is 4.50's function, and the word is not renamed.
  write_file(dir / "viewer.frag",
             "uniform sampler2D u_tex0;\nvoid main() {\n  gl_FragColor = texture(u_tex0, vec2(0.5));\n}\n");
  viewer = preprocess(dir / "viewer.frag", {});
  EXPECT_TRUE(viewer.renamed.empty());
  EXPECT_EQ(join(validate(viewer)), "");

  write_file(dir / "toy.frag",
             "void mainImage(out vec4 c, in vec2 f) {\n  vec4 buffer = vec4(1.0);\n  float buffer = 2.0;\n"
             "  c = buffer;\n}\n");
  EXPECT_EQ(join(validate(preprocess(dir / "toy.frag", {}))),
            (dir / "toy.frag").string() + ":3:9: error: 'buffer' : redefinition\n");
}

// An #extension must precede every declaration, and the host's come before
// the scene's: the extensions that open the scene move up to follow the
// #version, and keep their file and line. One in an #if, or after the first
// declaration, stays where it is.
TEST(Source, ExtensionsThatOpenTheSceneFollowTheVersionLine) {
  TempDir dir;
  write_file(dir / "scene.frag",
             "// derivatives\n#extension GL_OES_standard_derivatives : enable\n#ifdef GL_ES\n"
             "#extension GL_EXT_shader_texture_lod : require\n#endif\n/* lod */ #extension all : warn\n"
             "float x;\n#extension GL_late : enable\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(x); }\n");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok()) << join(s.errors);
  EXPECT_EQ(s.final_line_text(2), "#extension GL_OES_standard_derivatives : enable");
  EXPECT_EQ(s.locate(2), std::make_pair((dir / "scene.frag").string(), 2));
  EXPECT_EQ(s.final_line_text(3), "/* lod */ #extension all : warn");
  EXPECT_EQ(s.locate(3), std::make_pair((dir / "scene.frag").string(), 6));
  EXPECT_EQ(origin_of(s, "GL_EXT_shader_texture_lod"), std::make_pair((dir / "scene.frag").string(), 4));
  EXPECT_GT(final_line_of(s, "GL_EXT_shader_texture_lod"), final_line_of(s, "uniform vec3 iResolution"));
  EXPECT_EQ(origin_of(s, "GL_late"), std::make_pair((dir / "scene.frag").string(), 8));
  EXPECT_EQ(origin_of(s, "float x;"), std::make_pair((dir / "scene.frag").string(), 7));
  EXPECT_EQ(origin_of(s, "void mainImage"), std::make_pair((dir / "scene.frag").string(), 9));
}

// glslViewer's vertex shader gives v_texcoord; the host's gives nothing, so
// the declaration goes and the name reads gl_FragCoord through the host.
TEST(Source, GlslViewersTexcoordIsTheFragmentsPlace) {
  TempDir dir;
  write_file(dir / "scene.frag",
             "uniform vec2 u_resolution;\nvarying highp vec2  v_texcoord ; // from the vertex shader\n"
             "void main() { gl_FragColor = vec4(v_texcoord, 0.0, 1.0); }\n");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok()) << join(s.errors);
  EXPECT_EQ(final_line_of(s, "varying highp"), 0) << "the declaration is taken out";
  EXPECT_EQ(origin_of(s, "void main()"), std::make_pair((dir / "scene.frag").string(), 3));
  EXPECT_NE(s.text.find("#define v_texcoord (gl_FragCoord.xy / rm_Resolution)"), std::string::npos);
  EXPECT_NE(s.text.find("#define gl_FragCoord (gl_FragCoord + vec4(rm_FragCoordOffset"), std::string::npos);
  EXPECT_EQ(join(validate(s)), "");

  // A mainImage for another host in an inactive block: still glslViewer's,
  // and its lines are where they were.
  write_file(dir / "scene.frag",
             "#ifdef SHADERTOY\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n#endif\n"
             "varying vec2 v_texcoord;\nvoid main() { gl_FragColor = vec4(v_texcoord, 0.0, 1.0); }\n");
  s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok()) << join(s.errors);
  EXPECT_EQ(s.kind, ShaderKind::Legacy);
  EXPECT_EQ(final_line_of(s, "varying vec2"), 0);
  EXPECT_EQ(origin_of(s, "#ifdef SHADERTOY"), std::make_pair((dir / "scene.frag").string(), 1));
  EXPECT_EQ(join(validate(s)), "");

  // Not glslViewer's (a vec3), or in a Shadertoy shader: the code's own.
  write_file(dir / "scene.frag", "in vec3 v_texcoord;\nvoid main() { gl_FragColor = vec4(v_texcoord, 1.0); }\n");
  EXPECT_EQ(preprocess(dir / "scene.frag", {}).text.find("rm_Resolution"), std::string::npos);
}

TEST(Source, OldVersionLineIsTreatedAsLegacy) {
  TempDir dir;
  write_file(dir / "scene.frag", "#version 120\nvoid main() { gl_FragColor = vec4(1.0); }\n");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s.kind, ShaderKind::Legacy);
  EXPECT_EQ(s.text.find("#version 120"), std::string::npos);
}

TEST(Source, MainImageInACommentDoesNotMakeAShadertoyShader) {
  TempDir dir;
  write_file(dir / "scene.frag", "#version 330\n// mainImage(\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n");
  EXPECT_EQ(preprocess(dir / "scene.frag", {}).kind, ShaderKind::Complete);
}

TEST(Source, NeitherMainNorMainImageIsAnError) {
  TempDir dir;
  write_file(dir / "scene.frag", "float f() { return 1.0; }\n");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_EQ(s.errors.size(), 1u);
  EXPECT_NE(s.errors[0].str().find("neither mainImage"), std::string::npos);
}

TEST(Source, CrLfLineEndingsKeepLineNumbers) {
  TempDir dir;
  write_file(dir / "scene.frag", "// a\r\n// b\r\nfloat crlf_marker;\r\n" + std::string(kMain));
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(origin_of(s, "crlf_marker").second, 3);
  EXPECT_EQ(s.text.find('\r'), std::string::npos);
}

TEST(Source, InMemoryFileSystemIsUsedForEveryRead) {
  FileSystem memory;
  memory.read = [](const fs::path& p, Diagnostic* why) -> std::optional<std::string> {
    if (p == "/mem/scene.frag") return std::string("#include \"x.glsl\"\n") + kMain;
    if (p == "/mem/x.glsl") return std::string("float mem_marker;\n");
    why->message = "no such file";
    return std::nullopt;
  };
  memory.exists = [](const fs::path& p) { return p == "/mem/scene.frag" || p == "/mem/x.glsl"; };
  Source s = preprocess("/mem/scene.frag", {}, memory);
  ASSERT_TRUE(s.ok()) << join(s.errors);
  EXPECT_EQ(origin_of(s, "mem_marker"), std::make_pair(std::string("/mem/x.glsl"), 1));
}

// An include the machine could not read (no file descriptor left) leaves
// the shader unchecked, an I/O error (status 2); a missing one is the
// shader's error (status 1), as for a C compiler.
TEST(SourceDeathTest, AnIncludeTheMachineCouldNotReadLeavesTheShaderUnchecked) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  TempDir dir;
  write_file(dir / "x.glsl", "float x_marker;\n");
  const fs::path scene = dir / "scene.frag";
  FileSystem files = disk_file_system();
  files.read = [scene, disk = files.read](const fs::path& path, Diagnostic* why) -> std::optional<std::string> {
    if (path == scene) return "#include \"x.glsl\"\n#include \"gone.glsl\"\n" + std::string(kMain);
    return disk(path, why);
  };
  files.exists = [](const fs::path&) { return true; };
  const Source missing = preprocess(scene, {}, files);
  ASSERT_EQ(missing.errors.size(), 1u) << join(missing.errors);
  EXPECT_NE(missing.errors[0].message.find("gone.glsl': no such file"), std::string::npos) << join(missing.errors);
  EXPECT_EQ(build_failure_status(missing.errors), kExitShaderError);
  EXPECT_EXIT(
      {
        rlimit few{};
        few.rlim_cur = few.rlim_max = 64;
        setrlimit(RLIMIT_NOFILE, &few);
        while (open("/dev/null", O_RDONLY | O_CLOEXEC) >= 0) {
        }
        const Source starved = preprocess(scene, {}, files);
        std::fputs(join(starved.errors).c_str(), stderr);
        std::_Exit(build_failure_status(starved.errors));
      },
      testing::ExitedWithCode(kExitUsage), "scene.frag:1:10: error: cannot read include '.*x.glsl': Too many open files");
}

TEST(Source, ChannelPragmaNamesADefaultImageRelativeToItsFile) {
  TempDir dir;
  write_file(dir / "scene.frag", "#include \"lib/look.glsl\"\n#pragma channel2 \"tex.png\"  // fallback\n"
                                 "#pragma optimize(off)\nfloat s_marker;\n" + std::string(kMain));
  write_file(dir / "lib/look.glsl", "#pragma channel0 \"wood.png\"\nfloat l_marker;\n");
  write_file(dir / "tex.png", "x");
  write_file(dir / "lib/wood.png", "x");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok()) << join(s.errors);
  EXPECT_EQ(s.channels[0].path, dir / "lib/wood.png");
  EXPECT_EQ(s.channels[1].kind, ChannelSpec::Kind::None);
  EXPECT_EQ(s.channels[2].path, dir / "tex.png");
  EXPECT_EQ(s.text.find("channel"), std::string::npos) << "the driver never sees the pragma";
  EXPECT_NE(s.text.find("#pragma optimize(off)"), std::string::npos) << "other pragmas pass through";
  EXPECT_EQ(origin_of(s, "s_marker"), std::make_pair((dir / "scene.frag").string(), 4));
  EXPECT_EQ(origin_of(s, "l_marker"), std::make_pair((dir / "lib/look.glsl").string(), 2));
  EXPECT_NE(std::find(s.watch.begin(), s.watch.end(), dir / "tex.png"), s.watch.end());
}

TEST(Source, MissingOrMalformedChannelPragmaIsAnErrorAtItsLine) {
  TempDir dir;
  write_file(dir / "a.frag", "\n  #pragma channel1 \"missing.png\"\n" + std::string(kMain));
  write_file(dir / "b.frag", "#pragma channel4 \"x.png\"\n" + std::string(kMain));
  write_file(dir / "c.frag", "#pragma channel0 x.png\n" + std::string(kMain));
  Source a = preprocess(dir / "a.frag", {});
  ASSERT_EQ(a.errors.size(), 1u);
  EXPECT_EQ(a.errors[0].str(), (dir / "a.frag").string() + ":2:3: error: cannot find channel image 'missing.png'");
  for (const char* name : {"b.frag", "c.frag"}) {
    Source s = preprocess(dir / name, {});
    ASSERT_EQ(s.errors.size(), 1u) << name;
    EXPECT_EQ(s.errors[0].line, 1) << name;
    EXPECT_NE(s.errors[0].message.find("#pragma channelN expects"), std::string::npos) << name;
  }
}

// A #pragma channelN in an #if branch binds only where the compiler takes
// that branch, and its missing file is an error only there (the host read
// every one, and the last won: `#else` always, and a missing file in a
// branch not taken failed the scene).
TEST(Source, AChannelPragmaInAnIfBranchBindsOnlyWhereTheCompilerTakesIt) {
  TempDir dir;
  write_file(dir / "scene.frag", "#ifdef HQ\n#pragma channel0 \"big.png\"\n#else\n#pragma channel0 \"small.png\"\n#endif\n"
                                 "#if defined(USE_ROCK) && USE_ROCK > 1\n  #pragma channel1 \"rock.png\"\n#endif\n"
                                 "#include \"look.glsl\"\n#pragma channel3 \"c.png\"\n" + std::string(kMain));
  write_file(dir / "look.glsl", "#ifndef LOOK\n#define LOOK\n#pragma channel2 \"small.png\"\n"
                                "#ifdef HQ\n#pragma channel3 \"big.png\"\n#endif\n#endif\n");
  for (const char* name : {"big.png", "small.png", "c.png"}) write_file(dir / name, "x");
  const auto with = [&](std::vector<Define> defines) {
    SourceOptions options;
    options.defines = std::move(defines);
    return preprocess(dir / "scene.frag", options);
  };
  const Source plain = with({});
  ASSERT_TRUE(plain.ok()) << join(plain.errors);
  EXPECT_EQ(plain.channels[0].path, dir / "small.png");
  EXPECT_EQ(plain.channels[1].kind, ChannelSpec::Kind::None);
  EXPECT_EQ(plain.channels[2].path, dir / "small.png");
  EXPECT_EQ(plain.channels[3].path, dir / "c.png");
  EXPECT_NE(std::find(plain.watch.begin(), plain.watch.end(), dir / "rock.png"), plain.watch.end())
      << "creating it, or taking its branch, reloads";
  EXPECT_EQ(plain.text.find("rm_channel_pragma"), std::string::npos) << "the mark is for the preprocessor alone";

  const Source hq = with({{"HQ", ""}, {"USE_ROCK", "1"}});
  ASSERT_TRUE(hq.ok()) << join(hq.errors);
  EXPECT_EQ(hq.channels[0].path, dir / "big.png");
  EXPECT_EQ(hq.channels[1].kind, ChannelSpec::Kind::None);
  EXPECT_EQ(hq.channels[3].path, dir / "c.png") << "a later pragma outside a branch still wins";

  const Source rock = with({{"USE_ROCK", "2"}});
  ASSERT_EQ(rock.errors.size(), 1u) << join(rock.errors);
  EXPECT_EQ(rock.errors[0].str(), (dir / "scene.frag").string() + ":7:3: error: cannot find channel image 'rock.png'");
}

// A scene whose kind and whose channel pragmas both depend on its #if
// branches asks glslang's preprocessor once for both: each ask is a round
// trip to the worker, on every reload.
TEST(Source, TheKindAndTheChannelPragmasAskThePreprocessorOnce) {
  TempDir dir;
  write_file(dir / "scene.frag", "#ifdef HQ\n#pragma channel0 \"big.png\"\n#endif\n" + std::string(kMain) +
                                     "#ifdef GLSLVIEWER\nvoid main() { mainImage(gl_FragColor, gl_FragCoord.xy); }\n#endif\n");
  write_file(dir / "big.png", "x");
  for (const bool hq : {false, true}) {
    SourceOptions options;
    if (hq) options.defines = {{"HQ", ""}};
    const long before = glslang_requests();
    const Source s = preprocess(dir / "scene.frag", options);
    ASSERT_TRUE(s.ok()) << join(s.errors);
    EXPECT_EQ(s.kind, ShaderKind::Shadertoy);
    EXPECT_EQ(s.channels[0].kind, hq ? ChannelSpec::Kind::Image : ChannelSpec::Kind::None);
    EXPECT_EQ(glslang_requests() - before, 1) << (hq ? "with" : "without") << " HQ";
  }
}

// Found by the fuzzer (tests/fuzz): a #version number too large for an int
// made std::stoi throw, and the program abort.
TEST(Source, HugeVersionNumberDoesNotThrow) {
  TempDir dir;
  write_file(dir / "v.frag", "#version 3000000000000 \nvoid main() {}\n");
  Source s;
  EXPECT_NO_THROW(s = preprocess(dir / "v.frag", {}));
}

TEST(Source, UnreadableSceneIsOneError) {
  Source s = preprocess("/nonexistent/scene.frag", {});
  ASSERT_EQ(s.errors.size(), 1u);
  EXPECT_EQ(s.errors[0].str(), "/nonexistent/scene.frag: error: cannot read scene: no such file");
}

// Directives are read by core/lexing, not std::regex: the spellings the
// regexes took, and a line too long for them (it overflowed the stack).
TEST(Source, DirectivesInEverySpellingAndAnyLength) {
  TempDir dir;
  write_file(dir / "a.glsl", "float a_marker;\n");
  write_file(dir / "b.glsl", "float b_marker;\n");
  write_file(dir / "c.png", "");
  write_file(dir / "scene.frag", "#version 300 es // a comment\n"
                                 "  #  include \"a.glsl\"   // why\n"
                                 "#include<b.glsl>\n"
                                 "#pragma channel2 \"c.png\" // default\n"
                                 "#pragma channels are not ours\n"
                                 "\t\f\v#include \"a.glsl\"\n"
                                 "float" + std::string(200000, ' ') + "wide;\n"
                                 "void\n  main (\n) {}\n");
  SourceOptions options;
  options.include_dirs = {dir.path()};
  Source s = preprocess(dir / "scene.frag", options);
  ASSERT_TRUE(s.ok()) << join(s.errors);
  EXPECT_EQ(s.version_line, "#version 300 es");
  EXPECT_EQ(s.kind, ShaderKind::Complete);
  EXPECT_EQ(origin_of(s, "a_marker").second, 1);
  EXPECT_EQ(origin_of(s, "b_marker").second, 1);
  EXPECT_EQ(s.channels[2].path, dir / "c.png");
  EXPECT_EQ(origin_of(s, "#pragma channels").second, 5);
  // Form feed and vertical tab, blanks to GLSL but not to glslang, are spaces.
  EXPECT_EQ(s.text.find_first_of("\f\v"), std::string::npos);
  EXPECT_EQ(origin_of(s, "wide;").second, 7);
}

TEST(Source, MalformedIncludesAndWordsThatOnlyLookLikeMain) {
  TempDir dir;
  write_file(dir / "a.frag", "#include lib.glsl\n" + std::string(kMain));
  write_file(dir / "b.frag", "#include \"\"\n" + std::string(kMain));
  write_file(dir / "c.frag", "#include \"x.glsl\" trailing\n" + std::string(kMain));
  for (const char* name : {"a.frag", "b.frag", "c.frag"}) {
    Source s = preprocess(dir / name, {});
    ASSERT_EQ(s.errors.size(), 1u) << name;
    EXPECT_EQ(s.errors[0].str(), (dir / name).string() + ":1:10: error: #include expects \"FILE\" or <FILE>");
  }
  write_file(dir / "d.frag", "void voidmain() {}\nvoid main_() {}\nint mainImages;\n");
  EXPECT_FALSE(preprocess(dir / "d.frag", {}).ok());
}

// Files that are not regular, and files over the size limit, are refused by
// what they are before a byte is read.
TEST(Source, OnlyRegularFilesUpToTheLimitAreRead) {
  TempDir dir;
  ASSERT_EQ(mkfifo((dir / "fifo.glsl").c_str(), 0644), 0);
  write_file(dir / "fifo.frag", "#include \"fifo.glsl\"\n" + std::string(kMain));
  write_file(dir / "zero.frag", "\n#include \"/dev/zero\"\n" + std::string(kMain));
  write_file(dir / "big.glsl", std::string(kMaxShaderBytes + 1, ' '));
  write_file(dir / "big.frag", "#include \"big.glsl\"\n" + std::string(kMain));
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"fifo.frag", ":1:10: error: cannot read include '" + (dir / "fifo.glsl").string() +
                        "': is a named pipe (FIFO), not a regular file"},
      {"zero.frag", ":2:10: error: cannot read include '/dev/zero': is a character device, not a regular file"},
      {"big.frag", ":1:10: error: cannot read include '" + (dir / "big.glsl").string() + "': is " +
                       std::to_string(kMaxShaderBytes + 1) + " bytes, over the 16 MiB limit for shader files"},
  };
  for (const auto& [name, says] : cases) {
    Source s = preprocess(dir / name, {});
    ASSERT_EQ(s.errors.size(), 1u) << name;
    EXPECT_EQ(s.errors[0].str(), (dir / name).string() + says);
  }
}

// Real Shadertoy shaders carry a main() for other hosts in an inactive block:
// the kind is decided on what the compiler sees, with the -D macros.
TEST(Source, AMainInAnInactiveBlockLeavesAShadertoyShader) {
  TempDir dir;
  write_file(dir / "scene.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(iTime); }\n"
                                 "#ifdef GLSLVIEWER\nvoid main() { mainImage(gl_FragColor, gl_FragCoord.xy); }\n#endif\n");
  EXPECT_EQ(preprocess(dir / "scene.frag", {}).kind, ShaderKind::Shadertoy);
  SourceOptions viewer;
  viewer.defines.push_back({"GLSLVIEWER", ""});
  EXPECT_EQ(preprocess(dir / "scene.frag", viewer).kind, ShaderKind::Legacy) << "with the block active, main() is its own";
  EXPECT_TRUE(validate(preprocess(dir / "scene.frag", {})).empty());
}

TEST(Source, ChannelPragmasNameBuffersSelfTheKeyboardAndSettings) {
  TempDir dir;
  write_file(dir / "a.frag", kMain);
  write_file(dir / "scene.frag", "#pragma channel0 \"a.frag\" filter=nearest wrap=repeat\n#pragma channel1 self vflip=false\n"
                                 "#pragma channel2 keyboard  // the keys\n" + std::string(kMain));
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok()) << join(s.errors);
  EXPECT_EQ(s.channels[0].kind, ChannelSpec::Kind::Pass);
  EXPECT_EQ(s.channels[0].path, dir / "a.frag");
  EXPECT_EQ(s.channels[0].sampler.filter, Sampler::Filter::Nearest);
  EXPECT_EQ(s.channels[0].sampler.wrap, Sampler::Wrap::Repeat);
  EXPECT_EQ(s.channels[1].kind, ChannelSpec::Kind::Self);
  EXPECT_FALSE(s.channels[1].sampler.vflip);
  EXPECT_EQ(s.channels[2].kind, ChannelSpec::Kind::Keyboard);
  write_file(dir / "bad.frag", "\n#pragma channel1 self filter=fuzzy\n" + std::string(kMain));
  Source bad = preprocess(dir / "bad.frag", {});
  ASSERT_EQ(bad.errors.size(), 1u);
  EXPECT_EQ(bad.errors[0].line, 2);
  EXPECT_NE(bad.errors[0].message.find("unknown channel setting 'filter=fuzzy'"), std::string::npos) << bad.errors[0].message;
}

// A bad value 100,000 characters long gets a line an editor can show: what it
// quotes is cut to 40 bytes and "...".
TEST(Source, AnErrorQuotesALongBadValueBriefly) {
  TempDir dir;
  write_file(dir / "a.frag", kMain);
  const std::string zeros(100000, '0');
  for (const auto& [pragma, message] : std::vector<std::pair<std::string, std::string>>{
           {"\"a.frag\" size=1x1" + zeros, "not '1x1" + std::string(37, '0') + "...'"},
           {"\"a.frag\" scale=0." + zeros + "x", "not '0." + std::string(38, '0') + "...'"},
           {"\"a.frag\" filter=" + zeros, "unknown channel setting 'filter=" + std::string(33, '0') + "...'"},
       }) {
    write_file(dir / "bad.frag", "#pragma channel0 " + pragma + "\n" + std::string(kMain));
    const Source bad = preprocess(dir / "bad.frag", {});
    ASSERT_EQ(bad.errors.size(), 1u);
    EXPECT_NE(bad.errors[0].message.find(message), std::string::npos) << bad.errors[0].message.substr(0, 200);
    EXPECT_LT(bad.errors[0].message.size(), 400u);
  }
  write_file(dir / "gv.frag", "uniform sampler2D u_buffer0; // 1x" + zeros + "\nvoid main() {\n"
                              "  gl_FragColor = texture2D(u_buffer0, vec2(0.5));\n}\n");
  const Source gv = preprocess(fs::absolute(dir / "gv.frag").lexically_normal(), {});
  ASSERT_EQ(gv.errors.size(), 1u);
  EXPECT_EQ(gv.errors[0].column, 33);
  EXPECT_NE(gv.errors[0].message.find("not '1x" + std::string(38, '0') + "...'"), std::string::npos);
  EXPECT_LT(gv.errors[0].message.size(), 400u);
}

// A file that is not there is named whole, however deep its path; a name
// longer than any path can be (PATH_MAX) is cut.
TEST(Source, AMissingFilesNameIsQuotedWholeUpToPathMax) {
  TempDir dir;
  const std::string deep = "a/b/c/d/e/f/g/h/i/j/k/l/m/n/o/p/q/r/s/t/u/v/w/x/y/z/missing.png";
  const std::string endless(100000, 'b');
  for (const auto& [line, message] : std::vector<std::pair<std::string, std::string>>{
           {"#pragma channel0 \"" + deep + "\"", "cannot find channel image '" + deep + "'"},
           {"#include \"" + deep + "\"", "cannot find include '" + deep + "'"},
           {"#pragma channel0 \"" + endless + "\"", "cannot find channel image '" + endless.substr(0, PATH_MAX) + "...'"},
           {"#include \"" + endless + "\"", "cannot find include '" + endless.substr(0, PATH_MAX) + "...'"},
       }) {
    write_file(dir / "bad.frag", line + "\n" + std::string(kMain));
    const Source bad = preprocess(dir / "bad.frag", {});
    ASSERT_EQ(bad.errors.size(), 1u);
    EXPECT_EQ(bad.errors[0].message, message);
  }
}

}  // namespace
}  // namespace rm
