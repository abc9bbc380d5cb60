// The pass graph on the GPU: buffers with feedback, Shadertoy's order of
// reads, sampler settings, the keyboard texture, resize, restart and reloads
// that touch one pass.
#include <gtest/gtest.h>

#include <epoxy/egl.h>
#include <glm/gtc/type_ptr.hpp>

#include <mutex>
#include <set>
#include <thread>

#include "core/capture.h"
#include "core/data_paths.h"
#include "core/frame_graph.h"
#include "core/project.h"
#include "window/panels.h"
#include "egl_fixture.h"
#include "support.h"

namespace rm {
namespace {

using test::TempDir;
using test::write_file;

class Passes : public test::EglTest {
 protected:
  // Loads the project whose image pass is `image` (a file in dir_).
  Project& load(const std::string& image) {
    project_ = std::make_unique<Project>(dir_ / image, SourceOptions{});
    EXPECT_EQ(project_->reload(), ReloadStatus::Swapped) << join(project_->diagnostics());
    std::string error;
    EXPECT_TRUE(graph_.update(*project_, &error)) << error;
    return *project_;
  }
  // Draws frame `frame` (buffers, then the image) and reads the image back.
  Image frame(int frame, glm::ivec2 size = {4, 4}) {
    FrameInputs in;
    in.resolution = glm::vec3(size, 1.0f);
    in.frame = frame;
    return graph_.render_frame(*project_, in, size);
  }

  static glm::vec4 at(const Image& image, int x, int y) { return glm::make_vec4(image.pixel(x, y)); }

