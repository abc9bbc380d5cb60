// Words GLSL 4.50 core reserves that Shadertoy's and glslViewer's dialects
// leave free as names: which the host renames, and how messages name them.
#include "core/dialect_names.h"

#include <gtest/gtest.h>

namespace rm {
namespace {

using Names = std::vector<std::string>;

TEST(DialectNames, ANameShadertoyAllowsIsRenamed) {
  EXPECT_EQ(names_core_reserves("vec4 buffer = texture(iChannel0, uv);\nc = buffer;", Dialect::EsSl300),
            Names{"buffer"});
  EXPECT_EQ(names_core_reserves("float shared, precise;\nx = f(shared) * precise;", Dialect::EsSl300),
            (Names{"shared", "precise"}));
  // A function of that name; a name at a line's end, the operand on the next.
  EXPECT_EQ(names_core_reserves("float precise(float x) { return x; }", Dialect::EsSl300), Names{"precise"});
  EXPECT_EQ(names_core_reserves("#define B buffer\nfloat f;", Dialect::EsSl300), Names{"buffer"});
}

TEST(DialectNames, WordsShadertoyReservesTooAreLeftAlone) {
  // ES 3.00 reserves `sample` and makes `smooth` a keyword: Shadertoy
  // rejects them as names, and so does the host, at the same place.
  EXPECT_EQ(names_core_reserves("float sample = 1.0; float smooth = sample;", Dialect::EsSl300), Names{});
  EXPECT_EQ(names_core_reserves("float sample = 1.0; float smooth = sample;", Dialect::Glsl110),
            (Names{"sample", "smooth"}));
}

TEST(DialectNames, AQualifierUseOrAMacroOfItsOwnKeepsTheWord) {
  EXPECT_EQ(names_core_reserves("precise float x = 1.0;\nfloat y = x;", Dialect::EsSl300), Names{});
  EXPECT_EQ(names_core_reserves("layout(location = 0) out vec4 o;\nflat in int id;", Dialect::Glsl110), Names{});
  EXPECT_EQ(names_core_reserves("buffer Block { float v[]; };", Dialect::EsSl300), Names{});
  // Both uses: renaming would break the qualifier; the name stays an error.
  EXPECT_EQ(names_core_reserves("precise float x;\nfloat precise = 1.0;", Dialect::EsSl300), Names{});
  EXPECT_EQ(names_core_reserves("#define sample(p) texture(iChannel0, p)\nc = sample(uv);", Dialect::Glsl110),
            Names{});
  EXPECT_EQ(names_core_reserves("float buffer_a, sampled, my_sample;", Dialect::Glsl110), Names{});
}

TEST(DialectNames, MessagesNameTheWordAsTheCodeSpellsIt) {
  const Names renamed = {"buffer", "sample"};
  EXPECT_EQ(with_names_restored("'rm_buffer' : redefinition", renamed), "'buffer' : redefinition");
  EXPECT_EQ(with_names_restored("'rm_sample' : undeclared identifier; rm_sample", renamed),
            "'sample' : undeclared identifier; sample");
  // The host's other names, and words that only begin so, stay.
  EXPECT_EQ(with_names_restored("rm_FragColor rm_buffers rm_shared xrm_buffer", renamed),
            "rm_FragColor rm_buffers rm_shared xrm_buffer");
  EXPECT_EQ(compiler_name("buffer"), "rm_buffer");
}

}  // namespace
}  // namespace rm
