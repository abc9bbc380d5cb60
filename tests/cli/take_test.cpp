// `render --take` as a user runs it: a take written by hand (as the window
// writes one, core/take.h) replayed frame by frame, as recorded and at
// another rate, and the one-line errors of a take used wrong.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "support.h"

namespace rm {
namespace {

using test::TempDir;
using test::write_file;

// Each channel says one input: R the fraction of iTime, G iMouse.x across the
// picture, B a uniform, A iFrame / 100.
const char* kScene =
    "uniform float gain;  // ui: min=0 max=1 default=0.5\n"
    "void mainImage(out vec4 c, in vec2 f) {\n"
    "  c = vec4(fract(iTime), iMouse.x / iResolution.x, gain, float(iFrame) / 100.0);\n"
    "}\n";

// Three frames of a 4x2 window: a drag from x=1 to x=3, released in the
// last frame, and the uniform set in the panel from 0.25 to 0.75 then.
const char* kTake = R"({
 "raymarching_take": 1,
 "scene": "scene.frag",
 "include_dirs": [],
 "date": "2026-11-24T04:00:00.000",
 "events": [{"frame": 0, "defines": [], "hashes": {}}],
 "frames": [
{"w":0,"t":1.25,"f":10,"r":[4,2],"m":[1,1,1,1],"c":[1,1],"u":{"gain":"0.25"}},
{"w":0.1,"t":1.5,"f":11,"m":[3,1,1,-1],"c":[3,1]},
{"w":0.2,"t":1.75,"f":12,"m":[3,1,-1,-1],"u":{"gain":"0.75"}}
 ]
})";

class Take : public ::testing::Test {
 protected:
  void SetUp() override {
    write_file(dir_ / "scene.frag", kScene);
    write_file(dir_ / "t.take.json", kTake);
  }
  test::Outcome render(const std::string& args) {
    return test::run_binary("render --take " + (dir_ / "t.take.json").string() + " " + args);
  }
  // Pixel (0, 0) of frame `n`'s EXR.
  std::vector<float> pixel(const std::string& pattern, int n) {
    char name[64];
    std::snprintf(name, sizeof name, pattern.c_str(), n);
    const std::vector<float> px = test::read_pixels(dir_ / name);
    return px.size() >= 4 ? std::vector<float>(px.begin(), px.begin() + 4) : std::vector<float>{};
  }
  static void expect_pixel(const std::vector<float>& got, const std::vector<float>& want) {
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-6) << "channel " << i;
  }
  // Arguments that render a 4x2 PNG of one colour to `name` in the folder.
  std::string good_png(const std::string& name, const std::string& colour) {
    write_file(dir_ / (name + ".frag"), "void mainImage(out vec4 c, in vec2 f) { c = " + colour + "; }\n");
    return (dir_ / (name + ".frag")).string() + " --size 4x2 -o " + (dir_ / name).string();
  }
  TempDir dir_;
};

TEST_F(Take, DrawsEveryRecordedFrameWithItsInputs) {
  const test::Outcome r = render("-o " + (dir_ / "a_%d.exr").string() + " --size 8x4");
  ASSERT_EQ(r.status, 0) << r.err;
  // The mouse's pixels scale from the 4x2 window to the 8x4 picture.
  expect_pixel(pixel("a_%d.exr", 0), {0.25f, 0.25f, 0.25f, 0.10f});
  expect_pixel(pixel("a_%d.exr", 1), {0.5f, 0.75f, 0.25f, 0.11f});
  expect_pixel(pixel("a_%d.exr", 2), {0.75f, 0.75f, 0.75f, 0.12f});
  EXPECT_TRUE(pixel("a_%d.exr", 3).empty()) << "one frame per recorded frame";
}

// A take recorded with -U replays without the scene's own #define of it;
// the command line's -D of the name gives it back.
TEST_F(Take, ReplaysWithoutTheMacrosItWasRecordedWithout) {
  write_file(dir_ / "aa.frag", "#define AA\nvoid mainImage(out vec4 c, in vec2 f) {\n#ifdef AA\n  c = vec4(1.0);\n"
                               "#else\n  c = vec4(0.0);\n#endif\n}\n");
  std::string take = kTake;
  take.replace(take.find("\"scene.frag\""), 12, "\"aa.frag\"");
  take.replace(take.find("\"include_dirs\""), 0, "\"undefines\": [\"AA\"], ");
  write_file(dir_ / "t.take.json", take);
  ASSERT_EQ(render("-o " + (dir_ / "u_%d.exr").string()).status, 0);
  expect_pixel(pixel("u_%d.exr", 0), {0.0f, 0.0f, 0.0f, 0.0f});
  const test::Outcome r = render("-o " + (dir_ / "d_%d.exr").string() + " -D AA");
  ASSERT_EQ(r.status, 0) << r.err;
  expect_pixel(pixel("d_%d.exr", 0), {1.0f, 1.0f, 1.0f, 1.0f});
}