  TempDir dir_;
  Renderer renderer_;
  FrameGraph graph_{renderer_};
  std::unique_ptr<Project> project_;
};

const char* kShowChannel0 = "#pragma channel0 \"buffer_a.frag\" filter=nearest\n"
                            "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(f), 0); }\n";

TEST_F(Passes, ABufferThatAddsOnePerFrameReadsNAtFrameN) {
  write_file(dir_ / "buffer_a.frag", "#pragma channel0 self filter=nearest\n"
                                     "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(f), 0) + 1.0; }\n");
  write_file(dir_ / "image.frag", kShowChannel0);
  Project& project = load("image.frag");
  ASSERT_EQ(project.passes().size(), 2u);
  EXPECT_TRUE(project.has_feedback());
  EXPECT_TRUE(project.inputs_read().time) << "feedback animates a shader that reads no clock";
  for (int n = 0; n < 5; ++n) EXPECT_EQ(at(frame(n), 1, 1)[0], float(n + 1)) << "frame " << n << " read " << n;
}

// Buffer A reads B, drawn after it: B's previous frame. B reads A, drawn
// before it: A's frame now. A(n) = B(n-1) + 1 and B(n) = 2 A(n), from zero.
TEST_F(Passes, LaterBuffersAreReadFromThePreviousFrameEarlierOnesFromThisOne) {
  write_file(dir_ / "buffer_a.frag", "#pragma channel0 \"buffer_b.frag\" filter=nearest\n"
                                     "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(f), 0) + 1.0; }\n");
  write_file(dir_ / "buffer_b.frag", "#pragma channel0 \"buffer_a.frag\" filter=nearest\n"
                                     "void mainImage(out vec4 c, in vec2 f) { c = 2.0 * texelFetch(iChannel0, ivec2(f), 0); }\n");
  write_file(dir_ / "image.frag", "#pragma channel0 \"buffer_a.frag\" filter=nearest\n"
                                  "#pragma channel1 \"buffer_b.frag\" filter=nearest\n"
                                  "void mainImage(out vec4 c, in vec2 f) {\n"
                                  "  c = vec4(texelFetch(iChannel0, ivec2(f), 0).x, texelFetch(iChannel1, ivec2(f), 0).x, 0, 1);\n}\n");
  Project& project = load("image.frag");
  ASSERT_EQ(project.passes().size(), 3u);
  EXPECT_EQ(project.passes()[0].file.filename(), "buffer_a.frag");
  const float a[] = {1, 3, 7, 15}, b[] = {2, 6, 14, 30};
  for (int n = 0; n < 4; ++n) {
    const glm::vec4 p = at(frame(n), 0, 0);
    EXPECT_EQ(p.x, a[n]) << "A at frame " << n;
    EXPECT_EQ(p.y, b[n]) << "B at frame " << n;
  }
}

// A buffer of 0/1 columns: nearest reads a texel, linear blends two, and the
// mipmap filter at a coarse level averages them all.
TEST_F(Passes, BuffersAreSampledWithTheReadersSettings) {
  write_file(dir_ / "buffer_a.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(mod(floor(f.x), 2.0)); }\n");
  write_file(dir_ / "image.frag",
             "#pragma channel0 \"buffer_a.frag\" filter=nearest\n"
             "#pragma channel1 \"buffer_a.frag\" filter=linear\n"
             "#pragma channel2 \"buffer_a.frag\" filter=mipmap\n"
             "void mainImage(out vec4 c, in vec2 f) {\n"
             "  vec2 uv = vec2(1.0, 0.5) / iChannelResolution[0].xy;  // the border of texels 0 and 1\n"
             "  c = vec4(texture(iChannel0, uv + vec2(0.1, 0) / iChannelResolution[0].xy).x,\n"
             "           texture(iChannel1, uv).x, textureLod(iChannel2, vec2(0.5), 3.0).x, 1);\n}\n");
  load("image.frag");
  const glm::vec4 p = at(frame(0, {8, 8}), 0, 0);
  EXPECT_EQ(p.x, 1.0f) << "nearest: texel 1";
  EXPECT_NEAR(p.y, 0.5f, 1e-3f) << "linear: half of each";
  EXPECT_NEAR(p.z, 0.5f, 1e-3f) << "mipmap level 3 of 8x8: the average";
}

// Row 0: down; row 1: pressed in this frame; row 2: toggled.
TEST_F(Passes, TheKeyboardTextureHasShadertoysThreeRows) {
  write_file(dir_ / "image.frag", "#pragma channel0 keyboard\n"
                                  "void mainImage(out vec4 c, in vec2 f) {\n"
                                  "  c = vec4(texelFetch(iChannel0, ivec2(65, 0), 0).x, texelFetch(iChannel0, ivec2(65, 1), 0).x,\n"
                                  "           texelFetch(iChannel0, ivec2(65, 2), 0).x, iChannelResolution[0].x);\n}\n");
  Project& project = load("image.frag");
  EXPECT_TRUE(project.reads_keyboard());
  EXPECT_EQ(at(frame(0), 0, 0), glm::vec4(0, 0, 0, 256));
  graph_.keyboard().press(65);
  EXPECT_EQ(at(frame(1), 0, 0), glm::vec4(1, 1, 1, 256)) << "pressed";
  graph_.keyboard().end_frame();
  EXPECT_EQ(at(frame(2), 0, 0), glm::vec4(1, 0, 1, 256)) << "held";
  graph_.keyboard().release(65);
  EXPECT_EQ(at(frame(3), 0, 0), glm::vec4(0, 0, 1, 256)) << "released, still toggled";
  graph_.keyboard().press(65);
  graph_.keyboard().release(65);
  EXPECT_EQ(at(frame(4), 0, 0), glm::vec4(0, 1, 0, 256)) << "tapped: pressed this frame, toggled back";
}

TEST_F(Passes, AResizeKeepsTheContentWhereItFitsAndRestartClears) {
  write_file(dir_ / "buffer_a.frag", "#pragma channel0 self filter=nearest\n"
                                     "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(f), 0) + 1.0; }\n");
  write_file(dir_ / "image.frag", kShowChannel0);
  load("image.frag");
  for (int n = 0; n < 3; ++n) frame(n);
  const Image bigger = frame(3, {8, 8});
  EXPECT_EQ(at(bigger, 1, 6)[0], 4.0f) << "kept, then one more";
  EXPECT_EQ(at(bigger, 6, 6)[0], 1.0f) << "new texels start at zero";
  graph_.restart();
  EXPECT_EQ(at(frame(0, {8, 8}), 1, 6)[0], 1.0f);
}

// The progressive example keeps its buffer's size in texel (0, 0), so that
// a resize, which keeps the old sums where they fit, starts the sum again:
// its next picture is the one a fresh graph draws at that size and frame,
// not a mix of sums traced for another picture.
TEST_F(Passes, TheProgressiveExampleStartsAgainAfterAResize) {
  const fs::path image = fs::path(RM_SOURCE_DIR) / "examples" / "progressive" / "image.frag";
  SourceOptions options;
  options.shaderlib_dir = shaderlib_dir();
  project_ = std::make_unique<Project>(image, options);
  ASSERT_EQ(project_->reload(), ReloadStatus::Swapped) << join(project_->diagnostics());
  std::string error;
  ASSERT_TRUE(graph_.update(*project_, &error)) << error;
  for (int n = 0; n < 6; ++n) frame(n, {24, 16});
  const Image resized = frame(6, {32, 18});

  FrameGraph fresh(renderer_);
  ASSERT_TRUE(fresh.update(*project_, &error)) << error;
  FrameInputs in;
  in.resolution = glm::vec3(32, 18, 1);
  in.frame = 6;
  const Image expected = fresh.render_frame(*project_, in, {32, 18});
  ASSERT_EQ(resized.rgba.size(), expected.rgba.size());
  EXPECT_EQ(resized.rgba, expected.rgba);
  EXPECT_NE(at(frame(7, {32, 18}), 5, 5), at(expected, 5, 5)) << "the next frame adds a sample";
}

TEST_F(Passes, ASaveToOneBufferRebuildsOnlyItAndABrokenPassKeepsTheWholeGraph) {
  write_file(dir_ / "common.glsl", "float step_of() { return 1.0; }\n");
  write_file(dir_ / "buffer_a.frag", "#include \"common.glsl\"\n#pragma channel0 self filter=nearest\n"
                                     "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(f), 0) + step_of(); }\n");
  write_file(dir_ / "buffer_b.frag", "#include \"common.glsl\"\n"
                                     "void mainImage(out vec4 c, in vec2 f) { c = vec4(step_of()); }\n");
  write_file(dir_ / "image.frag", "#pragma channel0 \"buffer_a.frag\" filter=nearest\n"
                                  "#pragma channel1 \"buffer_b.frag\" filter=nearest\n"
                                  "void mainImage(out vec4 c, in vec2 f) {\n"
                                  "  c = vec4(texelFetch(iChannel0, ivec2(f), 0).x, texelFetch(iChannel1, ivec2(f), 0).x, 0, 1);\n}\n");
  Project& project = load("image.frag");
  frame(0);
  frame(1);
  auto generations = [&] {
    std::vector<int> out;
    for (const Pass& pass : project.passes()) out.push_back(pass.scene->generation());
    return out;
  };
  const std::vector<int> before = generations();
  write_file(dir_ / "buffer_b.frag", "#include \"common.glsl\"\n"
                                     "void mainImage(out vec4 c, in vec2 f) { c = vec4(5.0 * step_of()); }\n");
  ASSERT_EQ(project.reload(), ReloadStatus::Swapped);
  EXPECT_EQ(generations(), (std::vector<int>{before[0], before[1] + 1, before[2]}));
  EXPECT_EQ(at(frame(2), 0, 0), glm::vec4(3, 5, 0, 1)) << "a reload keeps buffer A's count";

  // common.glsl changes A and B; B no longer compiles, so neither swaps.
  write_file(dir_ / "common.glsl", "float step_of() { return 2.0; }\n");
  write_file(dir_ / "buffer_b.frag", "#include \"common.glsl\"\n"
                                     "void mainImage(out vec4 c, in vec2 f) { c = vec4(5.0 * step_of() + missing); }\n");
  EXPECT_EQ(project.reload(), ReloadStatus::Failed);
  ASSERT_EQ(count_errors(project.diagnostics()), 1);
  EXPECT_EQ(project.diagnostics()[0].path, (dir_ / "buffer_b.frag").string());
  EXPECT_EQ(project.diagnostics()[0].line, 2);
  EXPECT_EQ(at(frame(3), 0, 0), glm::vec4(4, 5, 0, 1)) << "the last good graph: A still adds 1";
  write_file(dir_ / "buffer_b.frag", "#include \"common.glsl\"\n"
                                     "void mainImage(out vec4 c, in vec2 f) { c = vec4(5.0 * step_of()); }\n");
  EXPECT_EQ(project.reload(), ReloadStatus::Swapped);
  EXPECT_EQ(at(frame(4), 0, 0), glm::vec4(6, 10, 0, 1)) << "both new: A adds 2, B is 10";
}

// A tweak's exact programs, built as jobs in the background, while a save
// to one pass is shown without compiling: that pass keeps its new tweak,
// the other takes its exact program; a code edit is left for the builder.
TEST_F(Passes, ExactBuildsOfAProjectKeepOnlyWhatTheSavesMeanwhileLeftCurrent) {
  const std::string buffer = "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.25); }\n";
  const std::string image = "#pragma channel0 \"buffer_a.frag\" filter=nearest\n"
                            "void mainImage(out vec4 c, in vec2 f) { c = vec4(texelFetch(iChannel0, ivec2(f), 0).x, 0.5, 0, 1); }\n";
  write_file(dir_ / "buffer_a.frag", buffer);
  write_file(dir_ / "image.frag", image);
  Project& project = load("image.frag");
  ASSERT_TRUE(project.prepare_twins());
  project.commit_twins();
  auto saved = [&](const std::string& b, const std::string& i) {
    write_file(dir_ / "buffer_a.frag", b);
    write_file(dir_ / "image.frag", i);
  };
  auto with = [](std::string text, const std::string& from, const std::string& to) {
    return text.replace(text.find(from), from.size(), to);
  };
  saved(with(buffer, "0.25", "0.75"), with(image, "0.5, 0", "0.125, 0"));
  ASSERT_EQ(project.prepare_without_compiling(), ReloadStatus::Swapped);
  project.commit();
  ASSERT_TRUE(project.tweaked());
  const std::vector<Scene::ExactJob> jobs = project.exact_jobs();
  ASSERT_EQ(jobs.size(), 2u);
  EXPECT_EQ(jobs.front().path, dir_ / "buffer_a.frag") << "in draw order";

  // Saved while the jobs run: a code edit waits for the builder, a number edit of the image does not.
  saved(with(buffer, "vec4(0.25)", "vec4(0.25 + f.x)"), with(image, "0.5, 0", "0.125, 0"));
  EXPECT_EQ(project.prepare_without_compiling(), ReloadStatus::NeedsCompile);
  EXPECT_TRUE(project.diagnostics().empty()) << join(project.diagnostics());
  saved(with(buffer, "0.25", "0.75"), with(image, "0.5, 0", "0.375, 0"));
  ASSERT_EQ(project.prepare_without_compiling(), ReloadStatus::Swapped);
  project.commit();
  const int generation = project.generation();

  ASSERT_EQ(project.take_exact(Project::build_exact(jobs)), ReloadStatus::Swapped);
  project.commit();
  EXPECT_EQ(project.generation(), generation + 1);
  EXPECT_EQ(project.rebuilt(), (std::vector<fs::path>{dir_ / "buffer_a.frag"}));
  EXPECT_FALSE(project.passes().front().scene->tweaked()) << "the buffer's exact program";
  EXPECT_TRUE(project.image().scene->tweaked()) << "the image's latest tweak";
  EXPECT_EQ(at(frame(0), 0, 0), glm::vec4(0.75f, 0.375f, 0, 1));
}

// The window builds a reload on another thread: prepare() must leave the
// running graph drawing as it was until commit() swaps it.
// What llvmpipe's code for a pass depends on in a texture it reads: the
// target, the format, whether it has mip levels, and whether its sides are
// powers of two.
std::tuple<GLint, GLint, bool, bool, bool> described(GLuint texture) {
  GLint target = 0, format = 0, levels = 0, width = 0, height = 0;
  glGetTextureParameteriv(texture, GL_TEXTURE_TARGET, &target);
  glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &width);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &height);
  auto power_of_two = [](GLint n) { return n > 0 && (n & (n - 1)) == 0; };
  return {target, format, levels > 1, power_of_two(width), power_of_two(height)};
}

