// Shadertoy JSON projects of our own (tests/data/shadertoy), each rendered
// by `render` as a person would run it, and its picture read back: buffers
// with feedback, the ping-pong order, samplers, the keyboard, Cube A, media
// and their stand-ins, what is unsupported, and an error in Common.
#include <gtest/gtest.h>

#include <cmath>

#include "core/capture.h"
#include "support.h"

namespace rm {
namespace {

using test::TempDir;

struct Rendered {
  test::Outcome outcome;
  std::vector<float> pixels;  // RGBA of an 8x8 EXR
  float at(int x, int y, int c) const { return pixels[static_cast<size_t>((y * 8 + x) * 4 + c)]; }
  int warnings() const {
    int n = 0;
    for (size_t at = 0; (at = outcome.err.find("warning:", at)) != std::string::npos; ++at) ++n;
    return n;
  }
};

Rendered render(const std::string& project, int frame, const std::string& more = "") {
  TempDir dir;
  const fs::path out = dir / "out.exr";
  Rendered r;
  r.outcome = test::run_binary("render " + std::string(RM_TEST_DATA_DIR) + "/shadertoy/" + project + " -o " +
                               out.string() + " --size 8x8 --frame " + std::to_string(frame) + " " + more);
  r.pixels = test::read_pixels(out);
  return r;
}

TEST(ShadertoyProjects, CounterAddsCommonsStepPerFrame) {
  const Rendered r = render("counter.json", 6);
  ASSERT_EQ(r.outcome.status, 0) << r.outcome.err;
  EXPECT_FLOAT_EQ(r.at(3, 3, 0), 7.0f / 255.0f);
  EXPECT_EQ(r.warnings(), 0) << r.outcome.err;
}

TEST(ShadertoyProjects, PingPongReadsLaterBuffersFromThePreviousFrame) {
  const Rendered r = render("pingpong.json", 3);
  ASSERT_EQ(r.outcome.status, 0) << r.outcome.err;
  EXPECT_EQ(r.at(0, 0, 0), 15.0f) << "A(n) = B(n-1) + 1";
  EXPECT_EQ(r.at(0, 0, 1), 30.0f) << "B(n) = 2 A(n)";
}

TEST(ShadertoyProjects, SparseUnorderedInputsKeepTheirSamplers) {
  const Rendered r = render("samplers.json", 0);
  ASSERT_EQ(r.outcome.status, 0) << r.outcome.err;
  EXPECT_EQ(r.at(0, 0, 0), 1.0f) << "nearest";
  EXPECT_NEAR(r.at(0, 0, 1), 0.5f, 1e-3f) << "linear";
  EXPECT_NEAR(r.at(0, 0, 2), 0.5f, 1e-3f) << "mipmap";
}

TEST(ShadertoyProjects, TheKeyboardReadsNoKeyHeadless) {
  const Rendered r = render("keyboard.json", 2);
  ASSERT_EQ(r.outcome.status, 0) << r.outcome.err;
  EXPECT_EQ(r.at(0, 0, 0), 1.0f) << "Space is up";
  EXPECT_EQ(r.at(0, 0, 1), 0.0f) << "and was never toggled";
  EXPECT_EQ(r.at(0, 0, 2), 1.0f) << "iChannelResolution.x is 256";
}

TEST(ShadertoyProjects, CubeAIsReadBackByDirection) {
  const Rendered r = render("cube_pass.json", 0);
  ASSERT_EQ(r.outcome.status, 0) << r.outcome.err;
  const float d[3] = {1 / std::sqrt(14.0f), 2 / std::sqrt(14.0f), 3 / std::sqrt(14.0f)};
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(r.at(4, 4, c), d[c] * 0.5f + 0.5f, 2e-3f) << "component " << c;
}

// green.png and half.bin are in --media; a texture and a cube map are not:
// noise and a sky (blue overhead) stand in, with one warning each.
TEST(ShadertoyProjects, MediaComeFromMediaAndMissingOnesFromStandIns) {
  TempDir media;
  std::string error;
  ASSERT_TRUE(write_image(media / "green.png", Image{1, 1, {0, 1, 0, 1}}, {}, Overwrite::Replace, &error)) << error;
  std::string bin = "BIN";
  bin += '\0';
  for (uint32_t n : {1u, 1u, 1u}) bin += std::string(reinterpret_cast<const char*>(&n), 4);
  bin += {1, 0, 0, 0};
  bin += static_cast<char>(51);  // 0.2
  test::write_file(media / "half.bin", bin);
  const Rendered r = render("media.json", 0, "--media " + media.path().string());
  ASSERT_EQ(r.outcome.status, 0) << r.outcome.err;
  EXPECT_EQ(r.at(2, 2, 0), 1.0f) << "green.png";
  EXPECT_GT(r.at(2, 2, 1), 0.8f) << "the stand-in sky is blue overhead";
  EXPECT_NEAR(r.at(2, 2, 2), 0.2f, 1e-3f) << "half.bin";
  EXPECT_EQ(r.at(2, 2, 3), 1.0f) << "the noise stand-in is not black";
  EXPECT_EQ(r.warnings(), 2) << r.outcome.err;
  EXPECT_NE(r.outcome.err.find("value noise stands in"), std::string::npos) << r.outcome.err;
  EXPECT_NE(r.outcome.err.find("a sky stands in"), std::string::npos) << r.outcome.err;
}

// Media exist before a frame is drawn, and so do their stand-ins: a buffer
// that reads a missing texture sees the stand-in in frame 0, and the project
// feeds no frame into the next (it can be sliced, and drawn at any scale).
TEST(ShadertoyProjects, AStandInIsDrawnBeforeTheBufferThatReadsIt) {
  TempDir dir;
  test::write_file(dir / "p.json", R"({"Shader": {"info": {"id": "x"}, "renderpass": [
    {"type": "image", "name": "Image", "inputs": [{"channel": 0, "type": "buffer", "id": "4dXGR8"}],
     "outputs": [{"id": "4dfGRr"}], "code": "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, f / iResolution.xy); }"},
    {"type": "buffer", "name": "Buffer A", "outputs": [{"id": "4dXGR8"}],
     "inputs": [{"channel": 0, "type": "texture", "filepath": "/media/a/missing.png"}],
     "code": "void mainImage(out vec4 c, in vec2 f) { c = vec4(texture(iChannel0, f / iResolution.xy).rgb, 1.0); }"}]}})");
  const test::Outcome r = test::run_binary("render " + (dir / "p.json").string() + " -o " + (dir / "f_%d.exr").string() +
                                           " --size 8x8 --frames 3 --frame-range 0:0");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<float> px = test::read_pixels(dir / "f_0.exr");
  ASSERT_EQ(px.size(), 8u * 8u * 4u);
  float sum = 0;
  for (size_t i = 0; i < px.size(); i += 4) sum += px[i] + px[i + 1] + px[i + 2];
  EXPECT_GT(sum, 1.0f) << "frame 0 of the buffer read the stand-in's noise, not black";
}

