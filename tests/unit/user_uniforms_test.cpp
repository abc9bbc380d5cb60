// The shader's own uniforms: every type with a control, the `// ui:`
// annotation, arrays and bad annotations (warnings, never failures),
// uniforms in inactive #if blocks, and the values `--set` gives.
#include <gtest/gtest.h>

#include "core/data_paths.h"
#include "core/user_uniforms.h"
#include "support.h"

namespace rm {
namespace {

UserUniforms uniforms_of(const std::string& text) {
  test::TempDir dir;
  test::write_file(dir / "s.frag", text + "void mainImage(out vec4 c, in vec2 f) { c = vec4(0); }\n");
  const Source source = preprocess(dir / "s.frag", {});
  EXPECT_TRUE(source.ok()) << join(source.errors);
  return find_user_uniforms(source);
}

TEST(UserUniforms, EveryTypeWithItsAnnotation) {
  const UserUniforms u = uniforms_of(
      "uniform float speed;   // ui: min=0 max=4 step=0.1 default=1\n"
      "uniform int count;     // ui: min=1 max=8 default=3\n"
      "uniform bool rings;    // ui: default=true\n"
      "uniform vec2 offset;\n"
      "uniform highp vec3 tint;  // ui: color default=1,0.5,0.2\n"
      "uniform vec4 glow, haze;  // ui: colour\n"
      "uniform float iTime;  // the host's: no control\n");
  ASSERT_EQ(u.uniforms.size(), 7u);
  EXPECT_TRUE(u.warnings.empty()) << join(u.warnings);
  const UserUniform& speed = u.uniforms[0];
  EXPECT_EQ(speed.name, "speed");
  EXPECT_EQ(speed.type, UserUniform::Type::Float);
  EXPECT_EQ(speed.min, 0.0f);
  EXPECT_EQ(speed.max, 4.0f);
  EXPECT_FLOAT_EQ(speed.step, 0.1f);
  EXPECT_EQ(speed.initial, std::vector<float>{1.0f});
  EXPECT_EQ(speed.line, 1);
  EXPECT_EQ(u.uniforms[1].type, UserUniform::Type::Int);
  EXPECT_EQ(u.uniforms[1].initial, std::vector<float>{3.0f});
  EXPECT_EQ(u.uniforms[2].initial, std::vector<float>{1.0f}) << "true";
  EXPECT_EQ(u.uniforms[3].components, 2);
  EXPECT_EQ(u.uniforms[3].initial, (std::vector<float>{0, 0})) << "no annotation: zeros";
  EXPECT_TRUE(u.uniforms[4].color);
  EXPECT_EQ(u.uniforms[4].initial, (std::vector<float>{1.0f, 0.5f, 0.2f}));
  EXPECT_EQ(u.uniforms[5].name, "glow");
  EXPECT_EQ(u.uniforms[6].name, "haze");
  EXPECT_TRUE(u.uniforms[6].color) << "the annotation is the whole declaration's";
}

TEST(UserUniforms, ArraysAndBadAnnotationsAreWarningsNeverFailures) {
  const UserUniforms u = uniforms_of("uniform float weights[3];\n"
                                     "uniform float a;  // ui: max=x wat\n"
                                     "uniform float b;  // ui: color default=1,2\n"
                                     "uniform mat3 m;   // no control, no word\n");
  ASSERT_EQ(u.uniforms.size(), 2u);
  EXPECT_EQ(u.uniforms[0].name, "a");
  ASSERT_EQ(u.warnings.size(), 5u) << join(u.warnings);
  EXPECT_NE(u.warnings[0].message.find("weights is an array: it gets no control"), std::string::npos);
  EXPECT_EQ(u.warnings[0].line, 1);
  EXPECT_NE(u.warnings[1].message.find("max=x is not a number"), std::string::npos);
  EXPECT_NE(u.warnings[2].message.find("'wat' is not understood"), std::string::npos);
  EXPECT_NE(u.warnings[3].message.find("only a vec3 or vec4 can be a colour"), std::string::npos);
  EXPECT_NE(u.warnings[4].message.find("default=1,2"), std::string::npos);
  for (const Diagnostic& w : u.warnings) EXPECT_EQ(w.severity, Severity::Warning);
}

TEST(UserUniforms, AWarningQuotesALongWordBriefly) {
  const std::string x(100000, 'x');
  const UserUniforms u = uniforms_of("uniform float a;  // ui: max=" + x + " " + x + " default=" + x + "\n");
  ASSERT_EQ(u.warnings.size(), 3u) << join(u.warnings).substr(0, 300);
  EXPECT_NE(u.warnings[0].message.find("max=" + std::string(40, 'x') + "... is not a number"), std::string::npos);
  EXPECT_NE(u.warnings[1].message.find("'" + std::string(40, 'x') + "...' is not understood"), std::string::npos);
  EXPECT_NE(u.warnings[2].message.find("default=" + std::string(40, 'x') + "...: '" + std::string(40, 'x') + "...'"),
            std::string::npos)
      << u.warnings[2].message.substr(0, 300);
  for (const Diagnostic& w : u.warnings) EXPECT_LT(w.message.size(), 300u);
}

TEST(UserUniforms, OnlyTheActiveCodeCounts) {
  const UserUniforms u = uniforms_of("#ifdef NEVER\nuniform float hidden;\n#else\nuniform float shown;\n#endif\n"
                                     "// uniform float commented;\n");
  ASSERT_EQ(u.uniforms.size(), 1u);
  EXPECT_EQ(u.uniforms[0].name, "shown");
}

// shaderlib's own uniform (rm/common.glsl's rm_Zero, which no one sets) is
// the library's, not a control of the scene's.
TEST(UserUniforms, ShaderlibsOwnUniformIsNoControl) {
  test::TempDir dir;
  test::write_file(dir / "s.frag", "#include <rm/common.glsl>\nuniform float gain;\n"
                                   "void mainImage(out vec4 c, in vec2 f) { c = vec4(gain); }\n");
  SourceOptions options;
  options.shaderlib_dir = shaderlib_dir();
  const Source source = preprocess(dir / "s.frag", options);
  ASSERT_TRUE(source.ok()) << join(source.errors);
  ASSERT_NE(source.text.find("uniform int rm_Zero;"), std::string::npos);
  const UserUniforms u = find_user_uniforms(source);
  ASSERT_EQ(u.uniforms.size(), 1u);
  EXPECT_EQ(u.uniforms[0].name, "gain");
}

TEST(UserUniforms, SetGivesValuesAndRefusesWhatDoesNotFit) {
  const UserUniforms u = uniforms_of("uniform float speed;  // ui: default=1\nuniform vec3 tint;\nuniform bool on;\n");
  std::string error;
  auto values = uniform_values(u, {"tint=0.1,0.2,0.3", "on=true"}, &error);
  ASSERT_TRUE(values) << error;
  ASSERT_EQ(values->size(), 3u);
  EXPECT_EQ((*values)[0].text, "1") << "the default";
  EXPECT_EQ((*values)[1].value, (std::vector<float>{0.1f, 0.2f, 0.3f}));
  EXPECT_EQ((*values)[2].text, "true");
  EXPECT_FALSE(uniform_values(u, {"nope=1"}, &error));
  EXPECT_EQ(error, "'nope=1': the shader declares no uniform 'nope' of its own (it has speed, tint, on)");
  EXPECT_FALSE(uniform_values(u, {"tint=1,2"}, &error));
  EXPECT_EQ(error, "'tint=1,2': '1,2' has 2 numbers; tint takes 3");
  EXPECT_FALSE(uniform_values(u, {"on=maybe"}, &error));
  EXPECT_FALSE(uniform_values(u, {"speed"}, &error));
  EXPECT_EQ(error, "'speed': not NAME=VALUE");
  EXPECT_EQ(uniform_value_text(UserUniform::Type::Float, {-0.0f}), "0") << "never -0";
  EXPECT_EQ(uniform_value_text(UserUniform::Type::Int, {1073741824.0f}), "1073741824") << "an int is whole";
}

// No control holds nan or inf, and an int's value past its range was an
// undefined cast to int.
TEST(UserUniforms, ValuesAreFiniteAndAnIntsFitsAnInt) {
  const UserUniforms u = uniforms_of("uniform float speed;  // ui: max=inf default=1e39\n"
                                     "uniform int count;  // ui: default=3e9\n");
  ASSERT_EQ(u.uniforms.size(), 2u);
  EXPECT_EQ(u.uniforms[0].max, 1.0f) << "max=inf is refused";
  EXPECT_EQ(u.uniforms[0].initial, std::vector<float>{0.0f}) << "so is default=1e39";
  EXPECT_EQ(u.uniforms[1].initial, std::vector<float>{0.0f}) << "and 3e9 for an int";
  ASSERT_EQ(u.warnings.size(), 3u) << join(u.warnings);
  EXPECT_NE(u.warnings[2].message.find("'3e9' is out of an int's range"), std::string::npos) << join(u.warnings);
  std::string error;
  for (const char* set : {"speed=nan", "speed=-inf", "speed=1e39"}) {
    EXPECT_FALSE(uniform_values(u, {set}, &error)) << set;
    EXPECT_NE(error.find("is not a number"), std::string::npos) << error;
  }
  EXPECT_FALSE(uniform_values(u, {"count=-1e10"}, &error));
  EXPECT_EQ(error, "'count=-1e10': '-1e10' is out of an int's range");
  auto values = uniform_values(u, {"count=-2147483648", "speed=-3.4e38"}, &error);
  ASSERT_TRUE(values) << error;
  EXPECT_EQ((*values)[1].value, std::vector<float>{-2147483648.0f});
}

}  // namespace
}  // namespace rm