TEST_F(Take, AtAnotherRateInterpolatesBetweenTheRecordedFrames) {
  const test::Outcome r = render("-o " + (dir_ / "b_%d.exr").string() + " --size 8x4 --fps 20");
  ASSERT_EQ(r.status, 0) << r.err;
  // 0.2 s at 20 fps: frames at 0, 0.05, ..., 0.2, counted on from the take's first iFrame.
  // Halfway through the drag: iTime and x halfway (2 of 4), the uniform as it was.
  expect_pixel(pixel("b_%d.exr", 1), {0.375f, 0.5f, 0.25f, 0.11f});
  // Released in the next recorded frame: x stays; the uniform halfway from 0.25 to 0.75.
  expect_pixel(pixel("b_%d.exr", 3), {0.625f, 0.75f, 0.5f, 0.13f});
  EXPECT_EQ(pixel("b_%d.exr", 4).size(), 4u);
  EXPECT_TRUE(pixel("b_%d.exr", 5).empty());
}

// 0.2 s at 3 fps is not a whole number of steps: a last frame past the end
// shows how the take ended (iTime, the drag, the uniform set in its last
// frame), where the replay used to stop at 0 s and lose them.
TEST_F(Take, AtARateThatDoesNotDivideItsSpanTheReplayReachesItsEnd) {
  const test::Outcome r = render("-o " + (dir_ / "e_%d.exr").string() + " --size 8x4 --fps 3");
  ASSERT_EQ(r.status, 0) << r.err;
  expect_pixel(pixel("e_%d.exr", 0), {0.25f, 0.25f, 0.25f, 0.10f});
  expect_pixel(pixel("e_%d.exr", 1), {0.75f, 0.75f, 0.75f, 0.11f});
  EXPECT_TRUE(pixel("e_%d.exr", 2).empty());
}

TEST_F(Take, ASliceIsTheSameFramesOfTheWholeReplay) {
  ASSERT_EQ(render("-o " + (dir_ / "w_%d.exr").string() + " --fps 20").status, 0);
  const test::Outcome r = render("-o " + (dir_ / "s_%d.exr").string() + " --fps 20 --frame-range 2:3");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(pixel("s_%d.exr", 1).empty());
  for (int n : {2, 3}) EXPECT_EQ(pixel("s_%d.exr", n), pixel("w_%d.exr", n)) << n;
}

// iTimeDelta and iFrameRate are those of the frames replayed, as the window
// gave them live: iTimeDelta is 0 while the take was paused, and the
// recorded step of iTime after it; iFrameRate counts frames per second of
// the take's wall clock, whatever iTime did. The first frame has no frame
// before it: it gets one step at the replay's rate (here 10 fps: 3 frames in
// 0.2 s).
TEST_F(Take, TimeDeltaIsWhatITimeMovedSinceTheFrameBefore) {
  write_file(dir_ / "delta.frag",
             "void mainImage(out vec4 c, in vec2 f) { c = vec4(iTimeDelta, iFrameRate / 100.0, 0.0, 1.0); }\n");
  write_file(dir_ / "paused.take.json", R"({
 "raymarching_take": 1,
 "scene": "delta.frag",
 "include_dirs": [],
 "date": "2026-11-24T04:00:00.000",
 "events": [{"frame": 0, "defines": [], "hashes": {}}],
 "frames": [
{"w":0,"t":2.0,"f":10,"r":[4,2],"m":[0,0,0,0],"c":[0,0]},
{"w":0.1,"t":2.0,"f":11},
{"w":0.2,"t":2.25,"f":12}
 ]
})");
  const test::Outcome out =
      test::run_binary("render --take " + (dir_ / "paused.take.json").string() + " -o " + (dir_ / "d_%d.exr").string());
  ASSERT_EQ(out.status, 0) << out.err;
  expect_pixel(pixel("d_%d.exr", 0), {0.1f, 0.1f, 0.0f, 1.0f});
  expect_pixel(pixel("d_%d.exr", 1), {0.0f, 0.1f, 0.0f, 1.0f});    // paused: iTime stood still
  expect_pixel(pixel("d_%d.exr", 2), {0.25f, 0.1f, 0.0f, 1.0f});   // iTime moved 0.25 s in 0.1 s of the wall clock
}

