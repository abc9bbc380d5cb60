// F12's shot, drawn a slice at a time between the window's frames: once
// whole it is the picture `render` draws, also when it is larger than the
// renderer's largest target and comes in parts.
#include "window/tiled_shot.h"

#include <gtest/gtest.h>

#include "window/shot_writer.h"

#include "egl_fixture.h"
#include "support.h"

namespace rm {
namespace {

using test::TempDir;
using test::write_file;

class TiledShotTest : public test::EglTest {
 protected:
  TempDir dir_;
  Renderer renderer_;
  FrameGraph graph_{renderer_};
};

TEST_F(TiledShotTest, AShotLargerThanTheLargestTargetIsDrawnInPartsAndEqualsTheWholePicture) {
  write_file(dir_ / "t.frag",
             "void mainImage(out vec4 c, in vec2 f) { c = vec4(f / iResolution.xy, fract(f.x * 0.37 + f.y * 0.11), 1.0); }\n");
  Project project(dir_ / "t.frag", SourceOptions{});
  ASSERT_EQ(project.reload(), ReloadStatus::Swapped) << join(project.diagnostics());
  std::string error;
  ASSERT_TRUE(graph_.update(project, &error)) << error;
  const glm::ivec2 size(37, 23);
  FrameInputs in;
  in.resolution = glm::vec3(size, 1.0f);
  const Image whole = graph_.render_image(project, in, size);

  renderer_.limit_tile(8);  // 5 x 3 parts
  TiledShot shot(in, size, renderer_.max_tile(), 1000.0, 0.0, dir_ / "shot.png", {});
  int slices = 0;
  while (!shot.draw(graph_, project, 0.0)) ASSERT_LT(++slices, 1000);  // a slice of 0 ms: one tile each
  EXPECT_GE(slices, 15) << "one slice per part at least";
  EXPECT_EQ(shot.read().width, size.x);
  EXPECT_EQ(shot.read().height, size.y);
  EXPECT_EQ(shot.read().rgba, whole.rgba);

  // A new program part way: drawn again from the first tile, and whole
  // again, with the new program's metadata.
  TiledShot again(in, size, renderer_.max_tile(), 1000.0, 0.0, dir_ / "again.png", {{"raymarching:define:A", "1"}});
  for (int i = 0; i < 7; ++i) ASSERT_FALSE(again.draw(graph_, project, 0.0));
  again.restart({{"raymarching:define:A", "2"}});
  EXPECT_EQ(again.tiles(), 0);
  EXPECT_EQ(again.metadata(), (Metadata{{"raymarching:define:A", "2"}}));
  while (!again.draw(graph_, project, 1e9)) {
  }
  EXPECT_EQ(again.read().rgba, whole.rgba);
}

// The window's buffers are the size of its last picture, which the frame
// budget may have drawn at a lower scale; a shot of another size (F12 while
// it scales, or --shot-scale) draws the buffer passes anew, into buffers of
// its own, and is then what `render` draws at its size. The window's
// buffers stay as they were. The image pass reads its buffer texel by
// texel: the graph's 40x23 buffer would give a 160x90 shot its corner, and
// black elsewhere.
TEST_F(TiledShotTest, AShotOfAnotherSizeThanTheBuffersDrawsThemAnewAndLeavesTheWindowsAlone) {
  write_file(dir_ / "buffer.frag",
             "void mainImage(out vec4 c, in vec2 f) { c = vec4(f / iResolution.xy, fract(iTime + f.x * 0.37), 1.0); }\n");
  write_file(dir_ / "image.frag",
             "#pragma channel0 \"buffer.frag\" filter=nearest\n"
             "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(f), 0); }\n");
  Project project(dir_ / "image.frag", SourceOptions{});
  ASSERT_EQ(project.reload(), ReloadStatus::Swapped) << join(project.diagnostics());
  std::string error;
  ASSERT_TRUE(graph_.update(project, &error)) << error;
  auto inputs_at = [](glm::ivec2 size) {
    FrameInputs in;
    in.time = 0.25f;
    in.resolution = glm::vec3(size, 1.0f);
    return in;
  };
  const glm::ivec2 scaled(40, 23), size(160, 90);
  const Image window = graph_.render_frame(project, inputs_at(scaled), scaled);  // as the budget drew it
  ASSERT_TRUE(graph_.buffers_sized_for(project, scaled));
  ASSERT_FALSE(graph_.buffers_sized_for(project, size));
  FrameGraph fresh(renderer_);
  ASSERT_TRUE(fresh.update(project, &error)) << error;
  const Image whole = fresh.render_frame(project, inputs_at(size), size);

  TiledShot shot(inputs_at(size), size, renderer_.max_tile(), 1000.0, 0.0, dir_ / "shot.png", {}, true);
  int slices = 0;
  while (!shot.draw(graph_, project, 0.0)) ASSERT_LT(++slices, 1000);  // one tile a slice
  EXPECT_EQ(shot.read().rgba, whole.rgba);
  EXPECT_TRUE(graph_.buffers_sized_for(project, scaled)) << "the window's buffers are as they were";
  EXPECT_EQ(graph_.render_image(project, inputs_at(scaled), scaled).rgba, window.rgba);

  TiledShot reading_the_windows(inputs_at(size), size, renderer_.max_tile(), 1000.0, 0.0, dir_ / "old.png", {});
  while (!reading_the_windows.draw(graph_, project, 1e9)) {
  }
  EXPECT_NE(reading_the_windows.read().rgba, whole.rgba) << "what the shot drew before: a test that can fail";

  // A new program part way through the buffer: drawn again from the buffer's first tile.
  TiledShot again(inputs_at(size), size, renderer_.max_tile(), 1000.0, 0.0, dir_ / "again.png", {}, true);
  for (int i = 0; i < 3; ++i) ASSERT_FALSE(again.draw(graph_, project, 0.0));
  again.restart({});
  while (!again.draw(graph_, project, 1e9)) {
  }
  EXPECT_EQ(again.read().rgba, whole.rgba);
}

// Shots drawn are written on the writer's thread: each in its own file
// (one of the same name stays as it was), all of them before the writer is
// gone, each said on stdout.
TEST(ShotWriter, WritesEveryShotHandedOverBeforeItGoesAndReplacesNone) {
  TempDir dir;
  write_file(dir / "shot.png", "an earlier shot");
  testing::internal::CaptureStdout();
  {
    ShotWriter writer(false);
    for (int i = 0; i < 3; ++i) writer.write(Image{1, 1, {i / 4.0f, 0.5f, 1.0f, 1.0f}}, dir / "shot.png", {});
  }
  const std::string said = testing::internal::GetCapturedStdout();
  EXPECT_EQ(test::read_file(dir / "shot.png"), "an earlier shot");
  for (int i = 0; i < 3; ++i) {
    const fs::path written = dir / ("shot-" + std::to_string(i + 1) + ".png");
    EXPECT_NE(said.find("screenshot: " + written.string() + "\n"), std::string::npos) << said;
    const std::vector<float> px = test::read_pixels(written);
    ASSERT_EQ(px.size(), 4u) << written;
    EXPECT_NEAR(px[0], i / 4.0f, 1.0f / 255) << written;
  }
}

}  // namespace
}  // namespace rm
