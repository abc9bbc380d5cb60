// Long sessions in-process: the GL census counts what the driver holds, and
// many reloads alternating good and broken shaders leave no GL object behind.
// (Built with the sanitize preset and ASAN_OPTIONS=detect_leaks=1,
// LeakSanitizer checks the heap of the same run.)
#include <gtest/gtest.h>

#include "core/channels.h"
#include "core/gl_census.h"
#include "core/renderer.h"
#include "core/scene.h"
#include "gpu/egl_fixture.h"
#include "support.h"

namespace rm {
namespace {

using test::write_file;

class ReloadLeak : public test::EglTest {};

TEST_F(ReloadLeak, CensusCountsWhatTheDriverHolds) {
  const GlCensus before = take_gl_census();
  {
    gl::Texture a = gl::make_texture(GL_TEXTURE_2D), b = gl::make_texture(GL_TEXTURE_2D);
    gl::Framebuffer f = gl::make_framebuffer();
    gl::Program p(glCreateProgram());
    gl::Shader s(glCreateShader(GL_FRAGMENT_SHADER));
    const GlCensus during = take_gl_census();
    EXPECT_EQ(during.textures, before.textures + 2);
    EXPECT_EQ(during.framebuffers, before.framebuffers + 1);
    EXPECT_EQ(during.programs, before.programs + 1);
    EXPECT_EQ(during.shaders, before.shaders + 1);
    EXPECT_EQ(during.total(), before.total() + 5) << to_string(during);
  }
  EXPECT_EQ(take_gl_census(), before) << to_string(take_gl_census());
}

TEST_F(ReloadLeak, CensusFindsNamesFarAboveTheFirstOnes) {
  std::vector<gl::Program> many;
  for (int i = 0; i < 3000; ++i) many.emplace_back(glCreateProgram());
  many.erase(many.begin(), many.begin() + 2990);  // only the 10 highest names stay
  EXPECT_EQ(take_gl_census().programs, 10);
}

// Every text is new, so each good one is validated, compiled, linked and
// drawn; the scene's cache of 8 programs fills early and then only turns over.
TEST_F(ReloadLeak, AlternatingGoodAndBrokenReloadsHoldNoMoreGlObjects) {
  test::TempDir dir;
  const auto path = dir / "scene.frag";
  Scene scene(path, {});
  Renderer renderer;
  const ChannelInputs channels{};  // nothing bound
  GlCensus warm;
  constexpr int kReloads = 240;
  for (int i = 0; i < kReloads; ++i) {
    const std::string value = std::to_string(i % 250) + ".0 / 255.0";
    write_file(path, i % 2 == 0 ? "void mainImage(out vec4 c, in vec2 f) { c = vec4(" + value + "); }\n"
                                : "void mainImage(out vec4 c, in vec2 f) { c = vec4(" + value + ") +; }\n");
    ASSERT_EQ(scene.reload(), i % 2 == 0 ? ReloadStatus::Swapped : ReloadStatus::Failed) << i;
    FrameInputs in;
    in.resolution = {4, 4, 1};
    const Image image = renderer.render_image(*scene.program(), in, channels, {4, 4});
    ASSERT_NEAR(image.pixel(0, 0)[0], float(i / 2 * 2 % 250) / 255.0f, 1e-6f) << i;
    if (i == 39) warm = take_gl_census();
  }
  EXPECT_EQ(take_gl_census(), warm) << "after 40: " << to_string(warm) << "\nafter " << kReloads << ": "
                                    << to_string(take_gl_census());
  EXPECT_EQ(warm.programs, 10) << "the running program, the 8 cached and the renderer's own sample pass";
  EXPECT_EQ(warm.shaders, 0) << "shaders are deleted once linked";
}


// The window holds its picture while a storm of saves is built, so the
// program it drew last can leave the cache of 8 before it draws again. ImGui's
// backend then reads GL_CURRENT_PROGRAM, binds its own program and binds the
// one it read back. A program deleted while current lingers until the
// context binds another: ImGui's own bind freed it, and the bind back named a
// dead program (GL_INVALID_VALUE in glUseProgram, e2e.session's storm).
TEST_F(ReloadLeak, AProgramDroppedFromTheCacheAfterItDrewIsGoneAtOnce) {
  test::TempDir dir;
  const auto path = dir / "scene.frag";
  Scene scene(path, {});
  Renderer renderer;
  RenderTarget target(4, 4);
  const ChannelInputs channels{};
  auto save = [&](int i) {
    write_file(path, "void mainImage(out vec4 c, in vec2 f) { c = vec4(" + std::to_string(i) + ".0 / 255.0); }\n");
    ASSERT_EQ(scene.reload(), ReloadStatus::Swapped) << i;
  };
  for (const int sample : {0, 1}) {  // a picture, and a supersample added to the mean
    SCOPED_TRACE(sample);
    save(100 * sample);
    FrameInputs in;
    in.resolution = {4, 4, 1};
    in.sample = sample;
    target.bind();
    renderer.draw(*scene.program(), in, channels, {4, 4});
    const GLuint drawn = scene.program()->id();
    for (int i = 1; i <= 9; ++i) save(100 * sample + i);  // the drawn program leaves the cache
    EXPECT_FALSE(glIsProgram(drawn)) << "a program the cache dropped is still held by the driver";
    EXPECT_EQ(take_gl_census().programs, 10) << "the running program, the 8 cached and the sample pass";
    GLint current = 0;  // what ImGui's backend does around the interface
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    glUseProgram(0);
    glUseProgram(static_cast<GLuint>(current));  // the fixture fails the test on a GL error
  }
}

}  // namespace
}  // namespace rm