// A builder warms a pass the graph holds nothing for up with stand-ins:
// each like what the graph binds once it draws (else the window's first
// draw generates the pass's code again), for every kind of channel, and
// for the image pass's --channelN file.
TEST_F(Passes, StandInsAreLikeTheTexturesThePassReads) {
  std::string error;
  ASSERT_TRUE(write_image(dir_ / "rock.png", Image{8, 8, std::vector<float>(8 * 8 * 4, 0.5f)}, {},
                          Overwrite::Replace, &error)) << error;
  write_file(dir_ / "cube_a.frag", "void mainCubemap(out vec4 c, in vec2 f, in vec3 ro, in vec3 rd) { c = vec4(rd, 1); }\n");
  write_file(dir_ / "buffer_a.frag", "#pragma channel0 self filter=nearest wrap=clamp\n#pragma channel1 keyboard\n"
                                     "#pragma channel2 \"rock.png\"\n#pragma channel3 \"cube_a.frag\" cube\n"
                                     "void mainImage(out vec4 c, in vec2 f) {\n"
                                     "  c = texelFetch(iChannel0, ivec2(f), 0) + texture(iChannel1, f) + texture(iChannel2, f) +\n"
                                     "      texture(iChannel3, vec3(1));\n}\n");
  write_file(dir_ / "image.frag", std::string(kShowChannel0) + "#pragma channel1 \"cube_a.frag\" cube\n");
  project_ = std::make_unique<Project>(dir_ / "image.frag", SourceOptions{}, disk_file_system(),
                                       std::array<fs::path, 4>{{{}, {}, {}, dir_ / "rock.png"}});
  ASSERT_EQ(project_->reload(), ReloadStatus::Swapped) << join(project_->diagnostics());
  ASSERT_TRUE(graph_.update(*project_, &error)) << error;
  frame(0, {5, 3});
  frame(1, {5, 3});
  const auto states = graph_.pass_states(*project_);
  ASSERT_EQ(states.size(), 3u);
  for (const Pass& pass : project_->passes()) {
    const FrameGraph::PassState& real = states.at(pass.file);
    const FrameGraph::StandIns stand_ins =
        graph_.stand_ins(pass.scene->source().cubemap, project_->channels_of(pass.file, pass.scene->source()));
    EXPECT_EQ(stand_ins.state.format, real.format) << pass.file.filename() << "'s target";
    for (size_t c = 0; c < 4; ++c) {
      const ChannelInput& stand_in = stand_ins.state.channels[c];
      EXPECT_EQ(described(stand_in.texture), described(real.channels[c].texture))
          << pass.file.filename() << "'s iChannel" << c;
      EXPECT_EQ(stand_in.sampler, real.channels[c].sampler) << pass.file.filename() << "'s iChannel" << c;
    }
  }
}

