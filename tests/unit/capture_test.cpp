// Capture: files are written whole through a rename, never overwritten when
// asked not to, keep floats in EXR, and carry their metadata.
#include "core/capture.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <csignal>

#include "headless/render_command.h"
#include "support.h"

namespace rm {
namespace {

using test::read_pixels;
using test::TempDir;

Image gradient() {
  Image img{4, 2, {}};
  for (int i = 0; i < 8; ++i) img.rgba.insert(img.rgba.end(), {i * 0.5f - 1.0f, 0.25f, 2.0f, 1.0f});
  return img;
}

int files_in(const std::filesystem::path& dir) {
  return static_cast<int>(std::distance(std::filesystem::directory_iterator(dir), {}));
}

// The window names shots by the millisecond, so two in the same millisecond
// ask for the same name: the second must get its own file.
TEST(Capture, NeverOverwriteAddsANumberAndLeavesNoTemporaries) {
  TempDir dir;
  std::string error;
  auto a = write_image(dir / "shot.png", gradient(), {}, Overwrite::Never, &error);
  auto b = write_image(dir / "shot.png", gradient(), {}, Overwrite::Never, &error);
  ASSERT_TRUE(a && b) << error;
  EXPECT_EQ(*a, dir / "shot.png");
  EXPECT_EQ(*b, dir / "shot-1.png");
  EXPECT_EQ(files_in(dir.path()), 2);
}

TEST(Capture, ReplaceOverwrites) {
  TempDir dir;
  std::string error;
  test::write_file(dir / "out.png", "old");
  ASSERT_TRUE(write_image(dir / "out.png", gradient(), {}, Overwrite::Replace, &error)) << error;
  EXPECT_NE(test::read_file(dir / "out.png"), "old");
  EXPECT_EQ(files_in(dir.path()), 1);
}

TEST(Capture, PngClampsExrKeepsRawFloats) {
  TempDir dir;
  std::string error;
  ASSERT_TRUE(write_image(dir / "a.png", gradient(), {}, Overwrite::Replace, &error)) << error;
  ASSERT_TRUE(write_image(dir / "a.exr", gradient(), {}, Overwrite::Replace, &error)) << error;
  auto png = read_pixels(dir / "a.png");
  auto exr = read_pixels(dir / "a.exr");
  ASSERT_EQ(png.size(), 4u * 2 * 4);
  ASSERT_EQ(exr.size(), 4u * 2 * 4);
  EXPECT_EQ(png[0], 0.0f);   // -1 clamped
  EXPECT_EQ(png[2], 1.0f);   // 2 clamped
  EXPECT_EQ(exr[0], -1.0f);  // kept
  EXPECT_EQ(exr[2], 2.0f);
  EXPECT_NEAR(png[1], 0.25f, 0.5f / 255);
}

// Every format the host offers writes a picture that reads back. HDR and
// PNM take no alpha, and were refused after the render ("HDR can only
// support 3-channel images"); Debian's OpenImageIO writes JPEG 2000 files
// that nothing reads, so .jp2 is not offered.
TEST(Capture, EveryOfferedFormatWritesAPictureThatReadsBack) {
  TempDir dir;
  const std::vector<std::string> formats = image_codecs()->encodable_extensions();
  EXPECT_GE(formats.size(), 8u);
  for (const std::string& ext : formats) {
    SCOPED_TRACE("." + ext);
    Image flat{4, 2, {}};  // one colour: lossy formats keep it
    for (int i = 0; i < 8; ++i) flat.rgba.insert(flat.rgba.end(), {0.25f, 0.5f, 0.75f, 1.0f});
    std::string error;
    const fs::path path = dir / ("a." + ext);
    ASSERT_TRUE(write_image(path, flat, {}, Overwrite::Replace, &error)) << error;
    auto in = OIIO::ImageInput::open(path.string());
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec spec = in->spec();
    ASSERT_EQ(spec.width, 4);
    ASSERT_EQ(spec.height, 2);
    ASSERT_GE(spec.nchannels, 3);
    std::vector<float> px(static_cast<size_t>(spec.image_pixels() * spec.nchannels));
    ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data())) << in->geterror();
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(px[static_cast<size_t>(c)], 0.25f * (c + 1), 0.03f) << "channel " << c;
  }
}

TEST(Capture, MetadataRoundTrips) {
  TempDir dir;
  std::string error;
  FrameInputs in;
  in.resolution = {4, 2, 1};
  in.time = 1.25f;
  in.frame = 7;
  in.mouse = {1, 2, -3, -4};
  SourceOptions source;
  source.include_dirs = {"lib"};
  source.defines = {{"RM_MAX_STEPS", "64"}, {"FAST", ""}};
  for (const char* name : {"m.png", "m.exr"}) {
    ASSERT_TRUE(write_image(dir / name, gradient(), frame_metadata("scene.frag", source, in), Overwrite::Replace, &error));
    Metadata meta = read_metadata(dir / name);
    auto get = [&](const std::string& key) {
      for (auto& [k, v] : meta)
        if (k == key) return v;
      return std::string("<missing>");
    };
    EXPECT_EQ(get("raymarching:iTime"), "1.25") << name;
    EXPECT_EQ(get("raymarching:iFrame"), "7") << name;
    EXPECT_EQ(get("raymarching:iMouse"), "1,2,-3,-4") << name;
    EXPECT_EQ(get("raymarching:define:RM_MAX_STEPS"), "64") << name;
    EXPECT_EQ(get("raymarching:define:FAST"), "1") << name;
    EXPECT_NE(get("ImageDescription")
                  .find("raymarching render scene.frag -I lib -D RM_MAX_STEPS=64 -D FAST=1 --size 4x2 --time 1.25 --frame 7"),
              std::string::npos);
  }
}