// A take recorded with --channel0 replays with that image in iChannel0
// (stored relative to the take), unless the command line gives its own.
TEST_F(Take, ReplaysWithTheChannelImagesItWasRecordedWith) {
  write_file(dir_ / "channel.frag", "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, vec2(0.5)); }\n");
  ASSERT_EQ(test::run_binary("render " + good_png("red.png", "vec4(1.0, 0.0, 0.0, 1.0)")).status, 0);
  ASSERT_EQ(test::run_binary("render " + good_png("blue.png", "vec4(0.0, 0.0, 1.0, 1.0)")).status, 0);
  write_file(dir_ / "channel.take.json", R"({
 "raymarching_take": 1,
 "scene": "channel.frag",
 "channels": ["red.png", "", "", ""],
 "include_dirs": [],
 "date": "2026-11-24T04:00:00.000",
 "events": [{"frame": 0, "defines": [], "hashes": {}}],
 "frames": [{"w":0,"t":1.0,"f":0,"r":[4,2],"m":[0,0,0,0],"c":[0,0]}]
})");
  const std::string take = "render --take " + (dir_ / "channel.take.json").string();
  const test::Outcome recorded = test::run_binary(take + " -o " + (dir_ / "r_%d.exr").string());
  ASSERT_EQ(recorded.status, 0) << recorded.err;
  expect_pixel(pixel("r_%d.exr", 0), {1.0f, 0.0f, 0.0f, 1.0f});
  const test::Outcome given =
      test::run_binary(take + " --channel0 " + (dir_ / "blue.png").string() + " -o " + (dir_ / "b_%d.exr").string());
  ASSERT_EQ(given.status, 0) << given.err;
  expect_pixel(pixel("b_%d.exr", 0), {0.0f, 0.0f, 1.0f, 1.0f});
  // The recorded image gone: the error names the take's channel, not an option
  // the command line never gave.
  std::filesystem::remove(dir_ / "red.png");
  const test::Outcome gone = test::run_binary(take + " -o " + (dir_ / "g_%d.exr").string());
  EXPECT_EQ(gone.status, 2);
  EXPECT_EQ(gone.err, "raymarching: error: take: channel 0 '" + (dir_ / "red.png").string() + "': no such file\n");
  EXPECT_FALSE(std::filesystem::exists(dir_ / "g_0.exr"));
}

// A long take is larger than a shader may be: its own limit is not the shaders' 16 MiB.
TEST_F(Take, ATakeLargerThanAShaderIsRead) {
  write_file(dir_ / "t.take.json", std::string(kTake) + std::string(17u << 20, ' '));
  const test::Outcome r = render("-o " + (dir_ / "l_%d.exr").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(pixel("l_%d.exr", 2).size(), 4u);
}

TEST_F(Take, AChangedSceneIsOneWarningThatNamesIt) {
  // The hand-written take recorded no fingerprint of scene.frag: it is new to it.
  const test::Outcome r = render("-o " + (dir_ / "c_%d.exr").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "raymarching: warning: take: changed since the take was recorded: scene.frag (new); every frame "
                   "is drawn from the files as they are now\n");
}

TEST_F(Take, UsedWrongItSaysHowInOneLine) {
  test::Outcome r = test::run_binary("render " + (dir_ / "scene.frag").string() + " --take " +
                                     (dir_ / "t.take.json").string() + " -o " + (dir_ / "x_%d.png").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "raymarching: error: --take names its own scene: give SCENE or --take, not both\n");
  r = render("-o " + (dir_ / "x_%d.png").string() + " --time 3");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "raymarching: error: --time: a take gives every frame's inputs; leave it out with --take\n");
  r = render("-o " + (dir_ / "still.png").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("a take is a sequence of 3 frames: give OUT a counter"), std::string::npos) << r.err;
  r = test::run_binary("render --take " + (dir_ / "none.take.json").string() + " -o " + (dir_ / "x_%d.png").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("none.take.json"), std::string::npos) << r.err;
  write_file(dir_ / "bad.take.json", "{\"raymarching_take\": 1,\n \"scene\": }");
  r = test::run_binary("render --take " + (dir_ / "bad.take.json").string() + " -o " + (dir_ / "x_%d.png").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("bad.take.json"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("line 2"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  ASSERT_EQ(mkfifo((dir_ / "fifo.take.json").c_str(), 0600), 0);
  r = test::run_binary("render --take " + (dir_ / "fifo.take.json").string() + " -o " + (dir_ / "x_%d.png").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "raymarching: error: take '" + (dir_ / "fifo.take.json").string() +
                       "': is a named pipe (FIFO), not a regular file\n");
  r = test::run_binary("render -o " + (dir_ / "x.png").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "raymarching: error: render needs SCENE, or --take TAKE\n");
  // 3 years (the longest take) at 100000 frames a second: the count was an undefined cast to int.
  write_file(dir_ / "long.take.json", "{\"raymarching_take\": 1, \"scene\": \"scene.frag\", \"frames\": [{\"w\": 0, "
                                      "\"t\": 0, \"f\": 0, \"r\": [16, 9]}, {\"w\": 1e8, \"t\": 1, \"f\": 1}]}");
  r = test::run_binary("render --take " + (dir_ / "long.take.json").string() + " --fps 100000 -o " +
                       (dir_ / "x_%d.png").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err,
            "raymarching: error: the take at 100000 frames a second is over 2147483647 frames; at most 1000000\n");
}

}  // namespace
}  // namespace rm
