// Diagnostics: glslang's and the driver's messages land on the user's file,
// line and column, also inside includes and for host-added lines.
#include "core/check.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include "core/scene.h"
#include "support.h"

namespace rm {
namespace {

using test::TempDir;
using test::write_file;

// The diagnostics of `dir`/scene.frag saved with `text`, one per line.
std::string diagnostics_of_scene(const TempDir& dir, const std::string& text) {
  write_file(dir / "scene.frag", text);
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  return join(diags);
}

TEST(Check, ErrorInAnIncludedFileNamesThatFileAndLine) {
  TempDir dir;
  write_file(dir / "scene.frag", "// scene\n#include \"lib.glsl\"\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(g()); }\n");
  write_file(dir / "lib.glsl", "// lib line 1\n\nfloat g() {\n  return undefined_name;\n}\n");
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  ASSERT_GE(count_errors(diags), 1);
  EXPECT_EQ(diags[0].str(), (dir / "lib.glsl").string() + ":4:10: error: 'undefined_name' : undeclared identifier");
}

// GLSL ends a line at CR, LF or CR LF. glslang reads a file of CRs alone
// (an old Mac editor's) as one line, a comment here: the lines are the file's.
TEST(Check, EachLineEndingEndsALineAndErrorsKeepTheirLines) {
  TempDir dir;
  write_file(dir / "lib.glsl", "// lib\r\rfloat g() {\r  return bad_name;\r}\r");
  write_file(dir / "scene.frag", "// scene\r#include \"lib.glsl\"\r\nvoid mainImage(out vec4 c, in vec2 f) {\n"
                                 "  c = vec4(\\\r g());\r  float y = nope;\r}\r");
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  ASSERT_EQ(count_errors(diags), 2) << join(diags);
  EXPECT_EQ(diags[0].str(), (dir / "lib.glsl").string() + ":4:10: error: 'bad_name' : undeclared identifier");
  EXPECT_EQ(diags[1].str(), (dir / "scene.frag").string() + ":6:13: error: 'nope' : undeclared identifier");
}

// check_scene's diagnostics for `scene` with `defines`, one a line.
std::string checked(const fs::path& scene, std::vector<Define> defines = {}) {
  SourceOptions options;
  options.defines = std::move(defines);
  Diagnostics diags;
  check_scene(scene, options, &diags);
  return join(diags);
}

// The compiler's #if decides, even over a line continued by a backslash.
TEST(Check, AMissingIncludeIsAnErrorOnlyWhereItsBranchIsTaken) {
  TempDir dir;
  write_file(dir / "scene.frag", "#if defined(HAVE_NOISE) && \\\n    HAVE_NOISE > 1\n  #include \"noise.glsl\"\n#endif\n"
                                 "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
  auto diagnostics = [&](std::vector<Define> defines) { return checked(dir / "scene.frag", std::move(defines)); };
  EXPECT_EQ(diagnostics({}), "");
  EXPECT_EQ(diagnostics({{"HAVE_NOISE", "2"}}),
            (dir / "scene.frag").string() + ":3:12: error: cannot find include 'noise.glsl'\n");
  EXPECT_EQ(diagnostics({{"HAVE_NOISE", "1"}}), "");
}

// An include that cannot be read (a FIFO, a directory, NUL bytes) is, like
// a missing one, an error only where the compiler takes its branch; outside
// any branch it is one at once. A FIFO is refused by what it is, not read.
TEST(Check, AnUnreadableIncludeIsAnErrorOnlyWhereItsBranchIsTaken) {
  TempDir dir;
  ASSERT_EQ(mkfifo((dir / "pipe.glsl").c_str(), 0600), 0);
  std::filesystem::create_directories(dir / "dir.glsl");
  write_file(dir / "nul.glsl", std::string("float a;\0\n", 11));
  write_file(dir / "scene.frag", "#ifdef USE_PIPE\n#include \"pipe.glsl\"\n#endif\n#if LOOK > 1\n#include \"nul.glsl\"\n"
                                 "#elif LOOK == 1\n  #include \"dir.glsl\"\n#endif\n"
                                 "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
  auto diagnostics = [&](std::vector<Define> defines) { return checked(dir / "scene.frag", std::move(defines)); };
  const std::string scene = (dir / "scene.frag").string();
  EXPECT_EQ(diagnostics({}), "");
  EXPECT_EQ(diagnostics({{"USE_PIPE", ""}}), scene + ":2:10: error: cannot read include '" +
                                                 (dir / "pipe.glsl").string() +
                                                 "': is a named pipe (FIFO), not a regular file\n");
  EXPECT_EQ(diagnostics({{"LOOK", "2"}}), (dir / "nul.glsl").string() + ": error: not a text file (it contains NUL bytes)\n");
  EXPECT_EQ(diagnostics({{"LOOK", "1"}}),
            scene + ":7:12: error: cannot read include '" + (dir / "dir.glsl").string() + "': is a directory\n");
  write_file(dir / "plain.frag", "#include \"dir.glsl\"\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
  EXPECT_EQ(checked(dir / "plain.frag"), (dir / "plain.frag").string() + ":1:10: error: cannot read include '" +
                                              (dir / "dir.glsl").string() + "': is a directory\n");
}

// A file included first in a branch the compiler does not take is there
// when it is included again outside it.
TEST(Check, AFileIncludedInAnUntakenBranchIsIncludedAgainOutside) {
  TempDir dir;
  write_file(dir / "lib.glsl", "float level = 0.5;\n");
  const std::string main = "void mainImage(out vec4 c, in vec2 f) { c = vec4(level); }\n";
  EXPECT_EQ(diagnostics_of_scene(dir, "#ifdef NOT_DEFINED\n#include \"lib.glsl\"\n#endif\n#include \"lib.glsl\"\n" + main), "");
  EXPECT_EQ(diagnostics_of_scene(dir, "#if 1\n#include \"lib.glsl\"\n#endif\n#include \"lib.glsl\"\n" + main), "")
      << "taken twice, defined once";
  EXPECT_EQ(diagnostics_of_scene(dir, "/*\n#include \"lib.glsl\"\n*/\n" + main),
            (dir / "scene.frag").string() + ":4:50: error: 'level' : undeclared identifier\n");
}

// glslang gives an undeclared name no column: the host finds it on the
// line, as a word of its own and outside comments.
TEST(Check, AQuotedNameIsFoundAsAWord) {
  TempDir dir;
  const std::string line = "void mainImage(out vec4 c, in vec2 f) { /* g */ c = vec4(g); }\n";
  EXPECT_EQ(diagnostics_of_scene(dir, line), (dir / "scene.frag").string() + ":1:" +
                                                 std::to_string(line.find("(g)") + 2) + ": error: 'g' : undeclared identifier\n");
}

// An error inside a conditional (an include guard) is the only error: no
// "missing #endif", which glslang says when it stops at an error there.
TEST(Check, ErrorInsideAnIncludeGuardIsTheOnlyError) {
  TempDir dir;
  write_file(dir / "scene.frag", "#include \"lib.glsl\"\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(g()); }\n");
  write_file(dir / "lib.glsl", "#ifndef LIB\n#define LIB\nfloat g() { return nope; }\n#endif\n");
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  EXPECT_EQ(join(diags), (dir / "lib.glsl").string() + ":3:20: error: 'nope' : undeclared identifier\n");
}

// A conditional left open is reported where it opens, as C compilers do,
// not at the end of the text, which is the host's code; an #endif in a
// comment closes nothing.
TEST(Check, UnterminatedConditionalNamesItsOpeningLine) {
  TempDir dir;
  write_file(dir / "scene.frag", "#include \"lib.glsl\"\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(g()); }\n");
  write_file(dir / "lib.glsl", "#ifndef LIB\n#define LIB\n  #if 1 // #endif\n/* #endif */\nfloat g() { return 1.0; }\n#endif\n");
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  EXPECT_EQ(join(diags), (dir / "lib.glsl").string() + ":1:1: error: unterminated #ifndef\n");
}

// A file that ends inside a block: glslang's error comes after it, in the
// host's code after the scene or in the file that included it, and makes no
// sense there. The error is the '{' left open.
TEST(Check, BraceLeftOpenAtAFilesEndIsTheError) {
  TempDir dir;
  write_file(dir / "scene.frag", "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(1.0);\n");
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  EXPECT_EQ(join(diags), (dir / "scene.frag").string() + ":1:39: error: '{' : not closed before the end of the file\n");

  write_file(dir / "lib.glsl", "float g() {\n  return 1.0;\n");
  write_file(dir / "scene.frag", "#include \"lib.glsl\"\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(g()); }\n");
  check_scene(dir / "scene.frag", {}, &diags);
  EXPECT_EQ(join(diags), (dir / "lib.glsl").string() + ":1:11: error: '{' : not closed before the end of the file\n");
}

// Braces that do balance are left alone: an include inside a function's
// body, the alternative branches of a conditional, each with a '{', and a
// '{' in a #define's body.
TEST(Check, BalancedBracesKeepGlslangsError) {
  TempDir dir;
  write_file(dir / "body.glsl", "return nope;\n");
  write_file(dir / "scene.frag", "float g() {\n#include \"body.glsl\"\n}\n"
                                 "void mainImage(out vec4 c, in vec2 f) { c = vec4(g()); }\n");
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  EXPECT_EQ(join(diags), (dir / "body.glsl").string() + ":1:8: error: 'nope' : undeclared identifier\n");

  write_file(dir / "scene.frag", "#ifdef A\nfloat g() {\n#else\nfloat g() {\n#endif\n  return 1.0;\n}\n"
                                 "void mainImage(out vec4 c, in vec2 f) { c = vec4(nope); }\n");
  check_scene(dir / "scene.frag", {}, &diags);
  EXPECT_EQ(join(diags), (dir / "scene.frag").string() + ":8:50: error: 'nope' : undeclared identifier\n");
  // A '{' in a #define's body continued by a backslash is not code yet.
  write_file(dir / "lib.glsl", "#define BEGIN_BLOCK \\\n  {\nfloat g() { return 1.0; }\n");
  write_file(dir / "scene.frag", "#include \"lib.glsl\"\nvoid mainImage(out vec4 c, in vec2 f) {\n  c = vec4(g())\n}\n");
  check_scene(dir / "scene.frag", {}, &diags);
  EXPECT_EQ(join(diags), (dir / "scene.frag").string() + ":3:16: error: syntax error, expecting ',' or ';' before '}'\n");
}

// A declaration a file leaves unfinished: glslang names the next token,
// in the host's code or the including file. The error is where the ';' goes.
TEST(Check, SyntaxErrorAtAFilesEndIsPutThere) {
  TempDir dir;
  write_file(dir / "scene.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\nconst float x = 1.0 // no ;\n\n");
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  EXPECT_EQ(join(diags), (dir / "scene.frag").string() +
                             ":2:20: error: syntax error at the end of the file, expecting ',' or ';'\n");

  write_file(dir / "lib.glsl", "float g(float a\n");
  write_file(dir / "scene.frag", "#include \"lib.glsl\"\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
  check_scene(dir / "scene.frag", {}, &diags);
  EXPECT_EQ(join(diags), (dir / "lib.glsl").string() +
                             ":1:16: error: syntax error at the end of the file, expecting ')'\n");

  // A complete shader: no host code follows, and glslang names the text's end INT.
  write_file(dir / "full.frag", "#version 330 core\nout vec4 o;\nvoid main() { o = vec4(1.0); }\nfloat x = 1.0\n\n");
  check_scene(dir / "full.frag", {}, &diags);
  EXPECT_EQ(join(diags), (dir / "full.frag").string() +
                             ":4:14: error: syntax error at the end of the file, expecting ',' or ';'\n");
}

// A scene's macro that breaks the host's main() is not what the scene left
// open at its end: it is named at its #define. And an error in the middle of
// a line is where glslang says: it names a keyword in capitals, the column
// is found from it, and the message spells it as the code does.
TEST(Check, SyntaxErrorsElsewhereStayWhereGlslangPutsThem) {
  TempDir dir;
  write_file(dir / "scene.frag", "#define rm_color 1.0\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  EXPECT_EQ(join(diags), (dir / "scene.frag").string() +
                             ":1:9: error: the scene's #define rm_color changes the code the host adds around the "
                             "scene: syntax error, unexpected float constant, expecting ',' or ';'\n");

  write_file(dir / "scene.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0) return; }\n");
  check_scene(dir / "scene.frag", {}, &diags);
  EXPECT_EQ(join(diags), (dir / "scene.frag").string() +
                             ":1:55: error: syntax error, unexpected 'return', expecting ',' or ';'\n");
}

// glslang quotes no token for some errors; the column is that of what the
// message is about where the line leaves no doubt, in an include too, and
// left out where it does not (two constructors on one line). A constructor
// called over lines is named where it begins. A literal too big is the
// line's one integer literal past 32 bits.
TEST(Check, ErrorsThatQuoteNoTokenGetTheColumnOfTheirSubject) {
  TempDir dir;
  write_file(dir / "lib.glsl", "float g(float x) {\n  x += 1.0; // no return\n}\n");
  const std::string scene = (dir / "scene.frag").string(), lib = (dir / "lib.glsl").string();
  EXPECT_EQ(diagnostics_of_scene(dir, "#include \"lib.glsl\"\n"
                                      "void mainImage(out vec4 c, in vec2 f) { c = vec4(g(1.0)); }\n"),
            lib + ":1:7: error: function does not return a value: g\n");
  EXPECT_EQ(diagnostics_of_scene(dir, "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(1.0);\n  break;\n}\n"),
            scene + ":3:3: error: break statement only allowed in switch and loops\n");
  EXPECT_EQ(diagnostics_of_scene(dir, "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(1.0); continue;\n}\n"),
            scene + ":2:18: error: continue statement only allowed in loops\n");
  EXPECT_EQ(diagnostics_of_scene(dir, "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(1.0);\n"
                                      "  /* if ( */ if (c.x) c.y = 0.0;\n}\n"),
            scene + ":3:14: error: boolean expression expected\n");
  EXPECT_EQ(diagnostics_of_scene(dir, "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(1.0);\n"
                                      "  c.x = c.y ? 1.0 : 0.0;\n}\n"),
            scene + ":3:13: error: boolean expression expected\n");
  EXPECT_EQ(diagnostics_of_scene(dir, "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(1.0);\n"
                                      "  float y = vec2(1.0, 2.0, 3.0).x;\n}\n"),
            scene + ":3:13: error: 'constructor' : too many arguments\n");
  EXPECT_EQ(diagnostics_of_scene(dir, "void mainImage(out vec4 c, in vec2 f) {\n"
                                      "  c = vec4(vec2(1.0, 2.0, 3.0), 1.0, 1.0);\n}\n"),
            scene + ":2: error: 'constructor' : too many arguments\n");
  // A call over lines: glslang names the line where it ends; the error is
  // at the constructor, and the '=' that failed with it is its echo. Two
  // constructors that close on the line leave the column out.
  EXPECT_EQ(diagnostics_of_scene(dir, "void mainImage(out vec4 c, in vec2 f) {\n  mat3 m = mat3(\n"
                                      "    1.0, 0.0, 0.0, // (\n    0.0, (1.0), 0.0,\n    0.0, 0.0);\n"
                                      "  c = vec4(m[0], 1.0);\n}\n"),
            scene + ":2:12: error: 'constructor' : not enough data provided for construction\n");
  EXPECT_EQ(diagnostics_of_scene(dir, "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(vec3(1.0,\n"
                                      "    2.0, 3.0, 4.0), 1.0);\n}\n"),
            scene + ":3: error: 'constructor' : too many arguments\n" + scene +
                ":2:5: error: '=' : cannot convert from 'const float' to 'out vec4'\n");
  // An integer literal past 32 bits, of any base; a float's digits and a comment's are none.
  EXPECT_EQ(diagnostics_of_scene(dir, "void mainImage(out vec4 c, in vec2 f) {\n"
                                      "  float x = 4294967296.0; int i = 1 + 4294967296; // 99999999999\n"
                                      "  c = vec4(x, i, 1e10, 1.0);\n}\n"),
            scene + ":2:39: error: numeric literal too big\n");
  EXPECT_EQ(diagnostics_of_scene(dir, "void mainImage(out vec4 c, in vec2 f) {\n"
                                      "  uint u = 0xFFFFFFFFu + 0x1fFFFFFFFu;\n  c = vec4(u);\n}\n"),
            scene + ":2:26: error: hexadecimal literal too big\n");
}

// An error glslang puts on a line that does not spell its token, which a
// macro's expansion brought there: the column is the macro's call on the
// line, and the message says which macro and where it is defined, through
// a macro it calls, one continued over lines, one of an include. Two macros
// on the line that could have brought it leave the column out.
TEST(Check, AnErrorInAMacrosExpansionIsNamedAtItsCall) {
  TempDir dir;
  const std::string scene = (dir / "scene.frag").string(), lib = (dir / "lib.glsl").string();
  EXPECT_EQ(diagnostics_of_scene(dir, "#define F(x) (x + nothere)\n"
                                      "void mainImage(out vec4 c, in vec2 f) {\n  float k = F(1.0);\n  c = vec4(k);\n}\n"),
            scene + ":3:13: error: 'nothere' : undeclared identifier (in expansion of macro 'F', defined at " + scene +
                ":1:9)\n");
  write_file(dir / "lib.glsl", "#define G(x) (x * nothere)\n#define F(x) \\\n  (G(x) + 1.0)\n");
  EXPECT_EQ(diagnostics_of_scene(dir, "#include \"lib.glsl\"\n"
                                      "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(F(1.0));\n}\n"),
            scene + ":3:12: error: 'nothere' : undeclared identifier (in expansion of macro 'F', defined at " + lib +
                ":2:9, through macro 'G', defined at " + lib + ":1:9)\n");
  // Levels between the macro called and the one that spells the token are
  // counted; of two ways down, the shorter is taken.
  EXPECT_EQ(diagnostics_of_scene(dir, "#define D nothere\n#define C D\n#define B C\n#define A (B + C)\n"
                                      "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(A);\n}\n"),
            scene + ":6:12: error: 'nothere' : undeclared identifier (in expansion of macro 'A', defined at " + scene +
                ":4:9, through 1 more macro to 'D', defined at " + scene + ":1:9)\n");
  EXPECT_EQ(diagnostics_of_scene(dir, "#define A nothere\n#define B nothere\n"
                                      "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(A + B);\n}\n"),
            scene + ":4: error: 'nothere' : undeclared identifier\n");
  // Macros that name each other many times over, many levels deep, are
  // each read once (walked path by path, this took hours): F9's expansion
  // does not spell the token, H's does.
  std::string define_chain = "#define F0(a) a\n#define H nothere\n";
  for (int level = 1; level < 10; ++level) {
    define_chain += "#define F" + std::to_string(level) + "(a)";
    for (int i = 0; i < 20; ++i) define_chain += " F" + std::to_string(level - 1);
    define_chain += "\n";
  }
  EXPECT_EQ(diagnostics_of_scene(dir, define_chain + "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(H, F9(1));\n}\n"),
            scene + ":13:12: error: 'nothere' : undeclared identifier (in expansion of macro 'H', defined at " + scene +
                ":2:9)\n");
}

TEST(Check, ErrorAfterAnIncludeKeepsTheScenesLineNumber) {
  TempDir dir;
  write_file(dir / "scene.frag", "#include \"lib.glsl\"\n\n\nvoid mainImage(out vec4 c, in vec2 f) {\n  c = vec4(nope);\n}\n");
  write_file(dir / "lib.glsl", "float a;\nfloat b;\nfloat c2;\nfloat d;\n");
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  ASSERT_GE(count_errors(diags), 1);
  EXPECT_EQ(diags[0].path, (dir / "scene.frag").string());
  EXPECT_EQ(diags[0].line, 5);
  EXPECT_EQ(diags[0].column, 12);
}

TEST(Check, ValidShaderOfEachKindHasNoErrors) {
  TempDir dir;
  write_file(dir / "toy.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(f / iResolution.xy, sin(iTime), 1.0); }\n");
  write_file(dir / "full.frag", "#version 330 core\nuniform float u;\nout vec4 o;\nvoid main() { o = vec4(u); }\n");
  write_file(dir / "legacy.frag", "uniform float u_time;\nuniform sampler2D u_tex0;\nvarying vec2 v;\n"
                                  "void main() { gl_FragColor = texture2D(u_tex0, vec2(u_time)); }\n");
  for (const char* name : {"toy.frag", "full.frag", "legacy.frag"}) {
    Diagnostics diags;
    check_scene(dir / name, {}, &diags);
    EXPECT_EQ(count_errors(diags), 0) << name << "\n" << join(diags);
  }
}

TEST(Check, ErrorFromACommandLineDefineNamesTheCommandLine) {
  TempDir dir;
  write_file(dir / "scene.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(SCALE); }\n");
  SourceOptions opts;
  opts.defines = {{"SCALE", "1.0 +"}};
  Diagnostics diags;
  check_scene(dir / "scene.frag", opts, &diags);
  ASSERT_GE(count_errors(diags), 1);
  EXPECT_EQ(diags[0].path, (dir / "scene.frag").string());  // where the macro is used
}

// The host's main() keeps its own names out of the scene's way: macros
// named color or fragCoord, the obvious names for its locals, break nothing.
TEST(Check, MacrosNamedLikeShadertoysLocalsAreTheScenesOwn) {
  TempDir dir;
  write_file(dir / "scene.frag", "#define color vec4(0.5)\n#define fragCoord (f * 2.0)\n#define dir 1.0\n"
                                 "void mainImage(out vec4 c, in vec2 f) { c = color + vec4(fragCoord, dir, 1.0); }\n");
  write_file(dir / "cube.frag", "#define color vec4(0.5)\n#define st 1.0\n#define dir 1.0\n"
                                "void mainCubemap(out vec4 c, in vec2 f, in vec3 o, in vec3 d) { c = color * st * dir; }\n");
  for (const char* name : {"scene.frag", "cube.frag"}) {
    Diagnostics diags;
    check_scene(dir / name, {}, &diags);
    EXPECT_EQ(join(diags), "") << name;
  }
  SourceOptions view;
  view.defines = {{"RM_VIEW", "4"}};
  Diagnostics diags;
  check_scene(dir / "scene.frag", view, &diags);
  EXPECT_EQ(join(diags), "");
}

// The host's call finds no mainImage (or mainCubemap) to take its arguments:
// the error is at the scene's own, in the file that defines it, and says what
// the host calls.
TEST(Check, WrongMainImageSignatureIsNamedWhereTheSceneDefinesIt) {
  TempDir dir;
  write_file(dir / "lib.glsl", "// the scene's code\n\nvoid mainImage(out vec3 c, in vec2 f) { c = vec3(1.0); }\n");
  write_file(dir / "scene.frag", "#include \"lib.glsl\"\n");
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  EXPECT_EQ(join(diags), (dir / "lib.glsl").string() +
                             ":3:6: error: 'mainImage' : the host calls mainImage(out vec4, in vec2), and no "
                             "mainImage takes those parameters\n");

  write_file(dir / "cube_a.frag", "void mainCubemap(out vec4 c, in vec2 f, in vec3 o) { c = vec4(1.0); }\n");
  check_scene(dir / "cube_a.frag", {}, &diags);
  EXPECT_EQ(join(diags), (dir / "cube_a.frag").string() +
                             ":1:6: error: 'mainCubemap' : the host calls mainCubemap(out vec4, in vec2, in vec3, "
                             "in vec3), and no mainCubemap takes those parameters\n");
}

// Any other error in the host's code that a word of the scene's #defines is
// on: named at that #define (the last before it), in the file that has it.
TEST(Check, ASceneMacroThatBreaksTheHostsCodeIsNamedAtItsDefine) {
  TempDir dir;
  write_file(dir / "lib.glsl", "#define R iResolution\n#define vec4 float\n");
  write_file(dir / "scene.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n#include \"lib.glsl\"\n");
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  EXPECT_EQ(join(diags), (dir / "lib.glsl").string() +
                             ":2:9: error: the scene's #define vec4 changes the code the host adds around the scene: "
                             "'constructor' : too many arguments\n");
}

// A function declared but defined nowhere: the driver's link refuses it, so
// validation does too, once, at its first call. Mesa refuses such a call even
// in a function that main never reaches, and so does validation.
TEST(Check, CallToAFunctionWithNoBodyIsAnErrorAtItsFirstCall) {
  TempDir dir;
  write_file(dir / "scene.frag", "#include \"lib.glsl\"\n"
                                 "float unused(vec2 p) {\n  return helper(p) + helper(p.yx);\n}\n"
                                 "void mainImage(out vec4 c, in vec2 f) { c = vec4(helper(f)); }\n");
  write_file(dir / "lib.glsl", "float helper(vec2 p);\nfloat defined(vec2 p);\nfloat defined(vec2 p) { return p.x; }\n");
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  ASSERT_EQ(count_errors(diags), 1) << join(diags);
  EXPECT_EQ(diags[0].str(), (dir / "scene.frag").string() + ":3:10: error: 'helper' : function is called but no body defines it");
}

// Arrays are counted in all: four of 4,096 floats are the most a shader may
// hold; one more float is refused at the largest array, at its first use.
TEST(Check, TheShadersArraysMayHold16384ComponentsInAll) {
  TempDir dir;
  const auto scene = [&](int last) {
    return "void mainImage(out vec4 c, in vec2 f) {\n"
           "  float a[4096], b[4096], d[4096], e[" + std::to_string(last) + "];\n"
           "  a[0] = b[0] = d[0] = e[0] = 1.0;\n"
           "  c = vec4(a[int(f.x)], b[int(f.x)], d[int(f.x)], e[int(f.x)]);\n}\n";
  };
  write_file(dir / "scene.frag", scene(4096));
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  EXPECT_EQ(count_errors(diags), 0) << join(diags);
  write_file(dir / "scene.frag", scene(4097));
  check_scene(dir / "scene.frag", {}, &diags);
  ASSERT_EQ(count_errors(diags), 1) << join(diags);
  EXPECT_EQ(diags[0].str(), (dir / "scene.frag").string() +
                                ":3:24: error: 'e' : an array of 4097 components, and 16385 in all the shader's arrays; "
                                "at most 16384 are allowed in a shader's arrays (the GL driver compiles code for each)");
}

// The driver inlines every call, so a function's array counts once a call
// that main() reaches: four calls of 4,096 floats are allowed, five (one
// direct, four through g's two calls) are not. A function nothing calls
// costs nothing, whatever it holds.
TEST(Check, AFunctionsArrayCountsOnceForEachCallThatMainReaches) {
  TempDir dir;
  const std::string functions = "float f(int i) {\n  float a[4096];\n  a[i] = 1.0;\n  return a[i / 2];\n}\n"
                                "float g(int i) { return f(i) + f(i + 1); }\n"
                                "float never(int i) { float b[16777216]; b[i] = 1.0; return b[i]; }\n";
  write_file(dir / "scene.frag", functions + "void mainImage(out vec4 c, in vec2 p) {\n"
                                             "  int i = int(p.x);\n  c = vec4(g(i) + g(i + 2));\n}\n");
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  EXPECT_EQ(count_errors(diags), 0) << join(diags);
  write_file(dir / "scene.frag", functions + "void mainImage(out vec4 c, in vec2 p) {\n"
                                             "  int i = int(p.x);\n  c = vec4(g(i) + g(i + 2) + f(i));\n}\n");
  check_scene(dir / "scene.frag", {}, &diags);
  ASSERT_EQ(count_errors(diags), 1) << join(diags);
  EXPECT_EQ(diags[0].str(), (dir / "scene.frag").string() +
                                ":3:3: error: 'a' : an array of 4096 components in each of 5 calls of f(); at most "
                                "16384 are allowed in a shader's arrays (the GL driver compiles code for each)");
}

// A chain's depth flows through an if: after it, a variable holds what
// either branch left in it, and one branch never sees the other's writes.
// Each half below is 1,500 variables (3,000 operations); the whole, 6,000,
// is past the limit of 5,000.
TEST(Check, AChainsDepthFlowsThroughEitherBranchOfAnIf) {
  const auto chain = [](const std::string& from, const std::string& name) {
    std::string text = "  float " + name + "0 = " + from + ";\n";
    for (int i = 1; i < 1500; ++i)
      text += "  float " + name + std::to_string(i) + " = " + name + std::to_string(i - 1) + " * 1.0001 + 0.1;\n";
    return text;
  };
  const std::string start = "void mainImage(out vec4 c, in vec2 f) {\n" + chain("f.x", "a") + "  float y = f.y;\n";
  struct Case {
    std::string middle;  // between the first half and the second, which starts from y
    bool past;
  };
  const std::vector<Case> cases = {
      {"  if (f.x > 1.0) y = a1499;\n", true},                      // the yes branch's value
      {"  if (f.x > 1.0) y = 0.0; else y = a1499;\n", true},        // the no branch's
      {"  if (f.x > 1.0) y = a1499;\n  y = f.y;\n", false},        // written again after it
      {"  if (f.x > 1.0) { y = a1499; } else {\n" + chain("y", "b") + "  }\n  y = f.y;\n", false},  // no sees not yes's write
  };
  TempDir dir;
  for (const Case& c : cases) {
    write_file(dir / "scene.frag", start + c.middle + chain("y", "z") + "  c = vec4(z1499);\n}\n");
    Diagnostics diags;
    check_scene(dir / "scene.frag", {}, &diags);
    EXPECT_EQ(count_errors(diags), c.past ? 1 : 0) << c.middle << join(diags);
    if (c.past) {
      EXPECT_NE(join(diags).find("operations deep"), std::string::npos) << join(diags);
    }
  }
}

TEST(Check, PrototypeThatNothingCallsIsNoError) {
  TempDir dir;
  write_file(dir / "scene.frag", "float helper(vec2 p);\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  EXPECT_EQ(count_errors(diags), 0) << join(diags);
}

TEST(MapLog, MesaCompileMessagesAreMappedWithColumn) {
  TempDir dir;
  write_file(dir / "scene.frag", "#include \"lib.glsl\"\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
  write_file(dir / "lib.glsl", "float a;\nfloat b;\n");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok());
  int b_line = 0;
  for (size_t i = 1; i <= s.line_map.size(); ++i)
    if (s.final_line_text(static_cast<int>(i)) == "float b;") b_line = static_cast<int>(i);
  Diagnostics d = map_log("0:" + std::to_string(b_line) + "(7): error: syntax error, unexpected ';'\n", s, LogFormat::Mesa);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].str(), (dir / "lib.glsl").string() + ":2:7: error: syntax error, unexpected ';'");
}

// Mesa's preprocessor says "preprocessor error: " (these were kept whole and
// placed at the scene alone), and the driver may take an #if branch glslang
// did not: Mesa defines GL_MESA_shader_integer_functions, glslang does not,
// so a missing include in that branch is Mesa's #error.
TEST(MapLog, MesaPreprocessorErrorsAreMappedAndAMissingIncludeNamed) {
  TempDir dir;
  write_file(dir / "scene.frag", "#ifdef GL_MESA_shader_integer_functions\n  #include \"nothere.glsl\"\n#endif\n"
                                 "#error mine\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok()) << join(s.errors);
  int mark_line = 0, error_line = 0;
  for (size_t i = 1; i <= s.line_map.size(); ++i) {
    const std::string text = s.final_line_text(static_cast<int>(i));
    if (text.starts_with("#error rm_missing_include_")) mark_line = static_cast<int>(i);
    if (text == "#error mine") error_line = static_cast<int>(i);
  }
  ASSERT_GT(mark_line, 0);
  const Diagnostics d = map_log("0:" + std::to_string(mark_line) + "(1): preprocessor error: #error rm_missing_include_0\n" +
                                    "0:" + std::to_string(error_line) + "(1): preprocessor error: #error mine\n",
                                s, LogFormat::Mesa);
  EXPECT_EQ(join(d), (dir / "scene.frag").string() + ":2:12: error: cannot find include 'nothere.glsl'\n" +
                         (dir / "scene.frag").string() + ":4:1: error: #error mine\n");
}

TEST(MapLog, LinkErrorWithoutLineNamesTheScene) {
  TempDir dir;
  write_file(dir / "scene.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
  Source s = preprocess(dir / "scene.frag", {});
  Diagnostics d = map_log("error: unresolved reference to function `f'\n", s, LogFormat::Mesa);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].str(), (dir / "scene.frag").string() + ": error: unresolved reference to function `f'");
}

// A function declared but defined nowhere: the line that first names it
// (outside comments), in the file that holds it, here an include's prototype.
// glslang stops at a required extension it lacks and then calls the rest
// of the line extra tokens: the one error is the extension.
TEST(Check, ARequiredExtensionTheDriverLacksIsOneError) {
  TempDir dir;
  write_file(dir / "scene.frag",
             "#extension GL_OES_texture_float : require\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  EXPECT_EQ(join(diags),
            (dir / "scene.frag").string() + ":1:1: error: '#extension' : extension not supported: GL_OES_texture_float\n");
}

// An input the host's vertex shader does not feed (glslViewer's v_color):
// the driver's link error names no line; the declaration is the place.
TEST(MapLog, AnInputNothingFeedsIsAtItsDeclaration) {
  TempDir dir;
  write_file(dir / "scene.frag", "// v_color: the vertex's\nvarying vec4 v_color;\nvoid main() { gl_FragColor = v_color; }\n");
  Source s = preprocess(dir / "scene.frag", {});
  ASSERT_TRUE(s.ok()) << join(s.errors);
  Diagnostics d = map_log("error: fragment shader input `v_color' has no matching output in the previous stage\n", s,
                          LogFormat::Mesa);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].str(), (dir / "scene.frag").string() +
                            ":2:14: error: 'v_color' is an input from a vertex shader, and the host's passes on "
                            "nothing (glslViewer's v_texcoord is the one input it supplies)");
}

// `check` says what a build's link would: an input the host's vertex shader
// does not feed is an error wherever the code uses it (in a function nothing
// calls too, as the driver's linker counts it), and none where it only is
// declared. A block is named by its block name.
TEST(Check, AnInputNothingFeedsIsAnErrorBeforeTheDriver) {
  TempDir dir;
  write_file(dir / "scene.frag", "varying vec4 v_color;\n"
                                 "varying vec4 v_unused;\n"
                                 "varying vec3 v_normal;\n"
                                 "vec3 never_called() { return v_normal; }\n"
                                 "void main() { gl_FragColor = v_color; }\n");
  write_file(dir / "block.frag", "#version 330\nin Data { vec4 c; } d;\nout vec4 o;\nvoid main() { o = d.c; }\n");
  const std::string tail =
      " is an input from a vertex shader, and the host's passes on nothing (glslViewer's v_texcoord is the one "
      "input it supplies)\n";
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  EXPECT_EQ(join(diags), (dir / "scene.frag").string() + ":3:14: error: 'v_normal'" + tail +
                             (dir / "scene.frag").string() + ":1:14: error: 'v_color'" + tail);
  check_scene(dir / "block.frag", {}, &diags);
  EXPECT_EQ(join(diags), (dir / "block.frag").string() + ":2:4: error: 'Data'" + tail);
}

// The one diagnostic a driver's log line maps to, for `scene` (preprocessed
// as the host does); "" where there is not exactly one.
std::string the_one_mapped(const fs::path& scene, const std::string& log) {
  const Source s = preprocess(scene, {});
  EXPECT_TRUE(s.ok()) << join(s.errors);
  const Diagnostics d = map_log(log, s, LogFormat::Mesa);
  EXPECT_EQ(d.size(), 1u) << join(d);
  return d.size() == 1 ? d[0].str() : "";
}

// Too many uniform components for the driver names no line; the place is
// the scene's uniform with the most, in whichever file declares it (one in
// a comment, the host's own, a smaller one and a macro's size do not count).
TEST(MapLog, TooManyUniformComponentsIsAtTheLargestUniform) {
  TempDir dir;
  write_file(dir / "inc.glsl", "// uniform vec4 commented[100000];\nuniform float small[10];\n"
                               "#define N 100000\nuniform vec4 by_macro[N];\n  uniform highp vec3 u[2][50];\n");
  write_file(dir / "scene.frag", "#include \"inc.glsl\"\nuniform mat4 m;\n"
                                 "void mainImage(out vec4 c, in vec2 f) { c = vec4(u[0][0], 1.0) + m[0]; }\n");
  EXPECT_EQ(the_one_mapped(dir / "scene.frag", "error: Too many fragment shader default uniform block components\n"),
            (dir / "inc.glsl").string() +
                ":5:22: error: 'u' : its 300 components take the fragment shader's uniforms past what the driver "
                "allows (Too many fragment shader default uniform block components)");
  // Sizes past any driver's limit stop at 2^40 components, with no overflow.
  write_file(dir / "huge.frag", "uniform mat2x3 m[4];\nuniform float huge[99999999999][99999999999][9];\n"
                                "void mainImage(out vec4 c, in vec2 f) { c = vec4(huge[0][0][0]); }\n");
  EXPECT_EQ(the_one_mapped(dir / "huge.frag", "error: Too many fragment shader uniform components\n"),
            (dir / "huge.frag").string() +
                ":2:15: error: 'huge' : its 1099511627776 components take the fragment shader's uniforms past what "
                "the driver allows (Too many fragment shader uniform components)");
}

TEST(MapLog, UnresolvedFunctionPointsAtItsFirstMention) {
  TempDir dir;
  write_file(dir / "scene.frag", "#include \"lib.glsl\"\n"
                                 "void mainImage(out vec4 c, in vec2 f) { c = vec4(helper(f)); }\n");
  write_file(dir / "lib.glsl", "// helper(): the scene's own\nfloat unhelpful(vec2 p) { return 0.0; }\n"
                               "  float helper(vec2 p);\n");
  EXPECT_EQ(the_one_mapped(dir / "scene.frag", "error: unresolved reference to function `helper'\n"),
            (dir / "lib.glsl").string() + ":3:9: error: unresolved reference to function `helper'");
}

}  // namespace
}  // namespace rm

namespace rm {
namespace {

TEST(Check, SyntaxErrorPointsAtTheUnexpectedToken) {
  test::TempDir dir;
  test::write_file(dir / "scene.frag", "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(1.0) +;\n}\n");
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  ASSERT_GE(count_errors(diags), 1);
  EXPECT_EQ(diags[0].str(), (dir / "scene.frag").string() + ":2:18: error: syntax error, unexpected ';'");
}

// The diagnostics of scene.frag in `dir`: `body` as the body of mainImage,
// whose code starts on line 3, after a struct Ray.
Diagnostics diagnostics_of_main_body(const test::TempDir& dir, const std::string& body) {
  test::write_file(dir / "scene.frag", "struct Ray { vec3 o; };\nvoid mainImage(out vec4 c, in vec2 f) {\n" + body + "}\n");
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  return diags;
}

// glslang names the line of a token it did not expect, not the token: the
// worker finds which of the line's it is (a struct's name before it is a
// type, a word in a comment is none, the same name or sign may come twice).
TEST(Check, AnUnexpectedTokenIsPointedAt) {
  test::TempDir dir;
  const std::string scene = (dir / "scene.frag").string();
  const std::pair<std::string, std::string> cases[] = {
      {"  float a = 1.0, b = 2.0;\n  c = /* a b */ vec4(a b, a, 1.0);\n",
       ":4:24: error: syntax error, unexpected identifier, expecting ')' or ','"},
      {"  Ray r = Ray(vec3(0.0)) x; c = vec4(r.o, 1.0);\n",
       ":3:26: error: syntax error, unexpected identifier, expecting ',' or ';'"},
      {"  float d = 1.0; d = d d; c = vec4(d);\n",
       ":3:24: error: syntax error, unexpected identifier, expecting ',' or ';'"},
      // Numbers the same way.
      {"  c = vec4(1.0, 1e-3 .5, 1.0);\n", ":3:22: error: syntax error, unexpected float constant, expecting ')' or ','"},
      {"  c = vec4(1.0, 2.0 1, 1.0);\n", ":3:21: error: syntax error, unexpected int constant, expecting ')' or ','"},
      // Signs and keywords: not their first spelling on the line, nor one in a comment.
      {"  c = vec4(1.0)); // )\n", ":3:16: error: syntax error, unexpected ')', expecting ',' or ';'"},
      {"  float a = 1.0; a += 2.0; a = = 3.0; c = vec4(a);\n", ":3:32: error: syntax error, unexpected '='"},
      {"  int i = 1; i <<= 1; i <<= <<= 2; c = vec4(i);\n", ":3:29: error: syntax error, unexpected '<<='"},
      {"  c = vec4(1.0); if (c.x > 0.0) return; return return;\n", ":3:48: error: syntax error, unexpected 'return'"},
  };
  for (const auto& [body, expected] : cases) {
    const Diagnostics diags = diagnostics_of_main_body(dir, body);
    ASSERT_FALSE(diags.empty()) << body;
    EXPECT_EQ(diags[0].str(), scene + expected) << body;
  }
}

// A token that starts its line, where the line above lacks a ';' (or a ')'
// or ','), is named as gcc and clang name it: where the missing token goes,
// at the end of the code above, past comments, blank lines and #defines
// (their bodies continued by backslashes too), and after an earlier error
// too. Across a conditional (which branch was compiled is not known)
// glslang's place stays.
TEST(Check, ASeparatorMissingAtALinesEndIsNamedWhereItGoes) {
  test::TempDir dir;
  const std::string scene = (dir / "scene.frag").string();
  const std::pair<std::string, std::string> cases[] = {
      {"  vec3 col = vec3(0.0)\n  col += 1.0;\n  c = vec4(col, 1.0);\n",
       ":3:23: error: syntax error, expecting ',' or ';' before 'col'"},
      {"  float a = 1.0\n  Ray r = Ray(vec3(a)); c = vec4(r.o, 1.0);\n",
       ":3:16: error: syntax error, expecting ',' or ';' before 'Ray'"},
      {"  c = vec4(1.0) // no ;\n  /* a comment\n  */\n\n}\n",
       ":3:16: error: syntax error, expecting ',' or ';' before '}'"},
      {"  c = vec4(1.0);\n  if (c.x > 0.0) c = vec4(0.5)\n  else return;\n",
       ":4:31: error: syntax error, expecting ',' or ';' before 'else'"},
      {"  c = vec4(1.0,\n           2.0\n           1.5e-3, 1.0);\n",
       ":4:15: error: syntax error, expecting ')' or ',' before '1.5e-3'"},
      {"  c = vec4(nope)\n  return;\n", ":3:12: error: 'nope' : undeclared identifier\n" + scene +
       ":3:17: error: syntax error, expecting ',' or ';' before 'return'"},
      {"  c = vec4(1.0)\n#ifdef NOPE\n  c.x = 0.0;\n#endif\n  return;\n",
       ":7:3: error: syntax error, unexpected 'return', expecting ',' or ';'"},
      {"  c = vec4(1.0)\n#define HALF 0.5\n#pragma optimize(on)\n  c.x = HALF;\n",
       ":3:16: error: syntax error, expecting ',' or ';' before 'c'"},
      // A body continued by backslashes is the #define's, not code left unfinished.
      {"  c = vec4(1.0)\n  #define TWICE(x) \\\n    (x) * \\\n    2.0\n  c.x = TWICE(c.y);\n",
       ":3:16: error: syntax error, expecting ',' or ';' before 'c'"},
  };
  for (const auto& [body, expected] : cases)
    EXPECT_EQ(join(diagnostics_of_main_body(dir, body)), scene + expected + "\n") << body;
}

// A type error names the types as GLSL writes them, and an assignment's is
// at its '=' when the line has one.
TEST(Check, ATypeErrorNamesTheTypesAsGlslDoes) {
  test::TempDir dir;
  test::write_file(dir / "scene.frag",
                   "void mainImage(out vec4 c, in vec2 f) {\n  vec3 a = vec3(1.0);\n  c = a;\n}\n");
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  EXPECT_EQ(join(diags), (dir / "scene.frag").string() + ":3:5: error: '=' : cannot convert from 'vec3' to 'out vec4'\n");
  test::write_file(dir / "scene.frag",
                   "void mainImage(out vec4 c, in vec2 f) {\n  vec3 a = vec3(1.0); c = a * mat2(1.0);\n}\n");
  check_scene(dir / "scene.frag", {}, &diags);
  // glslang goes on with the left operand's vec3, and its '=' then fails
  // too: the same line's echo, not shown (AnErrorsEchoOnItsLineIsNotShown).
  EXPECT_EQ(join(diags), (dir / "scene.frag").string() +
                             ":2:29: error: '*' : wrong operand types: no operation '*' exists that takes a left-hand "
                             "operand of type 'vec3' and a right operand of type 'const mat2' (or there is no "
                             "acceptable conversion)\n");
}

// Every error is named, as a compiler names them, not only the first (which
// glslang does by default: a shader with three mistakes took three saves).
TEST(Check, EveryErrorIsNamedNotOnlyTheFirst) {
  TempDir dir;
  write_file(dir / "lib.glsl", "float g() {\n  return radius;\n}\n");
  const std::string scene = (dir / "scene.frag").string();
  EXPECT_EQ(diagnostics_of_scene(dir, "#include \"lib.glsl\"\nvoid mainImage(out vec4 c, in vec2 f) {\n"
                                      "  float a = foo;\n  vec3 v = vec2(a);\n  int i = 1.5;\n  c = vec4(v, g());\n}\n"),
            (dir / "lib.glsl").string() + ":2:10: error: 'radius' : undeclared identifier\n" + scene +
                             ":3:13: error: 'foo' : undeclared identifier\n" + scene +
                             ":4:10: error: '=' : cannot convert from 'vec2' to 'vec3'\n" + scene +
                             ":5:9: error: '=' : cannot convert from 'const float' to 'int'\n");
}

// Past 20 errors the rest are not named, as clang does: the first error
// stays in sight.
TEST(Check, PastTwentyErrorsTheRestAreNotNamed) {
  test::TempDir dir;
  std::string code = "void mainImage(out vec4 c, in vec2 f) {\n  float a = 0.0;\n";
  for (int i = 0; i < 25; ++i) code += "  a += u" + std::to_string(i) + ";\n";
  test::write_file(dir / "scene.frag", code + "  c = vec4(a);\n}\n");
  Diagnostics diags;
  check_scene(dir / "scene.frag", {}, &diags);
  ASSERT_EQ(diags.size(), 21u);
  EXPECT_EQ(diags[19].str(), (dir / "scene.frag").string() + ":22:8: error: 'u19' : undeclared identifier");
  EXPECT_EQ(diags[20].str(), (dir / "scene.frag").string() + ": error: too many errors; only the first 20 are named");
}

// An error that follows from one before it on its line is not shown: a
// field the struct lacks, then the assignment to it; an undeclared sampler,
// then no texture() that takes it. A second undeclared name is news.
TEST(Check, AnErrorsEchoOnItsLineIsNotShown) {
  test::TempDir dir;
  const std::string scene = (dir / "scene.frag").string();
  EXPECT_EQ(diagnostics_of_scene(dir, "struct S { float x; };\nvoid mainImage(out vec4 c, in vec2 f) {\n"
                                      "  S s; s.y = 1.0;\n  c = texture(noSampler, f);\n  float a = foo + bar;\n"
                                      "  c = vec4(a);\n}\n"),
            scene + ":3:10: error: 'y' : no such field in structure 's'\n" + scene +
                             ":4:15: error: 'noSampler' : undeclared identifier\n" + scene +
                             ":5:13: error: 'foo' : undeclared identifier\n" + scene +
                             ":5:19: error: 'bar' : undeclared identifier\n");
}

// An #if really left open after an error is still named where it opens.
TEST(Check, AConditionalLeftOpenAfterAnErrorIsNamed) {
  test::TempDir dir;
  const std::string scene = (dir / "scene.frag").string();
  EXPECT_EQ(diagnostics_of_scene(dir, "void mainImage(out vec4 c, in vec2 f) {\n#if 1\n  c = vec4(foo);\n}\n"),
            scene + ":3:12: error: 'foo' : undeclared identifier\n" + scene + ":2:1: error: unterminated #if\n");
}

// Going on past an error, glslang 11 crashes on an empty initializer list
// (fixed upstream in 2026, KhronosGroup/glslang#4385). The worker then
// parses again as glslang does by default, and its first error is named.
TEST(Check, WhereGlslangsRecoveryCrashesItsFirstErrorIsNamed) {
  test::TempDir dir;
  EXPECT_EQ(diagnostics_of_scene(
                dir, "struct S { float x; };\nconst S s = {};\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(s.x); }\n"),
            (dir / "scene.frag").string() +
                             ":2: error: 'empty { } initializer' : not supported for this version or the enabled "
                             "extensions\n");
}

}  // namespace
}  // namespace rm