TEST(Capture, UnknownExtensionAndMissingDirectoryAreRefusedBeforeWriting) {
  TempDir dir;
  EXPECT_NE(check_output_path(dir / "x.notanimage").value_or("").find("cannot write images of type '.notanimage'"), std::string::npos);
  EXPECT_NE(check_output_path(dir / "noext").value_or("").find("no extension"), std::string::npos);
  EXPECT_NE(check_output_path(dir / "missing/x.png").value_or("").find("does not exist"), std::string::npos);
  test::write_file(dir / "file", "");
  EXPECT_NE(check_output_path(dir / "file/x.png").value_or("").find("'" + (dir / "file").string() + "' is not a directory"),
            std::string::npos);
  EXPECT_FALSE(check_output_path(dir / "x.png"));
}

TEST(Capture, FailedWriteLeavesNothingBehind) {
  std::string error;
  // /proc refuses new files even for root, after the pre-checks pass.
  EXPECT_FALSE(write_image("/proc/rm-test-shot.png", gradient(), {}, Overwrite::Replace, &error));
  EXPECT_NE(error.find("/proc/rm-test-shot.png"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists("/proc/rm-test-shot.png"));
}

// Noise compresses badly, so its PNG is far larger than the limit below.
Image noise(int size) {
  Image img{size, size, {}};
  unsigned state = 12345;
  for (int i = 0; i < size * size * 4; ++i) {
    state = state * 1664525u + 1013904223u;
    img.rgba.push_back(static_cast<float>(state >> 8) / 16777216.0f);
  }
  return img;
}

// A full disk, simulated with a file size limit: writes past it fail with
// EFBIG part way through, as they would with ENOSPC. Only the soft limit is
// lowered, so it can be put back.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &saved_);
    saved_handler_ = signal(SIGXFSZ, SIG_IGN);  // fail the write instead of killing the process
    const rlimit limit{bytes, saved_.rlim_max};
    setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &saved_);
    signal(SIGXFSZ, saved_handler_);
  }

 private:
  rlimit saved_{};
  void (*saved_handler_)(int) = nullptr;
};

// The write fails with a message naming the file, the file already under the
// final name keeps its old bytes, and no temporary is left.
TEST(Capture, FullDiskPartWayLeavesTheOldFileAndNoTemporary) {
  TempDir dir;
  for (const fs::path& path : {dir / "png" / "shot.png", dir / "exr" / "shot.exr"}) {
    test::write_file(path, "old picture");
    std::string error;
    std::optional<fs::path> written;
    {
      FileSizeLimit full_disk(16384);
      written = write_image(path, noise(256), {}, Overwrite::Replace, &error);
    }
    EXPECT_FALSE(written) << path;
    EXPECT_NE(error.find("cannot write '" + path.string() + "'"), std::string::npos) << error;
    EXPECT_EQ(test::read_file(path), "old picture");
    EXPECT_EQ(files_in(path.parent_path()), 1) << "a temporary was left in " << path.parent_path();
  }
}

// Files written together (an import's project): when the last cannot be
// written, none is, the first keeps its old bytes, and no temporary is left.
TEST(Capture, FilesWrittenTogetherAreAllWrittenOrNone) {
  TempDir dir;
  test::write_file(dir / "image.frag", "old image");
  std::string error;
  bool written = false;
  {
    FileSizeLimit full_disk(16384);
    written = write_whole_files({{dir / "image.frag", "new image"}, {dir / "buffer_a.frag", std::string(20000, 'x')}},
                                &error);
  }
  EXPECT_FALSE(written);
  EXPECT_NE(error.find("cannot write '" + (dir / "buffer_a.frag").string() + "'"), std::string::npos) << error;
  EXPECT_EQ(test::read_file(dir / "image.frag"), "old image");
  EXPECT_EQ(files_in(dir.path()), 1) << "a temporary or a part was left";
  ASSERT_TRUE(write_whole_files({{dir / "image.frag", "new image"}, {dir / "buffer_a.frag", "a"}}, &error)) << error;
  EXPECT_EQ(test::read_file(dir / "image.frag"), "new image");
  EXPECT_EQ(test::read_file(dir / "buffer_a.frag"), "a");
}

TEST(SequencePath, ExpandsOnePrintfCounter) {
  EXPECT_EQ(sequence_path("out/frame_%04d.png", 12), std::filesystem::path("out/frame_0012.png"));
  EXPECT_EQ(sequence_path("f%d.exr", 3), std::filesystem::path("f3.exr"));
  EXPECT_FALSE(sequence_path("frame.png", 1));
  EXPECT_FALSE(sequence_path("f%d_%d.png", 1));
  EXPECT_FALSE(sequence_path("f%s.png", 1));
}

}  // namespace
}  // namespace rm