// A buffer's own size is in its reader's text: a save that changes only
// glslViewer's size comment is no comment-only save, and the buffer draws
// at the new size. A warm-up's stand-in for it has the same sides, powers
// of two or not, which llvmpipe's code depends on.
TEST_F(Passes, ABuffersOwnSizeFollowsItsCommentAndItsStandIn) {
  auto write_scene = [&](const std::string& size) {
    write_file(dir_ / "sized.frag", "uniform sampler2D u_buffer0; // " + size + "\nvoid main() {\n#ifdef BUFFER_0\n"
                                    "  gl_FragColor = vec4(1.0);\n#else\n"
                                    "  gl_FragColor = vec4(vec2(textureSize(u_buffer0, 0)), 0.0, 1.0);\n#endif\n}\n");
  };
  write_scene("8x2");
  load("sized.frag");
  EXPECT_EQ(at(frame(0), 0, 0), glm::vec4(8, 2, 0, 1));
  for (const std::string size : {"5x3", "16x4", "0.5"}) {
    write_scene(size);
    ASSERT_EQ(project_->reload(), ReloadStatus::Swapped) << size << join(project_->diagnostics());
    std::string error;
    ASSERT_TRUE(graph_.update(*project_, &error)) << error;
    const glm::vec4 sides = size == "5x3" ? glm::vec4(5, 3, 0, 1) : size == "16x4" ? glm::vec4(16, 4, 0, 1)
                                                                                : glm::vec4(3, 2, 0, 1);  // half of 6x4
    EXPECT_EQ(at(frame(1, {6, 4}), 0, 0), sides) << size;
    if (size == "0.5") continue;  // its sides depend on the picture's, which a warm-up does not know
    const Pass& image = project_->image();
    const auto real = graph_.pass_states(*project_).at(image.file);
    const FrameGraph::StandIns stand_ins = graph_.stand_ins(false, project_->channels_of(image.file, image.scene->source()));
    EXPECT_EQ(described(stand_ins.state.channels[3].texture), described(real.channels[3].texture)) << size;
  }
}

