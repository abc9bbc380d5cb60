// Number tweaks: which literals a twin reads from rm_Tweak, and which edits
// keep the skeleton (a tweak) or change it (a code edit that compiles).
#include "core/tweak.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "core/lexing.h"

namespace rm {
namespace {

// A scene and a library file, served from memory: /lib stands for shaderlib.
Source source_of(const std::string& scene, const std::string& library = "float libF() { return 0.75; }\n") {
  FileSystem memory;
  const size_t body = scene.rfind("#version", 0) == 0 ? scene.find('\n') + 1 : 0;  // after a #version
  const std::string text = scene.substr(0, body) + "#include <rm/x.glsl>\n" + scene.substr(body);
  const std::map<fs::path, std::string> files{{"/s/scene.frag", text},
                                               {"/lib/rm/x.glsl", library}};
  memory.read = [files](const fs::path& p, Diagnostic* why) -> std::optional<std::string> {
    if (auto it = files.find(p); it != files.end()) return it->second;
    why->message = "no such file";
    return std::nullopt;
  };
  memory.exists = [files](const fs::path& p) { return files.count(p) != 0; };
  SourceOptions options;
  options.shaderlib_dir = "/lib";
  Source s = preprocess("/s/scene.frag", options, memory);
  EXPECT_TRUE(s.ok()) << join(s.errors);
  return s;
}

LiftedLiterals lift(const std::string& scene, LiftScope scope = LiftScope::FunctionBodies) {
  return lift_literals(source_of(scene), "/lib", scope);
}

constexpr char kScene[] = R"(#define GAIN 2.5
const float kScale = 1.5;
float glow = 0.5;
struct Light { vec3 dir; };
float shade(float x) {
  const float k = 3.0;  // a const: a constant is needed
  return x * 0.25 + k * 1e-2 /* 9.0 */ + float(2) + 0x1F + GAIN;
}
void mainImage(out vec4 c, in vec2 f) {
  float a[2] = float[2](.5, 4.);
  c = vec4(shade(f.x) * 1.0e+1, a[0], 7.0f, 1.0);
}
)";

TEST(Tweak, OnlyFloatLiteralsInTheUsersFunctionBodiesAreLifted) {
  const LiftedLiterals lifted = lift(kScene);
  ASSERT_TRUE(lifted.ok);
  // Not: the #define, the global const and initialiser, the local const,
  // the comment, the ints, the hex, nor the library's 0.75.
  EXPECT_EQ(lifted.values, (std::vector<float>{0.25f, 1e-2f, 0.5f, 4.0f, 10.0f, 7.0f, 1.0f}));
  EXPECT_NE(lifted.skeleton.find("kScale = 1.5"), std::string::npos);
  EXPECT_NE(lifted.skeleton.find("glow = 0.5"), std::string::npos);
  EXPECT_NE(lifted.skeleton.find("k = 3.0"), std::string::npos);
  EXPECT_NE(lifted.skeleton.find("return 0.75"), std::string::npos);
}

// The compiler splices a line that ends in a backslash onto the next before it
// strips comments (glslang warns of it), so a // comment so ended swallows the
// next line: no code, and no number to lift. Lifted, the twin's text would
// hold a line the scene's program does not. With \n and with \r\n.
TEST(Tweak, ACommentThatEndsInABackslashSwallowsTheNextLine) {
  for (const std::string eol : {"\n", "\r\n"}) {
    const std::string scene = "float f(float x) {" + eol + "  // was: \\" + eol + "  x *= 3.5;" + eol +
                              "  return x * 0.5;" + eol + "}" + eol +
                              "void mainImage(out vec4 c, in vec2 p) { c = vec4(f(p.x)); }" + eol;
    const Source source = source_of(scene);
    const LiftedLiterals lifted = lift_literals(source, "/lib");
    ASSERT_TRUE(lifted.ok);
    EXPECT_EQ(lifted.values, std::vector<float>{0.5f});
    EXPECT_EQ(lifted.skeleton.find("3.5"), std::string::npos);
    // Every line keeps its number.
    EXPECT_EQ(std::count(lifted.skeleton.begin(), lifted.skeleton.end(), '\n'),
              std::count(source.text.begin(), source.text.end(), '\n'));
  }
}

TEST(Tweak, ANumberEditKeepsTheSkeletonAndACodeEditChangesIt) {
  const LiftedLiterals before = lift(kScene);
  std::string scene = kScene;
  scene.replace(scene.find("x * 0.25"), 8, "x * 0.375");
  const LiftedLiterals number = lift(scene);
  EXPECT_EQ(number.skeleton, before.skeleton);
  EXPECT_EQ(number.values[0], 0.375f);

  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"kScale = 1.5", "kScale = 1.25"},  // a global const
           {"k = 3.0", "k = 3.5"},            // a local const
           {"GAIN 2.5", "GAIN 2.0"},          // a macro
           {"* 0.25", "* 1"},                 // a float become an int
           {"x * 0.25", "x / 0.25"}}) {       // an operator
    std::string code = kScene;
    code.replace(code.find(from), from.size(), to);
    EXPECT_NE(lift(code).skeleton, before.skeleton) << from << " -> " << to;
  }
  // A comment is not code: the same skeleton's code, and the same values.
  std::string commented = kScene;
  commented.replace(commented.find("9.0"), 3, "12.0");
  EXPECT_EQ(lexing::code_only(lift(commented).skeleton), lexing::code_only(before.skeleton));
  EXPECT_EQ(lift(commented).values, before.values);
}

