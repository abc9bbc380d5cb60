// Cube maps and volumes on the GPU: the three cube map layouts, a Cube A
// pass, a volume in both file layouts, and vflip on a flat image. Each cube
// test samples by direction and checks the face (and where on it) that
// answers.
#include <gtest/gtest.h>

#include <glm/gtc/type_ptr.hpp>

#include "core/capture.h"
#include "core/cube_map.h"
#include "core/frame_graph.h"
#include "core/project.h"
#include "egl_fixture.h"
#include "support.h"

namespace rm {
namespace {

using test::TempDir;
using test::write_file;

// A face's colour: its index in red, and green 1 in its top half (rows first
// in the file) and 0 in its bottom half.
Image face_image(int face, int n) {
  Image image{n, n, {}};
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) image.rgba.insert(image.rgba.end(), {face / 8.0f, y < n / 2 ? 1.0f : 0.0f, 0, 1});
  return image;
}

glm::vec4 at(const Image& image, int x) { return glm::make_vec4(image.pixel(x, 0)); }

class Cubes : public test::EglTest {
 protected:
  void write(const std::string& name, const Image& image) {
    std::string error;
    ASSERT_TRUE(write_image(dir_ / name, image, {}, Overwrite::Replace, &error)) << error;
  }
  // Renders `image` (a file in dir_) at frame `frame` as a 1-pixel-high row
  // of `width` pixels, drawing every frame before it.
  Image render(const std::string& image, int width, int frames = 1) {
    project_ = std::make_unique<Project>(dir_ / image, SourceOptions{});
    EXPECT_EQ(project_->reload(), ReloadStatus::Swapped) << join(project_->diagnostics());
    std::string error;
    EXPECT_TRUE(graph_.update(*project_, &error)) << error;
    Image out;
    for (int f = 0; f < frames; ++f) {
      FrameInputs in;
      in.resolution = glm::vec3(width, 1, 1);
      in.frame = f;
      out = graph_.render_frame(*project_, in, {width, 1});
    }
    return out;
  }
  TempDir dir_;
  Renderer renderer_;
  FrameGraph graph_{renderer_};
  std::unique_ptr<Project> project_;
};

// Pixel i samples direction i: the six axes, then up and down the +Z face.
const char* kSampleDirections = R"(#pragma channel0 "sky.png" cube filter=nearest
const vec3 dirs[8] = vec3[8](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0),
                             vec3(0, 0, 1), vec3(0, 0, -1), vec3(0, 0.5, 1), vec3(0, -0.5, 1));
void mainImage(out vec4 c, in vec2 f) {
  c = vec4(texture(iChannel0, dirs[int(f.x)]).xy, iChannelResolution[0].xy);
}
)";

void expect_faces_answer(const Image& out, int size) {
  for (int f = 0; f < 6; ++f) EXPECT_NEAR(at(out, f).x, f / 8.0f, 1.0f / 255) << "axis " << f << " reads face " << f;
  EXPECT_EQ(at(out, 6).y, 1.0f) << "up on +Z: the top half of the face file";
  EXPECT_EQ(at(out, 7).y, 0.0f) << "down on +Z: the bottom half";
  EXPECT_EQ(at(out, 0).z, float(size)) << "iChannelResolution is the face size";
}

TEST_F(Cubes, SixFaceFilesAreReadInGlOrder) {
  write("sky.png", face_image(0, 8));
  for (int f = 1; f < 6; ++f) write("sky_" + std::to_string(f) + ".png", face_image(f, 8));
  write_file(dir_ / "image.frag", kSampleDirections);
  expect_faces_answer(render("image.frag", 8), 8);
}

TEST_F(Cubes, AHorizontalCrossIsUnfoldedAroundPlusZ) {
  const int n = 8;
  Image cross{4 * n, 3 * n, std::vector<float>(static_cast<size_t>(12 * n * n * 4), 0.0f)};
  const glm::ivec2 cell[6] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}};
  for (int f = 0; f < 6; ++f) {
    const Image face = face_image(f, n);
    for (int y = 0; y < n; ++y)
      std::copy_n(face.pixel(0, y), n * 4, &cross.rgba[((cell[f].y * n + y) * 4 * n + cell[f].x * n) * 4]);
  }
  write("sky.png", cross);
  write_file(dir_ / "image.frag", kSampleDirections);
  expect_faces_answer(render("image.frag", 8), n);
}