TEST_F(Passes, APreparedReloadLeavesTheRunningGraphDrawingUntilItIsCommitted) {
  write_file(dir_ / "buffer_a.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
  write_file(dir_ / "image.frag", std::string(kShowChannel0));
  Project& project = load("image.frag");
  EXPECT_EQ(at(frame(0), 1, 1)[0], 1.0f);
  write_file(dir_ / "buffer_a.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(2.0); }\n");
  std::vector<GLuint> built;
  auto count_built = [&](const fs::path& pass, const Program& program, const Source&) {
    EXPECT_EQ(pass, dir_ / "buffer_a.frag");
    built.push_back(program.id());
  };
  ASSERT_EQ(project.prepare(count_built), ReloadStatus::Swapped) << join(project.diagnostics());
  EXPECT_EQ(built.size(), 1u) << "on_built sees the one pass compiled anew";
  EXPECT_EQ(project.generation(), 1);
  EXPECT_EQ(at(frame(1), 1, 1)[0], 1.0f) << "prepared, not committed: the running buffer draws";
  project.commit();
  std::string error;
  ASSERT_TRUE(graph_.update(project, &error)) << error;
  EXPECT_EQ(project.generation(), 2);
  EXPECT_EQ(project.passes().front().scene->program()->id(), built[0]);
  EXPECT_EQ(at(frame(2), 1, 1)[0], 2.0f);

  // Back to a text built before: from the cache, so nothing is built anew.
  write_file(dir_ / "buffer_a.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
  ASSERT_EQ(project.prepare(count_built), ReloadStatus::Swapped);
  EXPECT_EQ(built.size(), 1u);
  project.commit();
  ASSERT_TRUE(graph_.update(project, &error)) << error;
  EXPECT_EQ(at(frame(3), 1, 1)[0], 1.0f);
}

// The passes a save compiles anew (not those from the cache) link and warm
// up as jobs, one a pass, which the window's builder runs on two threads at
// once (Builder::run_jobs). Here the second thread has an EGL context of its
// own that shares this one's objects; its programs draw here as the others
// do. A pass the driver rejects after glslang passed it fails the whole
// save, with its error, and the last good graph keeps drawing.
TEST_F(Passes, ThePassesLinkAsJobsOnTwoThreadsAndAnyRejectedFailsTheSave) {
  write_file(dir_ / "buffer_a.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(2.0); }\n");
  write_file(dir_ / "buffer_b.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(3.0); }\n");
  write_file(dir_ / "image.frag", "#pragma channel0 \"buffer_a.frag\" filter=nearest\n"
                                  "#pragma channel1 \"buffer_b.frag\" filter=nearest\n"
                                  "void mainImage(out vec4 c, in vec2 f) {\n"
                                  "  c = vec4(texelFetch(iChannel0, ivec2(f), 0).x, texelFetch(iChannel1, ivec2(f), 0).x, 0, 1);\n}\n");
  const EGLDisplay display = eglGetCurrentDisplay();
  const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  eglChooseConfig(display, config_attribs, &config, 1, &configs);
  const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                    EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  const EGLContext beside = eglCreateContext(display, configs > 0 ? config : EGL_NO_CONFIG_KHR, eglGetCurrentContext(),
                                             context_attribs);
  ASSERT_NE(beside, EGL_NO_CONTEXT);
  std::vector<size_t> job_counts;
  std::set<std::thread::id> threads;
  std::mutex threads_lock;
  auto warm = [&](const fs::path&, const Program&, const Source&) {
    const std::lock_guard<std::mutex> lock(threads_lock);
    threads.insert(std::this_thread::get_id());
  };
  // Even jobs here, odd ones beside: both threads take part whatever their pace.
  auto two_threads = [&](const std::vector<std::function<void()>>& jobs) {
    job_counts.push_back(jobs.size());
    std::thread other([&] {
      eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, beside);
      for (size_t i = 1; i < jobs.size(); i += 2) jobs[i]();
      glFinish();
      eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    });
    for (size_t i = 0; i < jobs.size(); i += 2) jobs[i]();
    other.join();
  };
  project_ = std::make_unique<Project>(dir_ / "image.frag", SourceOptions{});
  ASSERT_EQ(project_->prepare(warm, {}, two_threads), ReloadStatus::Swapped) << join(project_->diagnostics());
  project_->commit();
  std::string error;
  ASSERT_TRUE(graph_.update(*project_, &error)) << error;
  EXPECT_EQ(job_counts, std::vector<size_t>{3});
  EXPECT_EQ(threads.size(), 2u) << "every pass warmed on one thread";
  EXPECT_EQ(at(frame(0), 0, 0), glm::vec4(2, 3, 0, 1));

  // B is new and the driver rejects it (glslang does not count uniforms); A is new too.
  write_file(dir_ / "buffer_a.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(4.0); }\n");
  write_file(dir_ / "buffer_b.frag", "uniform vec4 table[100000];\n"
                                     "void mainImage(out vec4 c, in vec2 f) { c = table[int(f.x)]; }\n");
  EXPECT_EQ(project_->prepare(warm, {}, two_threads), ReloadStatus::Failed);
  ASSERT_EQ(count_errors(project_->diagnostics()), 1) << join(project_->diagnostics());
  EXPECT_EQ(project_->diagnostics()[0].path, (dir_ / "buffer_b.frag").string());
  EXPECT_EQ(project_->diagnostics()[0].line, 1);
  EXPECT_EQ(at(frame(1), 0, 0), glm::vec4(2, 3, 0, 1)) << "the last good graph";

  write_file(dir_ / "buffer_b.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(5.0); }\n");
  ASSERT_EQ(project_->prepare(warm, {}, two_threads), ReloadStatus::Swapped) << join(project_->diagnostics());
  project_->commit();
  ASSERT_TRUE(graph_.update(*project_, &error)) << error;
  EXPECT_EQ(job_counts, (std::vector<size_t>{3, 2, 1})) << "a job for each pass compiled anew";
  EXPECT_EQ(at(frame(2), 0, 0), glm::vec4(4, 5, 0, 1)) << "A from the cache, B new";
  eglDestroyContext(display, beside);
}

// The runner's threads take the jobs in turn, so a long one taken last
// would leave one thread to build it alone: the largest pass comes first,
// whatever the order the passes are drawn in. (They were warmed in draw
// order, for Mesa's cache, which it writes on a thread of its own; each
// warm-up now draws again in a probe context, which waits for its entry.)
TEST_F(Passes, TheLargestPassIsTheFirstJob) {
  std::string large_body;
  for (int i = 0; i < 40; ++i) large_body += "  c += vec4(sin(f.x * " + std::to_string(i) + ".5));\n";
  write_file(dir_ / "buffer_a.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(2.0); }\n");
  write_file(dir_ / "buffer_b.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(3.0); }\n");
  write_file(dir_ / "image.frag", "#pragma channel0 \"buffer_a.frag\"\n#pragma channel1 \"buffer_b.frag\"\n"
                                  "void mainImage(out vec4 c, in vec2 f) {\n  c = texture(iChannel0, f) + texture(iChannel1, f);\n" +
                                      large_body + "}\n");
  std::vector<std::string> warmed;
  auto warm = [&](const fs::path& pass, const Program&, const Source&) { warmed.push_back(pass.filename().string()); };
  auto in_order = [](const std::vector<std::function<void()>>& jobs) {
    for (const auto& job : jobs) job();
  };
  project_ = std::make_unique<Project>(dir_ / "image.frag", SourceOptions{});
  ASSERT_EQ(project_->prepare(warm, {}, in_order), ReloadStatus::Swapped) << join(project_->diagnostics());
  EXPECT_EQ(warmed, (std::vector<std::string>{"image.frag", "buffer_a.frag", "buffer_b.frag"}))
      << "the image, drawn last, is the largest";
  project_->commit();
  ASSERT_EQ(project_->passes().size(), 3u);
  EXPECT_EQ(project_->passes()[0].file.filename(), "buffer_a.frag") << "drawn in Shadertoy's order still";
  EXPECT_EQ(project_->passes()[2].file.filename(), "image.frag");
}

// Each with the size it drew at, which the HUD shows beside its time: a
// buffer's own size, a cube's face, the picture's.
TEST_F(Passes, EachPassIsTimedInDrawOrderWhenAsked) {
  write_file(dir_ / "buffer_a.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(iTime); }\n");
  write_file(dir_ / "cube_a.frag", "void mainCubemap(out vec4 c, in vec2 f, in vec3 o, in vec3 d) { c = vec4(1.0); }\n");
  write_file(dir_ / "image.frag", "#pragma channel0 \"buffer_a.frag\" size=5x3\n"
                                  "#pragma channel1 \"cube_a.frag\" cube size=16\n"
                                  "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, f) + texture(iChannel1, vec3(1.0)); }\n");
  load("image.frag");
  frame(0);
  EXPECT_TRUE(graph_.pass_times().empty()) << "off by default";
  graph_.time_passes(true, /*finish*/ true);
  frame(1, {8, 6});
  frame(2, {8, 6});
  const auto times = graph_.pass_times();
  ASSERT_EQ(times.size(), 2u) << "one per pass, not per frame; the cube is static, drawn once";
  EXPECT_EQ(times[0].pass.filename(), "buffer_a.frag");
  EXPECT_EQ(times[0].size, glm::ivec2(5, 3));
  EXPECT_EQ(times[1].pass.filename(), "image.frag");
  EXPECT_EQ(times[1].size, glm::ivec2(8, 6));
  for (const auto& t : times) {
    EXPECT_GT(t.wall_ms, 0.0);
    EXPECT_GE(t.gpu_ms, 0.0);
  }
  graph_.restart();  // the cube drawn again
  frame(3, {8, 6});
  const auto again = graph_.pass_times();
  ASSERT_EQ(again.size(), 3u);
  EXPECT_EQ(again[1].pass.filename(), "cube_a.frag");
  EXPECT_EQ(again[1].size, glm::ivec2(16, 16)) << "a face";

  HudFigures figures;
  for (const auto& t : again) figures.passes.push_back({t.pass.filename().string(), t.size, 1.5});
  const std::vector<std::string> lines = hud_lines(figures);
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[3], "  buffer_a.frag                5x3   1.50 ms");
  EXPECT_EQ(lines[4], "  cube_a.frag                16x16   1.50 ms");
  EXPECT_EQ(lines[5], "  image.frag                   8x6   1.50 ms");
}