// With the constants: a #define's value, a global float const and a global
// float's initialiser, a local float const; still not the ints, the hex, the
// comment nor the library.
TEST(Tweak, WithConstantsTheFloatConstantsGlobalsAndDefinesAreLiftedToo) {
  const LiftedLiterals lifted = lift(kScene, LiftScope::WithConstants);
  ASSERT_TRUE(lifted.ok);
  EXPECT_EQ(lifted.values,
            (std::vector<float>{2.5f, 1.5f, 0.5f, 3.0f, 0.25f, 1e-2f, 0.5f, 4.0f, 10.0f, 7.0f, 1.0f}));
  EXPECT_EQ(lifted.constants, 4u);
  EXPECT_NE(lifted.skeleton.find("return 0.75"), std::string::npos);

  // Each of those edits keeps the skeleton that way, and only that way.
  const LiftedLiterals before = lift(kScene, LiftScope::WithConstants);
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"kScale = 1.5", "kScale = 1.25"}, {"k = 3.0", "k = 3.5"}, {"GAIN 2.5", "GAIN 2.0"}, {"glow = 0.5", "glow = 0.1"}}) {
    std::string code = kScene;
    code.replace(code.find(from), from.size(), to);
    EXPECT_EQ(lift(code, LiftScope::WithConstants).skeleton, before.skeleton) << from << " -> " << to;
    EXPECT_NE(lift(code).skeleton, lift(kScene).skeleton) << from << " -> " << to;
  }
  // An int stays an int; a float become an int is a code edit.
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{{"float(2)", "float(3)"},
                                                                                   {"kScale = 1.5", "kScale = 1"}}) {
    std::string code = kScene;
    code.replace(code.find(from), from.size(), to);
    EXPECT_NE(lift(code, LiftScope::WithConstants).skeleton, before.skeleton) << from << " -> " << to;
  }
  // Nothing but what the function bodies hold: no constants, the same skeleton.
  const std::string bodies_only = "int n = 3;\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(0.5); }\n";
  EXPECT_EQ(lift(bodies_only, LiftScope::WithConstants).constants, 0u);
  EXPECT_EQ(lift(bodies_only, LiftScope::WithConstants).skeleton, lift(bodies_only).skeleton);
}

// The twin makes them variables: a local const loses `const`; a global's
// initialiser moves into main(), after rm_Tweak is read, and its lines stay.
TEST(Tweak, TheTwinSetsTheGlobalsInMainAndDropsTheLocalConst) {
  const Source source = source_of(kScene);
  const Source twin = twin_source(source, lift_literals(source, "/lib", LiftScope::WithConstants));
  EXPECT_NE(twin.text.find("#define GAIN rm_Tweak_0\n float kScale ;\nfloat glow ;\n"), std::string::npos) << twin.text;
  EXPECT_NE(twin.text.find("  float k = rm_Tweak_3;"), std::string::npos);
  EXPECT_NE(twin.text.find("rm_Tweak_10 = rm_Tweak[10]; kScale = rm_Tweak_1; glow = rm_Tweak_2;"), std::string::npos);
  EXPECT_EQ(std::count(twin.text.begin(), twin.text.end(), '\n'), std::count(source.text.begin(), source.text.end(), '\n') + 1);

  // Declarators in a list, arrays, an initialiser over two lines; an int
  // const, a function, a uniform and the library are left alone.
  const std::string scene = "const int kN = 2;\nconst float a = 1.5, b[2] = float[](2.5,\n  a);\n"
                            "uniform float u;\nvec2 half(vec2 p) { return p * 0.5; }\n"
                            "void mainImage(out vec4 c, in vec2 f) { c = vec4(a, b[1], u, 1.0); }\n";
  const Source s = source_of(scene);
  const LiftedLiterals lifted = lift_literals(s, "/lib", LiftScope::WithConstants);
  EXPECT_EQ(lifted.values, (std::vector<float>{1.5f, 2.5f, 0.5f, 1.0f}));
  const std::string text = twin_source(s, lifted).text;
  EXPECT_NE(text.find("const int kN = 2;\n float a , b[2] \n;\n"), std::string::npos) << text;
  EXPECT_NE(text.find("rm_Tweak_3 = rm_Tweak[3]; a = rm_Tweak_0; b = float[](rm_Tweak_1,   a);"), std::string::npos) << text;
  EXPECT_NE(text.find("return p * rm_Tweak_2;"), std::string::npos);
  EXPECT_NE(text.find("return 0.75"), std::string::npos);
}