// A panorama whose top half is white and whose columns count up from 0 to 1:
// up is white, down is black, -Z is the middle column and +X three quarters.
TEST_F(Cubes, APanoramaIsWrappedAroundTheViewer) {
  const int w = 64, h = 32;
  Image pano{w, h, {}};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) pano.rgba.insert(pano.rgba.end(), {(x + 0.5f) / w, y < h / 2 ? 1.0f : 0.0f, 0, 1});
  write("sky.png", pano);
  write_file(dir_ / "image.frag", kSampleDirections);
  const Image out = render("image.frag", 8);
  EXPECT_EQ(at(out, 2).y, 1.0f) << "up";
  EXPECT_EQ(at(out, 3).y, 0.0f) << "down";
  EXPECT_NEAR(at(out, 5).x, 0.5f, 1.0f / w) << "-Z: the middle column";
  EXPECT_NEAR(at(out, 0).x, 0.75f, 1.0f / w) << "+X";
  EXPECT_NEAR(at(out, 1).x, 0.25f, 1.0f / w) << "-X";
  EXPECT_EQ(at(out, 0).z, float(h / 2)) << "faces half the panorama's height";
}

TEST_F(Cubes, ACubePassWritesWhatItsDirectionSamplesBack) {
  write_file(dir_ / "cube_a.frag", "void mainCubemap(out vec4 c, in vec2 f, in vec3 ro, in vec3 rd) {\n"
                                   "  c = vec4(rd, length(ro));\n}\n");
  write_file(dir_ / "image.frag", R"(#pragma channel0 "cube_a.frag" cube size=32 filter=nearest
void mainImage(out vec4 c, in vec2 f) {
  vec3 d = normalize(vec3(cos(f.x * 0.7), sin(f.x * 1.3), sin(f.x * 0.4 + 1.0)));
  c = vec4(dot(texture(iChannel0, d).xyz, d), texture(iChannel0, d).w, iChannelResolution[0].x, 1);
}
)");
  const Image out = render("image.frag", 16);
  ASSERT_EQ(project_->passes().size(), 2u);
  EXPECT_TRUE(project_->passes()[0].cube);
  for (int x = 0; x < 16; ++x) {
    EXPECT_GT(at(out, x).x, 0.995f) << "direction " << x << " finds the texel that looked along it";
    EXPECT_EQ(at(out, x).y, 0.0f) << "rays start at the origin";
    EXPECT_EQ(at(out, x).z, 32.0f) << "size=32";
  }
}

// The window draws a heavy Cube A pass in tiles, as any buffer: regions of
// its six faces stacked, here 20 rows each, so that most span two faces.
TEST_F(Cubes, ACubePassDrawnInRegionsEqualsOneDrawnWhole) {
  write_file(dir_ / "cube_a.frag", "void mainCubemap(out vec4 c, in vec2 f, in vec3 ro, in vec3 rd) {\n"
                                   "  c = vec4(rd * 0.5 + 0.5, f.x / 32.0);\n}\n");
  write_file(dir_ / "image.frag", R"(#pragma channel0 "cube_a.frag" cube size=32 filter=nearest
void mainImage(out vec4 c, in vec2 f) {
  vec3 d = normalize(vec3(cos(f.x * 0.7), sin(f.x * 1.3), sin(f.x * 0.4 + 1.0)));
  c = texture(iChannel0, d);
}
)");
  const Image whole = render("image.frag", 64);
  FrameGraph tiled_graph{renderer_};
  std::string error;
  ASSERT_TRUE(tiled_graph.update(*project_, &error)) << error;
  FrameInputs in;
  in.resolution = glm::vec3(64, 1, 1);
  tiled_graph.begin_frame(*project_);
  ASSERT_TRUE(tiled_graph.begin_pass(*project_, 0, {64, 1}));
  const glm::ivec2 size = tiled_graph.pass_size(*project_, 0, {64, 1});
  ASSERT_EQ(size, glm::ivec2(32, 6 * 32)) << "the six faces stacked";
  for (int y = 0; y < size.y; y += 20)
    for (int x = 0; x < size.x; x += 16) tiled_graph.draw_pass_region(*project_, 0, in, {x, y, 16, std::min(20, size.y - y)});
  tiled_graph.end_pass(*project_, 0);
  const Image tiled = tiled_graph.render_image(*project_, in, {64, 1}, 1, MotionBlur{});
  ASSERT_EQ(tiled.rgba.size(), whole.rgba.size());
  EXPECT_EQ(tiled.rgba, whole.rgba) << "every direction reads the same texel, drawn in parts or whole";
  bool faces_differ = false;  // the directions do reach several faces
  for (int x = 1; x < 64; ++x) faces_differ |= std::abs(at(whole, x).w - at(whole, 0).w) > 0.0f;
  EXPECT_TRUE(faces_differ);
}