// A buffer that reads no clock, mouse, keyboard or feedback draws the same
// picture every frame: it is drawn once, and again only after a resize, a
// restart or a reload. One that reads iTime is drawn every frame.
TEST_F(Passes, APassWhosePictureCannotChangeIsDrawnOnce) {
  write_file(dir_ / "buffer_a.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(f.x); }\n");
  write_file(dir_ / "buffer_b.frag", "#pragma channel0 \"buffer_a.frag\"\n"
                                     "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, f) + iTime; }\n");
  write_file(dir_ / "image.frag", "#pragma channel0 \"buffer_a.frag\" filter=nearest\n"
                                  "#pragma channel1 \"buffer_b.frag\"\n"
                                  "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(f), 0); }\n");
  Project& project = load("image.frag");
  graph_.time_passes(true);
  auto drawn = [&] {
    std::vector<std::string> names;
    for (const auto& t : graph_.pass_times()) names.push_back(t.pass.filename().string());
    return names;
  };
  using Names = std::vector<std::string>;
  EXPECT_EQ(at(frame(0), 2, 0)[0], 2.5f);
  EXPECT_EQ(drawn(), (Names{"buffer_a.frag", "buffer_b.frag", "image.frag"}));
  EXPECT_EQ(at(frame(1), 2, 0)[0], 2.5f) << "still there";
  EXPECT_EQ(drawn(), (Names{"buffer_b.frag", "image.frag"})) << "A is static; B reads iTime";
  frame(2, {8, 8});
  EXPECT_EQ(drawn(), (Names{"buffer_a.frag", "buffer_b.frag", "image.frag"})) << "a resize draws it again";
  graph_.restart();
  EXPECT_EQ(at(frame(3, {8, 8}), 2, 0)[0], 2.5f) << "a restart cleared it, and it was drawn again";
  write_file(dir_ / "buffer_a.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(2.0 * f.x); }\n");
  ASSERT_EQ(project.reload(), ReloadStatus::Swapped);
  std::string error;
  ASSERT_TRUE(graph_.update(project, &error)) << error;
  EXPECT_EQ(at(frame(4, {8, 8}), 2, 0)[0], 5.0f) << "a reload draws the new program";
}

