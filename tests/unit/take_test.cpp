// Takes: the file written and read back, the inputs between two recorded
// frames, the replay's frames at another rate, and what changed since.
#include "core/take.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support.h"

namespace rm {
namespace {

namespace fs = std::filesystem;

TakeFrame frame_at(double wall, float time, int frame, glm::vec4 mouse = glm::vec4(0)) {
  TakeFrame f;
  f.wall = wall;
  f.size = {200, 100};
  f.time = time;
  f.frame = frame;
  f.mouse = mouse;
  f.cursor = glm::vec2(mouse);
  return f;
}

Take sample_take(const fs::path& dir) {
  Take take;
  take.scene = dir / "scene.frag";
  take.include_dirs = {dir / "lib", "/usr/share/elsewhere"};
  take.undefines = {"AA"};
  take.channels[2] = dir / "textures" / "wood.png";
  take.date = "2026-11-24T04:00:00.000";
  take.events.push_back({0, {{"RM_STEPS", "64"}}, {{"scene.frag", "00000000000000aa"}}});
  take.events.push_back({2, {{"RM_STEPS", "128"}}, {{"scene.frag", "00000000000000aa"}}});
  take.frames = {frame_at(0.0, 1.0f, 60), frame_at(0.05, 1.05f, 61, {10, 20, 10, 20}),
                 frame_at(0.1, 1.1f, 62, {30, 20, 10, -20}), frame_at(0.15, 1.15f, 63, {30, 20, -10, -20})};
  take.frames[1].keys = {{65, true}};
  take.frames[3].keys = {{65, false}, {66, true}};
  for (TakeFrame& f : take.frames) f.uniforms = {{"speed", {1.5f}, "1.5"}, {"on", {1.0f}, "true"}};
  take.frames[2].uniforms[0] = {"speed", {2.5f}, "2.5"};
  take.frames[3].uniforms[0] = {"speed", {2.5f}, "2.5"};
  return take;
}

class TakeFiles : public ::testing::Test {
 protected:
  test::TempDir temp_;
  const fs::path dir_ = temp_.path();
};

TEST_F(TakeFiles, ReadsBackWhatWasWrittenAndWritesOnlyWhatChanged) {
  const Take take = sample_take(dir_);
  std::string error;
  const auto written = write_take(dir_ / "a.take.json", take, &error);
  ASSERT_TRUE(written) << error;
  EXPECT_EQ(*written, dir_ / "a.take.json");

  const std::string text = test::read_file(*written);
  // Paths below the take's folder are stored relative to it; the mouse once per change.
  EXPECT_NE(text.find("\"scene\": \"scene.frag\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"lib\""), std::string::npos);
  EXPECT_NE(text.find("/usr/share/elsewhere"), std::string::npos);
  EXPECT_NE(text.find("\"textures/wood.png\""), std::string::npos) << text;
  // The mouse is written in the frames it changed in (all four here), the uniforms in 0 and 2 only.
  auto count = [&](const std::string& what) {
    int n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("\"m\":"), 4);
  EXPECT_EQ(count("\"u\":"), 2);
  EXPECT_EQ(count("\"r\":"), 1);

  const auto back = read_take(*written, &error);
  ASSERT_TRUE(back) << error;
  EXPECT_EQ(back->scene, take.scene);
  EXPECT_EQ(back->include_dirs, take.include_dirs);
  EXPECT_EQ(back->undefines, take.undefines);
  EXPECT_EQ(back->channels, take.channels);  // --channel2 only
  EXPECT_EQ(back->date, take.date);
  ASSERT_EQ(back->events.size(), 2u);
  EXPECT_EQ(back->events[1].frame, 2);
  EXPECT_EQ(back->events[1].defines[0].value, "128");
  EXPECT_EQ(back->defines_at(1)[0].value, "64");
  EXPECT_EQ(back->defines_at(3)[0].value, "128");
  EXPECT_EQ(back->events[0].hashes, take.events[0].hashes);
  ASSERT_EQ(back->frames.size(), take.frames.size());
  for (size_t i = 0; i < take.frames.size(); ++i) {
    const TakeFrame &a = take.frames[i], &b = back->frames[i];
    EXPECT_NEAR(a.wall, b.wall, 1e-6);
    EXPECT_EQ(a.size, b.size);
    EXPECT_EQ(a.time, b.time);
    EXPECT_EQ(a.frame, b.frame);
    EXPECT_EQ(a.mouse, b.mouse) << i;
    EXPECT_EQ(a.cursor, b.cursor) << i;
    ASSERT_EQ(a.keys.size(), b.keys.size()) << i;
    for (size_t k = 0; k < a.keys.size(); ++k) {
      EXPECT_EQ(a.keys[k].code, b.keys[k].code);
      EXPECT_EQ(a.keys[k].down, b.keys[k].down);
    }
    ASSERT_EQ(a.uniforms.size(), b.uniforms.size()) << i;
    for (size_t u = 0; u < a.uniforms.size(); ++u) {
      EXPECT_EQ(a.uniforms[u].text, b.uniforms[u].text) << i;
      EXPECT_EQ(a.uniforms[u].value, b.uniforms[u].value) << i;
    }
  }
}

TEST_F(TakeFiles, NeverWritesOverATake) {
  std::string error;
  const auto first = write_take(dir_ / "t.take.json", sample_take(dir_), &error);
  const auto second = write_take(dir_ / "t.take.json", sample_take(dir_), &error);
  ASSERT_TRUE(first && second) << error;
  EXPECT_EQ(*first, dir_ / "t.take.json");
  EXPECT_NE(*first, *second);
  EXPECT_TRUE(read_take(*first, &error) && read_take(*second, &error)) << error;
}

TEST_F(TakeFiles, ABadTakeSaysWhatIsWrongWithIt) {
  auto error_of = [&](const std::string& text) {
    const fs::path path = dir_ / "bad.take.json";
    test::write_file(path, text);
    std::string error;
    EXPECT_FALSE(read_take(path, &error)) << text;
    return error;
  };
  EXPECT_NE(error_of("{ \"raymarching_take\": 1, ").find("parse error"), std::string::npos);
  // Cut inside a long string, a take's error is still one short line, not the rest of the file.
  const std::string cut = error_of("{ \"raymarching_take\": 1, \"scene\": \"" + std::string(5000, 's'));
  EXPECT_NE(cut.find("missing closing quote; last read: '\"sss"), std::string::npos) << cut;
  EXPECT_LT(cut.size(), 300u) << cut;
  EXPECT_NE(error_of("{\"frames\": []}").find("not a take of this version"), std::string::npos);
  EXPECT_NE(error_of("{\"raymarching_take\": 1e300}").find("not a take of this version"), std::string::npos);
  EXPECT_NE(error_of("{\"raymarching_take\": 1, \"scene\": \"s.frag\", \"frames\": []}").find("holds no frames"),
            std::string::npos);
  EXPECT_NE(error_of("{\"raymarching_take\": 1, \"scene\": \"s.frag\", \"frames\": [{\"w\": 0, \"t\": 0, \"f\": 0}]}")
                .find("no window size"),
            std::string::npos);
  EXPECT_NE(error_of("{\"raymarching_take\": 1, \"scene\": \"s.frag\", \"frames\": [{\"w\": 1, \"t\": 0, \"f\": 0, "
                     "\"r\": [2, 2]}, {\"w\": 0.5, \"t\": 0, \"f\": 1}]}")
                .find("comes before"),
            std::string::npos);
  const std::string frame = "{\"raymarching_take\": 1, \"scene\": \"s.frag\", \"frames\": [{\"w\": 0, \"t\": 0, ";
  EXPECT_NE(error_of(frame + "\"f\": 1e300, \"r\": [2, 2]}]}").find("expected a whole number that fits an int, not 1e+300"),
            std::string::npos);  // nlohmann's cast of it to an int is undefined
  EXPECT_NE(error_of(frame + "\"f\": 0, \"r\": [2, 18446744073709551615]}]}").find("expected a whole number"),
            std::string::npos);
  EXPECT_NE(error_of(frame + "\"f\": 0, \"r\": [2, 2]}, {\"w\": 1, \"t\": 1e300, \"f\": 1}]}")
                .find("expected a number that fits a float, not 1e+300"),
            std::string::npos);  // a double past a float's range: the conversion is undefined
  EXPECT_NE(error_of(frame + "\"f\": 0, \"r\": [2, 2], \"m\": [0, 0, -1e39, 0]}]}").find("fits a float"),
            std::string::npos);
  // A frame's wall clock becomes iDate in nanoseconds: past an int64's range the conversion is undefined.
  EXPECT_NE(error_of(frame + "\"f\": 0, \"r\": [2, 2]}, {\"w\": 1e300, \"t\": 1, \"f\": 1}]}")
                .find("frame 1's \"w\" is 1e+300 s, not from 0 to 100000000 s (3 years) into the take"),
            std::string::npos);
  EXPECT_NE(error_of("{\"raymarching_take\": 1, \"scene\": \"s.frag\", \"frames\": [{\"w\": -5, \"t\": 0, \"f\": 0, "
                     "\"r\": [2, 2]}]}")
                .find("frame 0's \"w\" is -5 s"),
            std::string::npos);
  EXPECT_NE(error_of(frame + "\"f\": 0, \"r\": [100000, 2]}]}").find("frame 0's window is 100000x2, over 16384"),
            std::string::npos);
  // A take's -D and -U are checked as the command line's: each becomes a line of the source.
  const std::string head = "{\"raymarching_take\": 1, \"scene\": \"s.frag\", \"frames\": [{\"w\": 0, \"t\": 0, \"f\": 0, "
                           "\"r\": [2, 2]}], ";
  EXPECT_NE(error_of(head + "\"events\": [{\"frame\": 0, \"defines\": [[\"A\\n#error x\", \"1\"]]}]}")
                .find("a -D of frame 0: 'A\\x0a#error x' is not a macro name"),
            std::string::npos);
  EXPECT_NE(error_of(head + "\"events\": [{\"frame\": 0, \"defines\": [[\"A\", \"1\\n#error x\"]]}]}")
                .find("a -D of frame 0: its value is not one line"),
            std::string::npos);
  EXPECT_NE(error_of(head + "\"undefines\": [\"2x\"]}").find("-U '2x': not a macro name"), std::string::npos);
  const std::string deep = "{\"raymarching_take\": 1, \"scene\": \"s.frag\",\n \"channels\": " + std::string(1000000, '[');
  EXPECT_EQ(error_of(deep + std::string(1000000, ']') + "}"),
            "take '" + (dir_ / "bad.take.json").string() + "': at line 2, column 77: arrays and objects nested deeper "
            "than 64 levels");
  std::string error;
  EXPECT_FALSE(read_take(dir_ / "missing.take.json", &error));
  EXPECT_NE(error.find("missing.take.json"), std::string::npos) << error;
}

TEST(TakeInputs, InterpolateWhatMovesAndHoldWhatSteps) {
  Take take = sample_take("/tmp");
  UserUniforms types;
  UserUniform speed, on;
  speed.name = "speed";
  on.name = "on";
  on.type = UserUniform::Type::Bool;
  types.uniforms = {speed, on};
  // Halfway between frames 2 and 3: the time between them, the button as frame 2 had it.
  FrameInputs in = take_inputs_at(take, 0.125, {200, 100}, types);
  EXPECT_FLOAT_EQ(in.time, 1.125f);
  EXPECT_EQ(in.frame, 62);
  EXPECT_EQ(glm::vec2(in.mouse), glm::vec2(30, 20));  // released in frame 3: not a slope
  EXPECT_GT(in.mouse.z, 0);
  // Halfway between frames 1 and 2, both held: the drag halfway, and the press not repeated.
  in = take_inputs_at(take, 0.075, {200, 100}, types);
  EXPECT_EQ(glm::vec2(in.mouse), glm::vec2(20, 20));
  EXPECT_LT(in.mouse.w, 0);
  EXPECT_FLOAT_EQ(in.uniforms[0].value[0], 2.0f);
  EXPECT_EQ(in.uniforms[0].text, "2");
  EXPECT_EQ(in.uniforms[1].text, "true");
  // At another size the mouse's pixels scale with the picture.
  in = take_inputs_at(take, 0.1, {400, 50}, types);
  EXPECT_EQ(in.mouse, glm::vec4(60, 10, 20, -10));
  EXPECT_EQ(in.resolution, glm::vec3(400, 50, 1));
  // A restart between two frames is a jump.
  take.frames[3].time = 0.0f;
  EXPECT_FLOAT_EQ(take_inputs_at(take, 0.14, {200, 100}, types).time, 1.1f);
  // Before the first frame and after the last: those frames.
  EXPECT_FLOAT_EQ(take_inputs_at(take, -1.0, {200, 100}, types).time, 1.0f);
  EXPECT_FLOAT_EQ(take_inputs_at(take, 9.0, {200, 100}, types).time, 0.0f);
}

TEST(TakeReplay, AsRecordedDrawsEachFrameOnce) {
  const Take take = sample_take("/tmp");
  const TakeReplay replay(take, 0);
  ASSERT_EQ(replay.frames(), 4);
  for (int n = 0; n < 4; ++n) {
    EXPECT_EQ(replay.wall(n), take.frames[static_cast<size_t>(n)].wall);
    EXPECT_EQ(replay.crossed(n), std::make_pair(n, n + 1));
  }
}

TEST(TakeReplay, AtAnotherRateEveryRecordedFrameIsCrossedOnce) {
  Take take = sample_take("/tmp");
  for (double fps : {7.0, 20.0, 60.0, 1000.0}) {
    const TakeReplay replay(take, fps);
    // The last replay frame at the take's end (0.15 s) or the first step past it.
    EXPECT_EQ(replay.frames(), static_cast<int>(std::ceil(0.15 * fps - 1e-9)) + 1) << fps;
    int next = 0;
    for (int n = 0; n < replay.frames(); ++n) {
      const auto [first, end] = replay.crossed(n);
      EXPECT_EQ(first, next) << fps << " frame " << n;
      for (int j = first; j < end; ++j) EXPECT_LE(take.frames[static_cast<size_t>(j)].wall, replay.wall(n) + 1e-12);
      next = end;
    }
    // Every recorded frame, each once: at 7 frames a second the take's
    // 0.15 s is not a whole number of steps, and its last frame (a release)
    // falls after the last step before its end.
    EXPECT_GE(replay.wall(replay.frames() - 1), take.duration()) << fps;
    EXPECT_EQ(next, static_cast<int>(take.frames.size())) << fps;
  }
}

TEST(TakeSources, HashTheFilesLinesNotTheHostsOrTheDefines) {
  Source a;
  a.text = "#version 450\n#define RM_STEPS 64\nvoid f() {}\n";
  a.line_map = {{-1, 0}, {-1, 0}, {0, 1}};
  Source b = a;
  b.text = "#version 450\n#define RM_STEPS 128\nvoid f() {}\n";
  EXPECT_EQ(source_hash(a), source_hash(b));
  b.text = "#version 450\n#define RM_STEPS 64\nvoid g() {}\n";
  EXPECT_NE(source_hash(a), source_hash(b));
  EXPECT_EQ(source_hash(a).size(), 16u);
}

TEST(TakeSources, OneSentenceNamesWhatChanged) {
  Take take;
  take.events.push_back({0, {}, {{"image.frag", "1"}, {"buffer_a.frag", "2"}}});
  EXPECT_FALSE(take_source_changes(take, {{"image.frag", "1"}, {"buffer_a.frag", "2"}}));
  auto said = take_source_changes(take, {{"image.frag", "9"}, {"buffer_b.frag", "3"}});
  ASSERT_TRUE(said);
  EXPECT_NE(said->find("image.frag"), std::string::npos) << *said;
  EXPECT_NE(said->find("buffer_b.frag (new)"), std::string::npos) << *said;
  EXPECT_NE(said->find("buffer_a.frag (gone)"), std::string::npos) << *said;
  // Saved while it recorded: the files as they are now draw every frame.
  take.events.push_back({40, {}, {{"image.frag", "5"}, {"buffer_a.frag", "2"}}});
  said = take_source_changes(take, {{"image.frag", "5"}, {"buffer_a.frag", "2"}});
  ASSERT_TRUE(said);
  EXPECT_NE(said->find("image.frag at frame 40"), std::string::npos) << *said;
  EXPECT_EQ(said->find("changed since"), std::string::npos) << *said;
}

}  // namespace
}  // namespace rm