TEST_F(Cubes, ACubePassThatReadsItselfAccumulates) {
  write_file(dir_ / "cube_a.frag", "#pragma channel0 self filter=nearest\n"
                                   "void mainCubemap(out vec4 c, in vec2 f, in vec3 ro, in vec3 rd) {\n"
                                   "  c = texture(iChannel0, rd) + 1.0;\n}\n");
  write_file(dir_ / "buffer_a.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(10); }\n");
  write_file(dir_ / "image.frag", "#pragma channel0 \"cube_a.frag\" cube size=4\n"
                                  "#pragma channel1 \"buffer_a.frag\"\n"
                                  "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, vec3(0, 0, 1)); }\n");
  EXPECT_EQ(at(render("image.frag", 1, 3), 0).x, 3.0f);
  EXPECT_EQ(project_->passes()[0].file.filename(), "buffer_a.frag") << "Buffer A draws before Cube A";
  EXPECT_EQ(project_->passes()[1].file.filename(), "cube_a.frag");
}

TEST_F(Cubes, ACubePassMustBeReadAsACube) {
  write_file(dir_ / "cube_a.frag", "void mainCubemap(out vec4 c, in vec2 f, in vec3 ro, in vec3 rd) { c = vec4(1); }\n");
  write_file(dir_ / "image.frag", "#pragma channel0 \"cube_a.frag\"\n"
                                  "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, f); }\n");
  Project project(dir_ / "image.frag", SourceOptions{});
  EXPECT_EQ(project.reload(), ReloadStatus::Failed);
  EXPECT_NE(join(project.diagnostics()).find("'cube_a.frag' defines mainCubemap: read it with `cube`"),
            std::string::npos)
      << join(project.diagnostics());
}

// A 2x2x2 volume whose texel (x, y, z) holds x, y and z in red, green, blue.
const char* kFetchVolume = R"(#pragma channel0 "vol.bin" volume
void mainImage(out vec4 c, in vec2 f) {
  ivec3 p = ivec3(int(f.x) & 1, (int(f.x) >> 1) & 1, int(f.x) >> 2);
  c = vec4(texelFetch(iChannel0, p, 0).xyz, iChannelResolution[0].z);
}
)";

void expect_volume_answers(const Image& out) {
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 p = at(out, i);
    EXPECT_EQ(glm::vec3(p), glm::vec3(i & 1, (i >> 1) & 1, i >> 2)) << "texel " << i;
    EXPECT_EQ(p.w, 2.0f) << "iChannelResolution.z is the depth";
  }
}

TEST_F(Cubes, AShadertoyBinVolumeIsReadTexelForTexel) {
  std::string bin = "BIN";
  bin += '\0';
  for (uint32_t n : {2u, 2u, 2u}) bin += std::string(reinterpret_cast<const char*>(&n), 4);
  bin += {3, 0, 0, 0};  // 3 channels, layout 0, format 0 (8 bit)
  for (int i = 0; i < 8; ++i)
    bin += {static_cast<char>((i & 1) * 255), static_cast<char>(((i >> 1) & 1) * 255), static_cast<char>((i >> 2) * 255)};
  write_file(dir_ / "vol.bin", bin);
  write_file(dir_ / "image.frag", kFetchVolume);
  expect_volume_answers(render("image.frag", 8));
}

TEST_F(Cubes, AVolumeImageStacksItsSlicesTopToBottom) {
  Image slices{2, 4, {}};
  for (int i = 0; i < 8; ++i) slices.rgba.insert(slices.rgba.end(), {float(i & 1), float((i >> 1) & 1), float(i >> 2), 1});
  write("vol.png", slices);
  std::string shader = kFetchVolume;
  shader.replace(shader.find("vol.bin"), 7, "vol.png");
  write_file(dir_ / "image.frag", shader);
  expect_volume_answers(render("image.frag", 8));
}