TEST(ShadertoyProjects, WhatDoesNotRunIsOneWarningEachAndTheRestRuns) {
  const Rendered r = render("unsupported.json", 0);
  ASSERT_EQ(r.outcome.status, 0) << r.outcome.err;
  EXPECT_EQ(r.at(0, 0, 0), 0.25f);
  EXPECT_EQ(r.at(0, 0, 1), 0.5f);
  EXPECT_EQ(r.at(0, 0, 2), 0.0f) << "the webcam reads black";
  EXPECT_EQ(r.warnings(), 3) << r.outcome.err;
  EXPECT_NE(r.outcome.err.find("unsupported.json: warning: pass 'Sound' of type 'sound' is not supported yet"),
            std::string::npos)
      << "each warning names the JSON: " << r.outcome.err;
}

TEST(ShadertoyProjects, AnErrorInCommonNamesCommonAndItsLine) {
  const Rendered r = render("broken_common.json", 0);
  EXPECT_EQ(r.outcome.status, 1);
  EXPECT_NE(r.outcome.err.find("broken_common.json/common.glsl:2:41: error: 'missing' : undeclared identifier"),
            std::string::npos)
      << r.outcome.err;
  EXPECT_TRUE(r.pixels.empty()) << "nothing written";
}

}  // namespace
}  // namespace rm