// A static pass is drawn again when a pass it reads was drawn after it. A
// pass that reads a later buffer is not static: it sees that buffer's first
// picture at the second frame, as on Shadertoy. A buffer of a size of its
// own follows a picture-sized buffer that a resize drew again.
TEST_F(Passes, AStaticPassIsDrawnAgainWhenWhatItReadsWasDrawnAfterIt) {
  write_file(dir_ / "buffer_a.frag", "#pragma channel0 \"buffer_b.frag\" filter=nearest\n"
                                     "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(0), 0) + 1.0; }\n");
  write_file(dir_ / "buffer_b.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(10.0); }\n");
  write_file(dir_ / "image.frag", "#pragma channel0 \"buffer_a.frag\" filter=nearest\n"
                                  "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(0), 0); }\n");
  load("image.frag");
  EXPECT_EQ(at(frame(0), 0, 0)[0], 1.0f) << "B's previous frame: nothing yet";
  EXPECT_EQ(at(frame(1), 0, 0)[0], 11.0f) << "B's first frame";
  EXPECT_EQ(at(frame(2), 0, 0)[0], 11.0f);

  write_file(dir_ / "buffer_c.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(iResolution.x); }\n");
  write_file(dir_ / "buffer_d.frag", "#pragma channel0 \"buffer_c.frag\" filter=nearest\n"
                                     "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(0), 0); }\n");
  write_file(dir_ / "sized.frag", "#pragma channel0 \"buffer_d.frag\" size=2x2 filter=nearest\n"
                                  "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(0), 0); }\n");
  load("sized.frag");
  EXPECT_EQ(at(frame(0), 0, 0)[0], 4.0f);
  EXPECT_EQ(at(frame(1, {8, 8}), 0, 0)[0], 8.0f) << "C drawn again at 8x8, and D, 2x2, after it";
}

TEST_F(Passes, RenderDrawsEveryFrameBeforeTheOneAskedFor) {
  write_file(dir_ / "buffer_a.frag", "#pragma channel0 self filter=nearest\n"
                                     "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(f), 0) + 1.0; }\n");
  write_file(dir_ / "image.frag", kShowChannel0);
  const auto out = dir_ / "out.exr";
  const test::Outcome r = test::run_binary("render " + (dir_ / "image.frag").string() + " -o " + out.string() +
                                           " --size 4x4 --frame 9");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(test::read_pixels(out)[0], 10.0f) << "frames 0 to 9 each added one";
}

// A Shadertoy JSON export runs as it is: "Buf A" adds Common's STEP each
// frame and the image shows it over 255.
TEST_F(Passes, AShadertoyJsonExportRunsAsItIs) {
  const auto out = dir_ / "out.exr";
  const test::Outcome r = test::run_binary("render " + std::string(RM_TEST_DATA_DIR) + "/shadertoy/counter.json -o " +
                                           out.string() + " --size 4x4 --frame 4");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_FLOAT_EQ(test::read_pixels(out)[0], 5.0f / 255.0f);
}

}  // namespace
}  // namespace rm