// An image saved again is read again (and a cube map's face files too); a
// save that breaks it keeps the last good picture, with an error.
TEST_F(Cubes, AChangedImageIsReadAgainAndABrokenOneKeepsTheLast) {
  write("tex.png", Image{1, 1, {1, 0, 0, 1}});
  write_file(dir_ / "image.frag", "#pragma channel0 \"tex.png\"\n"
                                  "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, vec2(0.5)); }\n");
  EXPECT_EQ(at(render("image.frag", 1), 0), glm::vec4(1, 0, 0, 1));
  auto later = [&](const char* name) {  // a write the clock can tell apart
    fs::last_write_time(dir_ / name, fs::last_write_time(dir_ / name) + std::chrono::seconds(2));
  };
  std::string error;
  EXPECT_TRUE(graph_.update(*project_, &error)) << error;
  EXPECT_FALSE(graph_.images_changed()) << "nothing changed";
  write("tex.png", Image{1, 1, {0, 0, 1, 1}});
  later("tex.png");
  EXPECT_TRUE(graph_.update(*project_, &error)) << error;
  EXPECT_TRUE(graph_.images_changed());
  FrameInputs in;
  in.resolution = glm::vec3(1, 1, 1);
  EXPECT_EQ(at(graph_.render_frame(*project_, in, {1, 1}), 0), glm::vec4(0, 0, 1, 1)) << "the new picture";
  write_file(dir_ / "tex.png", "not a PNG any more");
  later("tex.png");
  EXPECT_FALSE(graph_.update(*project_, &error));
  EXPECT_NE(error.find("tex.png"), std::string::npos) << error;
  EXPECT_EQ(at(graph_.render_frame(*project_, in, {1, 1}), 0), glm::vec4(0, 0, 1, 1)) << "the last good picture";
  EXPECT_EQ(project_->watch_list().size(), 2u) << "the scene and its image";
}

// The window's builder reads a changed image on its thread and hands the
// texture over: the graph takes it while the file is as it was read, and
// reads the file itself once it changed again.
TEST_F(Cubes, AnImageReadElsewhereIsTakenWhileItsFileIsAsRead) {
  write("tex.png", Image{1, 1, {1, 0, 0, 1}});
  write_file(dir_ / "image.frag", "#pragma channel0 \"tex.png\"\n"
                                  "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, vec2(0.5)); }\n");
  EXPECT_EQ(at(render("image.frag", 1), 0), glm::vec4(1, 0, 0, 1));
  auto stale = [&] {
    std::vector<ChannelSpec> out;
    for (const ChannelSpec& spec : project_->images_read())
      if (ImageTextures::stale(spec, graph_.images_held())) out.push_back(spec);
    return out;
  };
  EXPECT_TRUE(stale().empty()) << "nothing changed";
  auto later = [&](int seconds) {  // a write the clock can tell apart
    fs::last_write_time(dir_ / "tex.png", fs::last_write_time(dir_ / "tex.png") + std::chrono::seconds(seconds));
  };
  auto read_elsewhere = [&] {
    const std::vector<ChannelSpec> changed = stale();
    EXPECT_EQ(changed.size(), 1u);
    ImageTextures::Entry read = ImageTextures::read(changed.at(0));
    EXPECT_TRUE(read.texture) << read.error;
    const GLuint texture = read.texture.get();
    std::vector<std::pair<ChannelSpec, ImageTextures::Entry>> handed;
    handed.emplace_back(changed[0], std::move(read));
    graph_.hand_over(std::move(handed));
    return texture;
  };
  FrameInputs in;
  in.resolution = glm::vec3(1, 1, 1);
  std::string error;

  write("tex.png", Image{1, 1, {0, 1, 0, 1}});
  later(2);
  const GLuint green = read_elsewhere();
  ASSERT_TRUE(graph_.update(*project_, &error)) << error;
  EXPECT_TRUE(graph_.images_changed());
  EXPECT_EQ(graph_.pass_states(*project_).at(dir_ / "image.frag").channels[0].texture, green) << "taken";
  EXPECT_EQ(at(graph_.render_frame(*project_, in, {1, 1}), 0), glm::vec4(0, 1, 0, 1));

  write("tex.png", Image{1, 1, {0, 0, 1, 1}});
  later(4);
  const GLuint blue_as_read = read_elsewhere();
  write("tex.png", Image{1, 1, {1, 1, 0, 1}});  // changed again after the read
  later(6);
  ASSERT_TRUE(graph_.update(*project_, &error)) << error;
  EXPECT_NE(graph_.pass_states(*project_).at(dir_ / "image.frag").channels[0].texture, blue_as_read);
  EXPECT_EQ(at(graph_.render_frame(*project_, in, {1, 1}), 0), glm::vec4(1, 1, 0, 1)) << "read again";
}

