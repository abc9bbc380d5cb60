// Debug views through `raymarching render --view`, read back as floats: nan
// marks exactly the bad pixels; steps, normals and depth show what the
// primary ray did (exact counts for a head-on ray at a sphere); a view a
// scene cannot show is a usage error.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/glm.hpp>

#include "support.h"

namespace rm {
namespace {

using test::read_pixels;
using test::run_binary;
using test::TempDir;
using test::write_file;

// A unit sphere 5 in front of the camera; the centre pixel's ray hits it head-on.
const char* kSphere = R"(#include <rm/sdf.glsl>
#include <rm/render.glsl>
float map(vec3 p) { return sdSphere(p, 1.0); }
RmMaterial material(vec3 p, vec3 n) { return rmMaterial(vec3(0.8)); }
void mainImage(out vec4 c, in vec2 f) {
  RmCamera cam = rmLookAt(vec3(0.0, 0.0, 5.0), vec3(0.0), 0.5);
  c = vec4(rmRenderPixel(cam, f, iResolution), 1.0);
}
)";

class Views : public ::testing::Test {
 protected:
  // `scene` rendered to EXR with `args` (a --size and a view): its RGBA floats.
  std::vector<float> render(const std::string& scene, const std::string& args) {
    write_file(dir_ / "scene.frag", scene);
    const auto out = dir_ / "view.exr";
    const test::Outcome r = run_binary("render " + (dir_ / "scene.frag").string() + " -o " + out.string() + " " + args);
    EXPECT_EQ(r.status, 0) << r.err;
    return read_pixels(out);
  }

  // The scene rendered at 9x9 with `args`; the centre pixel's RGBA.
  glm::vec4 centre(const std::string& scene, const std::string& args) {
    const auto px = render(scene, "--size 9x9 " + args);
    if (px.size() != 9 * 9 * 4) return glm::vec4(NAN);
    const size_t i = (4 * 9 + 4) * 4;
    return {px[i], px[i + 1], px[i + 2], px[i + 3]};
  }
  TempDir dir_;
};

TEST_F(Views, DataCountsEveryMapCallAndTheHitDistance) {
  // Two march steps (4, then 0 at the surface) and four normal taps.
  const glm::vec4 data = centre(kSphere, "-D RM_VIEW=5 -D RM_COUNT");
  EXPECT_EQ(data.x, 6.0f);
  EXPECT_NEAR(data.y, 4.0, 1e-3);
  EXPECT_EQ(data.z, 0.0f);  // not NaN
}

TEST_F(Views, NormalsAndDepthShowThePrimaryHit) {
  const glm::vec4 normal = centre(kSphere, "--view normals");
  EXPECT_NEAR(normal.x, 0.5, 1e-3);
  EXPECT_NEAR(normal.y, 0.5, 1e-3);
  EXPECT_NEAR(normal.z, 1.0, 1e-3);  // facing the camera, +z
  const glm::vec4 depth = centre(kSphere, "--view depth");
  EXPECT_NEAR(depth.x, 1.0 - std::log(5.0) / std::log(101.0), 1e-3);
}

TEST_F(Views, StepsIsAHeatmapWithALegend) {
  const auto px = render(kSphere, "--size 100x50 --view steps");
  ASSERT_EQ(px.size(), 100u * 50u * 4u);
  auto at = [&](int x, int y_from_top) { return glm::vec3(px[(y_from_top * 100 + x) * 4], px[(y_from_top * 100 + x) * 4 + 1], px[(y_from_top * 100 + x) * 4 + 2]); };
  // The legend along the bottom left runs from the coldest colour to white.
  EXPECT_LT(glm::length(at(1, 47)), 0.4f);
  EXPECT_GT(at(38, 47).x, 0.9f);
  EXPECT_GT(at(38, 47).z, 0.9f);
  // The sphere's centre costs 6 calls, far below the legend's 256: cold.
  EXPECT_LT(at(50, 25).x, 0.2f);
}

TEST_F(Views, NanMarksExactlyTheBadPixels) {
  const char* shader = "void mainImage(out vec4 c, in vec2 f) {\n"
                       "  float zero = iTime * 0.0;\n"
                       "  c = f.x < 4.5 ? vec4(zero / zero) : vec4(0.5, 0.5, 0.5, 1.0);\n}\n";
  const auto px = render(shader, "--size 9x1 --view nan");
  ASSERT_EQ(px.size(), 9u * 4u);
  for (int x = 0; x < 9; ++x) {
    const glm::vec3 c(px[x * 4], px[x * 4 + 1], px[x * 4 + 2]);
    if (x < 4) EXPECT_EQ(c, glm::vec3(1, 0, 1)) << "pixel " << x;  // centres 0.5 .. 3.5
    else EXPECT_EQ(c.y, c.x) << "pixel " << x << " should be grey";
  }
}

TEST_F(Views, AViewTheSceneCannotShowIsAUsageError) {
  write_file(dir_ / "plain.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
  write_file(dir_ / "full.frag", "#version 450 core\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n");
  const std::string out = " -o " + (dir_ / "x.png").string();
  test::Outcome r = run_binary("render " + (dir_ / "plain.frag").string() + out + " --view steps");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("needs a scene that marches with shaderlib"), std::string::npos) << r.err;
  r = run_binary("render " + (dir_ / "full.frag").string() + out + " --view nan");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("needs a mainImage shader"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace rm