TEST(Tweak, TheTwinReadsEachLiteralFromAGlobalThatMainSetsFromTheArray) {
  const Source source = source_of(kScene);
  const LiftedLiterals lifted = lift_literals(source, "/lib");
  const Source twin = twin_source(source, lifted);
  EXPECT_NE(twin.text.find("uniform float rm_Tweak[7]; float rm_Tweak_0, rm_Tweak_1, rm_Tweak_2, rm_Tweak_3, "
                           "rm_Tweak_4, rm_Tweak_5, rm_Tweak_6;\n"),
            std::string::npos);
  EXPECT_NE(twin.text.find("x * rm_Tweak_0 + k * rm_Tweak_1"), std::string::npos) << twin.text;
  EXPECT_NE(twin.text.find("c = vec4(shade(f.x) * rm_Tweak_4, a[0], rm_Tweak_5, rm_Tweak_6);"), std::string::npos);
  // The host's main() (a Shadertoy shader's) sets them first, on its own line.
  EXPECT_NE(twin.text.find("void main() { rm_Tweak_0 = rm_Tweak[0]; rm_Tweak_1 = rm_Tweak[1];"), std::string::npos);
  EXPECT_EQ(std::count(twin.text.begin(), twin.text.end(), '\n'), std::count(source.text.begin(), source.text.end(), '\n') + 1);
  // One line more, a host line: the user's lines map to where they did.
  ASSERT_EQ(twin.line_map.size(), source.line_map.size() + 1);
  const std::string first_user_line = "#define GAIN 2.5";
  auto line_of = [](const Source& s, const std::string& text) {
    return std::count(s.text.begin(), s.text.begin() + static_cast<std::ptrdiff_t>(s.text.find(text)), '\n');
  };
  EXPECT_EQ(twin.locate(static_cast<int>(line_of(twin, first_user_line)) + 1),
            source.locate(static_cast<int>(line_of(source, first_user_line)) + 1));
}

// What the twin's preprocessor says of a knob, in the exact program's words:
// each rm_Tweak_i as literal i was written, other words left alone.
TEST(Tweak, TheTwinsNamesReadAsTheLiteralsWritten) {
  const Source source = source_of(kScene);
  const LiftedLiterals lifted = lift_literals(source, "/lib");
  ASSERT_EQ(lifted.literals.size(), lifted.values.size());
  EXPECT_EQ(lifted.literals[0], "0.25");
  EXPECT_EQ(lifted.literals[1], "1e-2");
  EXPECT_EQ(lifted.literals[5], "7.0f");
  const std::vector<std::string> literals = {"0.50", "1e-4", "2.f"};
  EXPECT_EQ(with_literals("rm_Tweak_1", literals), "1e-4");
  EXPECT_EQ(with_literals("( 100.0 * rm_Tweak_0 ) + rm_Tweak_2", literals), "( 100.0 * 0.50 ) + 2.f");
  EXPECT_EQ(with_literals("xrm_Tweak_1 rm_Tweak_1x rm_Tweak_ rm_Tweak_3", literals),
            "xrm_Tweak_1 rm_Tweak_1x rm_Tweak_ rm_Tweak_3");
  EXPECT_EQ(with_literals("", literals), "");
  // A knob whose value is one such name reads a lifted literal.
  EXPECT_TRUE(is_lifted_name("rm_Tweak_12"));
  for (const char* text : {"rm_Tweak_", "rm_Tweak_1x", "( rm_Tweak_1 )", "rm_Tweak_1 * 2.0", "0.5", ""})
    EXPECT_FALSE(is_lifted_name(text)) << text;
}

TEST(Tweak, EveryMainSetsTheGlobals) {
  // A complete shader with a main() in each branch of an #if: both set them.
  const std::string complete = "#version 450\nout vec4 o;\n#ifdef A\nvoid main() { o = vec4(0.5); }\n#else\n"
                               "void main ( void )\n{\n  o = vec4(0.25);\n}\n#endif\n";
  const Source source = source_of(complete);
  const LiftedLiterals lifted = lift_literals(source, "/lib");
  ASSERT_TRUE(lifted.ok);
  EXPECT_EQ(lifted.main_bodies.size(), 2u);
  const std::string twin = twin_source(source, lifted).text;
  EXPECT_NE(twin.find("void main() { rm_Tweak_0 = rm_Tweak[0]; rm_Tweak_1 = rm_Tweak[1]; o = vec4(rm_Tweak_0); }"),
            std::string::npos) << twin;
  EXPECT_NE(twin.find("{ rm_Tweak_0 = rm_Tweak[0]; rm_Tweak_1 = rm_Tweak[1];\n  o = vec4(rm_Tweak_1);"), std::string::npos);
}

TEST(Tweak, AFiniteLiteralAlwaysAndNeverMoreThanTheLimit) {
  EXPECT_FALSE(lift("void mainImage(out vec4 c, in vec2 f) { c = vec4(1e99); }\n").ok);
  std::string many = "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.0)";
  for (size_t i = 0; i < kMaxTweaks; ++i) many += " + 1.0";
  EXPECT_FALSE(lift(many + "; }\n").ok);
  EXPECT_TRUE(lift("void mainImage(out vec4 c, in vec2 f) { c = vec4(0.0) + 1.0; }\n").ok);
}

}  // namespace
}  // namespace rm