// A file the builder could not read is handed over as such: the graph says
// why without reading it again on the window's thread (a broken image is
// decoded as far as it goes, a second time).
TEST_F(Cubes, AFileThatCouldNotBeReadElsewhereIsNotReadAgain) {
  write("tex.png", Image{1, 1, {1, 0, 0, 1}});
  write_file(dir_ / "image.frag", "#pragma channel0 \"tex.png\"\n"
                                  "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, vec2(0.5)); }\n");
  EXPECT_EQ(at(render("image.frag", 1), 0), glm::vec4(1, 0, 0, 1));
  const ChannelSpec spec = project_->images_read().at(0);
  write_file(dir_ / "tex.png", "not a PNG");
  const auto broken = fs::last_write_time(dir_ / "tex.png") + std::chrono::seconds(2);
  fs::last_write_time(dir_ / "tex.png", broken);
  ImageTextures::Entry read = ImageTextures::read(spec);
  ASSERT_FALSE(read.texture);
  ASSERT_FALSE(read.error.empty());
  const std::string why = read.error;
  std::vector<std::pair<ChannelSpec, ImageTextures::Entry>> handed;
  handed.emplace_back(spec, std::move(read));
  graph_.hand_over(std::move(handed));
  // Good again, with the stamp the builder read: a graph that read the file would take it.
  write("tex.png", Image{1, 1, {0, 1, 0, 1}});
  fs::last_write_time(dir_ / "tex.png", broken);
  FrameInputs in;
  in.resolution = glm::vec3(1, 1, 1);
  std::string error;
  EXPECT_FALSE(graph_.update(*project_, &error)) << "not read again";
  EXPECT_NE(error.find(why), std::string::npos) << error;
  EXPECT_EQ(at(graph_.render_frame(*project_, in, {1, 1}), 0), glm::vec4(1, 0, 0, 1)) << "the last good image";
  ASSERT_TRUE(graph_.update(*project_, &error)) << "nothing handed over: read, " << error;
  EXPECT_EQ(at(graph_.render_frame(*project_, in, {1, 1}), 0), glm::vec4(0, 1, 0, 1));
}

TEST_F(Cubes, TheFaceFilesOfACubeMapAreWatched) {
  write("sky.png", face_image(0, 4));
  for (int f = 1; f < 6; ++f) write("sky_" + std::to_string(f) + ".png", face_image(f, 4));
  write_file(dir_ / "image.frag", kSampleDirections);
  render("image.frag", 8);
  const auto watched = project_->watch_list();
  for (int f = 1; f < 6; ++f)
    EXPECT_NE(std::find(watched.begin(), watched.end(), dir_ / ("sky_" + std::to_string(f) + ".png")), watched.end())
        << "face " << f;
}

// A --channelN file is named by no pass's text, and was not watched: a save
// of it did not show in the window.
TEST_F(Cubes, TheChannelFilesOfTheCommandLineAreWatched) {
  write("sky.png", face_image(0, 4));
  for (int f = 1; f < 6; ++f) write("night_" + std::to_string(f) + ".png", face_image(f, 4));
  write("night.png", face_image(0, 4));
  write_file(dir_ / "image.frag", kSampleDirections);
  Project project(dir_ / "image.frag", SourceOptions{}, disk_file_system(), {dir_ / "night.png"});
  ASSERT_EQ(project.reload(), ReloadStatus::Swapped) << join(project.diagnostics());
  const auto watched = project.watch_list();
  for (const std::string name : {"night.png", "night_1.png", "night_5.png"})
    EXPECT_NE(std::find(watched.begin(), watched.end(), dir_ / name), watched.end()) << name;
}

// A 1x2 image, red on top: right side up by default, upside down with vflip=false.
TEST_F(Cubes, VflipFalseLeavesAnImageAsGlReadsIt) {
  write("two.png", Image{1, 2, {1, 0, 0, 1, 0, 1, 0, 1}});
  write_file(dir_ / "image.frag", "#pragma channel0 \"two.png\" filter=nearest\n"
                                  "#pragma channel1 \"two.png\" filter=nearest vflip=false\n"
                                  "void mainImage(out vec4 c, in vec2 f) {\n"
                                  "  c = f.x < 1.0 ? texture(iChannel0, vec2(0.5, 0.75)) : texture(iChannel1, vec2(0.5, 0.75));\n}\n");
  const Image out = render("image.frag", 2);
  EXPECT_EQ(at(out, 0), glm::vec4(1, 0, 0, 1)) << "vflip=true: the file's top row is at the top";
  EXPECT_EQ(at(out, 1), glm::vec4(0, 1, 0, 1)) << "vflip=false: the file's top row is at the bottom";
}

}  // namespace
}  // namespace rm
