// Number tweaks on the GPU: a save that changes only numbers is shown by
// the scene's twin without a compile, draws what the exact program draws,
// and the exact program follows at the next prepare().
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>

#include "core/data_paths.h"
#include "core/lexing.h"
#include "core/renderer.h"
#include "core/scene.h"
#include "egl_fixture.h"
#include "support.h"

namespace rm {
namespace {

using test::TempDir;
using test::write_file;

constexpr char kScene[] = R"(const float kSize = 0.5;
void mainImage(out vec4 c, in vec2 f) {
  vec2 uv = f / iResolution.xy;
  c = vec4(uv.x * 0.25, step(kSize, uv.y) * 0.5, 0.125, 1.0);
}
)";

std::string with(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

class TweakGpu : public test::EglTest {
 protected:
  Image render(const Scene& scene, glm::ivec2 size) {
    FrameInputs in;
    in.resolution = glm::vec3(size, 1.0f);
    in.time = 1.0f;
    return renderer_.render_image(*scene.program(), in, channels_, size);
  }
  // The largest difference of any channel of any pixel.
  static float max_difference(const Image& a, const Image& b) {
    float most = 0;
    for (int y = 0; y < a.height; ++y)
      for (int x = 0; x < a.width; ++x)
        for (int c = 0; c < 4; ++c) most = std::max(most, std::abs(a.pixel(x, y)[c] - b.pixel(x, y)[c]));
    return most;
  }

  // `text` written to `path` and loaded into `scene`, with its twin built.
  static void load_with_twin(Scene& scene, const fs::path& path, const std::string& text = kScene) {
    write_file(path, text);
    ASSERT_EQ(scene.reload(), ReloadStatus::Swapped) << join(scene.diagnostics());
    ASSERT_TRUE(scene.prepare_twin());
    scene.commit_twin();
  }

  // A scene that includes shaderlib's marching loop, so that its knobs are used.
  static std::string marched(const std::string& image) {
    return "#include <rm/march.glsl>\nfloat map(vec3 p) { return length(p) - 1.0; }\n" + image;
  }
  static SourceOptions with_shaderlib(std::vector<Define> defines) {
    SourceOptions options;
    options.shaderlib_dir = shaderlib_dir();
    options.defines = std::move(defines);
    return options;
  }

  Renderer renderer_;
  ChannelInputs channels_{};
  TempDir dir_;
};

TEST_F(TweakGpu, ANumberEditShowsAtOnceInTheTwinAndThenInTheExactProgram) {
  const auto path = dir_ / "scene.frag";
  write_file(path, kScene);
  Scene scene(path, {});
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped);
  EXPECT_TRUE(scene.wants_twin());
  ASSERT_TRUE(scene.prepare_twin());
  scene.commit_twin();
  EXPECT_FALSE(scene.wants_twin());

  const std::string tweaked = with(kScene, "uv.x * 0.25", "uv.x * 0.75");
  write_file(path, tweaked);
  ASSERT_EQ(scene.prepare(), ReloadStatus::Swapped);
  EXPECT_EQ(scene.times().validate, 0.0) << "no glslang";
  EXPECT_EQ(scene.times().driver, 0.0) << "no compile";
  scene.commit();
  EXPECT_TRUE(scene.tweaked());
  EXPECT_EQ(scene.generation(), 2);
  EXPECT_EQ(scene.source().text.find("0.25"), std::string::npos) << "the source is the tweak's";
  const Image twin = render(scene, {16, 8});
  EXPECT_NEAR(twin.pixel(15, 0)[0], 0.75f * 15.5f / 16.0f, 1e-6f);

  TempDir other;
  write_file(other / "scene.frag", tweaked);
  Scene exact(other / "scene.frag", {});
  ASSERT_EQ(exact.reload(), ReloadStatus::Swapped);
  EXPECT_EQ(max_difference(twin, render(exact, {16, 8})), 0.0f);

  // The same text again builds the exact program.
  ASSERT_EQ(scene.prepare(), ReloadStatus::Swapped);
  EXPECT_GT(scene.times().driver, 0.0);
  scene.commit();
  EXPECT_FALSE(scene.tweaked());
  EXPECT_EQ(max_difference(render(scene, {16, 8}), twin), 0.0f);
  EXPECT_EQ(scene.reload(), ReloadStatus::Unchanged);

  // A code edit compiles; so does a float become an int. The twin stays for
  // the next number edit of a text of its skeleton.
  for (const std::string& code : {with(kScene, "0.125, 1.0", "0.125 + uv.y, 1.0"), with(kScene, "= 0.5", "= 1")}) {
    write_file(path, code);
    ASSERT_EQ(scene.prepare(), ReloadStatus::Swapped);
    EXPECT_GT(scene.times().driver, 0.0);
    scene.commit();
    EXPECT_FALSE(scene.tweaked());
  }
  write_file(path, with(kScene, "0.125", "0.375"));
  ASSERT_EQ(scene.prepare(), ReloadStatus::Swapped);
  EXPECT_EQ(scene.times().driver, 0.0);
  scene.commit();
  EXPECT_NEAR(render(scene, {16, 8}).pixel(0, 0)[2], 0.375f, 1e-6f);
}

// A save that changes only comments and blanks builds nothing and leaves the
// exact program on screen; a number edit after it is still a tweak.
TEST_F(TweakGpu, ANumberEditAfterACommentEditIsStillATweak) {
  const auto path = dir_ / "scene.frag";
  Scene scene(path, {});
  ASSERT_NO_FATAL_FAILURE(load_with_twin(scene, path));
  const std::string commented = with(kScene, "uv.x * 0.25", "uv.x /* red */ *  0.25");
  write_file(path, commented);
  ASSERT_EQ(scene.prepare(), ReloadStatus::Unchanged);
  EXPECT_EQ(scene.times().driver, 0.0) << "no compile";
  EXPECT_FALSE(scene.tweaked());

  write_file(path, with(commented, "0.25", "0.75"));
  ASSERT_EQ(scene.prepare(), ReloadStatus::Swapped);
  EXPECT_EQ(scene.times().validate, 0.0) << "no glslang";
  EXPECT_EQ(scene.times().driver, 0.0) << "no compile";
  scene.commit();
  EXPECT_TRUE(scene.tweaked());
  Scene fresh(path, {});
  ASSERT_EQ(fresh.reload(), ReloadStatus::Swapped);
  EXPECT_EQ(render(scene, {8, 8}).rgba, render(fresh, {8, 8}).rgba);
}

TEST_F(TweakGpu, ATwinBuildGivesUpWhenCancelledAndIsWantedStill) {
  const auto path = dir_ / "scene.frag";
  write_file(path, kScene);
  Scene scene(path, {});
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped);
  int asked = 0;
  EXPECT_FALSE(scene.prepare_twin({}, [&] { return ++asked >= 1; }));  // before the compile
  EXPECT_EQ(asked, 1);
  EXPECT_TRUE(scene.wants_twin());
  bool warmed = false;
  asked = 0;
  EXPECT_FALSE(scene.prepare_twin([&](const fs::path&, const Program&, const Source&) { warmed = true; },
                                  [&] { return ++asked >= 2; }));  // compiled, before the warm-up
  EXPECT_FALSE(warmed);
  EXPECT_TRUE(scene.wants_twin());
  ASSERT_TRUE(scene.prepare_twin({}, [] { return false; }));
  scene.commit_twin();
  EXPECT_FALSE(scene.wants_twin());
  write_file(path, with(kScene, "0.125", "0.375"));
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped);
  EXPECT_TRUE(scene.tweaked());
}

TEST_F(TweakGpu, ATweaksExactBuildIsPutOffWhenCancelledAndOnlyIt) {
  const auto path = dir_ / "scene.frag";
  Scene scene(path, {});
  ASSERT_NO_FATAL_FAILURE(load_with_twin(scene, path));
  write_file(path, with(kScene, "0.125", "0.375"));
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped);
  ASSERT_TRUE(scene.tweaked());
  for (int stage = 1; stage <= 3; ++stage) {  // before glslang, the driver, the warm-up
    int asked = 0;
    EXPECT_EQ(scene.prepare([&] { return ++asked >= stage; }), ReloadStatus::Unchanged) << stage;
    EXPECT_EQ(asked, stage);
    EXPECT_TRUE(scene.tweaked());
    EXPECT_EQ(scene.generation(), 2);
  }
  ASSERT_EQ(scene.prepare([] { return false; }), ReloadStatus::Swapped);
  scene.commit();
  EXPECT_FALSE(scene.tweaked());
  EXPECT_NEAR(render(scene, {4, 4}).pixel(0, 0)[2], 0.375f, 1e-6f);
  // A build that is not a tweak's is never put off.
  write_file(path, with(kScene, "0.125, 1.0", "0.125 + uv.y, 1.0"));
  EXPECT_EQ(scene.prepare([] { return true; }), ReloadStatus::Swapped);
}

// The window builds a tweak's exact program in the background as a job on
// copies, and shows a number edit saved meanwhile at once: the job's
// program, for a text no longer shown, goes to the cache, not on screen.
TEST_F(TweakGpu, ANumberEditDuringTheExactBuildIsShownAtOnceAndTheBuildIsCached) {
  const auto path = dir_ / "scene.frag";
  Scene scene(path, {});
  ASSERT_NO_FATAL_FAILURE(load_with_twin(scene, path));
  const std::string first = with(kScene, "0.125", "0.375");
  write_file(path, first);
  ASSERT_EQ(scene.prepare_without_compiling(), ReloadStatus::Swapped);
  scene.commit();
  ASSERT_TRUE(scene.tweaked());
  const std::optional<Scene::ExactJob> job = scene.exact_job();
  ASSERT_TRUE(job);
  EXPECT_EQ(job->source.text, scene.source().text);

  write_file(path, with(kScene, "0.125", "0.625"));  // saved while the job runs
  ASSERT_EQ(scene.prepare_without_compiling(), ReloadStatus::Swapped);
  EXPECT_EQ(scene.times().driver, 0.0);
  scene.commit();
  EXPECT_NEAR(render(scene, {4, 4}).pixel(0, 0)[2], 0.625f, 1e-6f);

  bool warmed = false;
  Scene::ExactResult result =
      Scene::build_exact(*job, [&](const fs::path& pass, const Program&, const Source&) { warmed = pass == path; });
  EXPECT_TRUE(warmed);
  ASSERT_TRUE(result.built);
  EXPECT_GT(result.times.driver, 0.0);
  EXPECT_EQ(scene.take_exact(std::move(result)), ReloadStatus::Unchanged) << "for a text no longer shown";
  EXPECT_TRUE(scene.tweaked());
  EXPECT_NEAR(render(scene, {4, 4}).pixel(0, 0)[2], 0.625f, 1e-6f);

  // Its text saved again comes from the cache: its exact program, no compile.
  write_file(path, first);
  ASSERT_EQ(scene.prepare_without_compiling(), ReloadStatus::Swapped);
  scene.commit();
  EXPECT_FALSE(scene.tweaked());
  EXPECT_NEAR(render(scene, {4, 4}).pixel(0, 0)[2], 0.375f, 1e-6f);
}

TEST_F(TweakGpu, AnExactBuildStillCurrentIsCommittedAndAPutOffOneChangesNothing) {
  const auto path = dir_ / "scene.frag";
  Scene scene(path, {});
  ASSERT_NO_FATAL_FAILURE(load_with_twin(scene, path));
  EXPECT_FALSE(scene.exact_job()) << "no tweak on screen";
  write_file(path, with(kScene, "0.125", "0.375"));
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped);
  ASSERT_TRUE(scene.tweaked());
  const std::optional<Scene::ExactJob> job = scene.exact_job();
  ASSERT_TRUE(job);
  for (int stage = 1; stage <= 3; ++stage) {  // before glslang, the driver, the warm-up
    int asked = 0;
    bool warmed = false;
    Scene::ExactResult put_off = Scene::build_exact(
        *job, [&](const fs::path&, const Program&, const Source&) { warmed = true; }, [&] { return ++asked >= stage; });
    EXPECT_TRUE(put_off.put_off) << stage;
    EXPECT_FALSE(warmed) << stage;
    EXPECT_EQ(scene.take_exact(std::move(put_off)), ReloadStatus::Unchanged) << stage;
    EXPECT_TRUE(scene.tweaked());
  }
  ASSERT_EQ(scene.take_exact(Scene::build_exact(*job)), ReloadStatus::Swapped);
  scene.commit();
  EXPECT_FALSE(scene.tweaked());
  EXPECT_EQ(scene.generation(), 3);
  EXPECT_NEAR(render(scene, {4, 4}).pixel(0, 0)[2], 0.375f, 1e-6f);
  EXPECT_EQ(scene.reload(), ReloadStatus::Unchanged);
}

// What the window may do while a background build runs: a code edit needs
// the builder, and asking leaves the scene as it was; a broken include
// fails at once, and an exact build that ends after it is not shown.
TEST_F(TweakGpu, WithoutCompilingACodeEditIsLeftForTheBuilderAndABrokenSaveFails) {
  const auto path = dir_ / "scene.frag";
  Scene scene(path, {});
  ASSERT_NO_FATAL_FAILURE(load_with_twin(scene, path));
  write_file(path, with(kScene, "0.125", "0.375"));
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped);
  const std::optional<Scene::ExactJob> job = scene.exact_job();
  ASSERT_TRUE(job);

  write_file(path, with(kScene, "0.125, 1.0", "0.125 + uv.y, 1.0"));
  EXPECT_EQ(scene.prepare_without_compiling(), ReloadStatus::NeedsCompile);
  EXPECT_EQ(scene.generation(), 2);
  EXPECT_TRUE(scene.tweaked());
  EXPECT_TRUE(scene.diagnostics().empty());

  write_file(path, "#include \"missing.glsl\"\n" + std::string(kScene));
  EXPECT_EQ(scene.prepare_without_compiling(), ReloadStatus::Failed);
  ASSERT_FALSE(scene.diagnostics().empty());
  EXPECT_NE(scene.diagnostics().front().message.find("missing.glsl"), std::string::npos);
  EXPECT_EQ(scene.take_exact(Scene::build_exact(*job)), ReloadStatus::Unchanged) << "the save after it failed";
  EXPECT_FALSE(scene.diagnostics().empty()) << "its errors stay";
  EXPECT_NEAR(render(scene, {4, 4}).pixel(0, 0)[2], 0.375f, 1e-6f);

  write_file(path, with(kScene, "0.125, 1.0", "0.125 + uv.y, 1.0"));
  ASSERT_EQ(scene.prepare(), ReloadStatus::Swapped) << "the builder compiles it";
  scene.commit();
  EXPECT_NEAR(render(scene, {4, 4}).pixel(0, 0)[2], 0.125f + 3.5f / 4.0f, 1e-6f);  // the top row's uv.y
}

// A twin job for a program no longer running is dropped, and wanted again.
TEST_F(TweakGpu, ATwinBuiltForAProgramNoLongerRunningIsDropped) {
  const auto path = dir_ / "scene.frag";
  write_file(path, kScene);
  Scene scene(path, {});
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped);
  const std::optional<Scene::TwinJob> job = scene.twin_job();
  ASSERT_TRUE(job);
  EXPECT_FALSE(scene.wants_twin());
  write_file(path, with(kScene, "0.125, 1.0", "0.125 + uv.y, 1.0"));  // built meanwhile
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped);
  Scene::TwinResult result = Scene::build_twin(*job);
  ASSERT_TRUE(result.twin);
  EXPECT_FALSE(scene.take_twin(std::move(result)));
  EXPECT_TRUE(scene.wants_twin());
  ASSERT_TRUE(scene.prepare_twin());
  scene.commit_twin();
  write_file(path, with(with(kScene, "0.125, 1.0", "0.125 + uv.y, 1.0"), "0.25", "0.5"));
  EXPECT_EQ(scene.prepare_without_compiling(), ReloadStatus::Swapped) << "a tweak of the running program's twin";
}

TEST_F(TweakGpu, ABrokenSaveBetweenTweaksKeepsTheTweakOnScreenAndItsMendIsATweak) {
  const auto path = dir_ / "scene.frag";
  Scene scene(path, {});
  ASSERT_NO_FATAL_FAILURE(load_with_twin(scene, path));
  write_file(path, with(kScene, "0.125", "0.625"));
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped);
  write_file(path, with(kScene, "0.125,", "0.625 +,"));
  EXPECT_EQ(scene.reload(), ReloadStatus::Failed);
  EXPECT_EQ(scene.diagnostics().front().line, 4);
  EXPECT_NEAR(render(scene, {4, 4}).pixel(0, 0)[2], 0.625f, 1e-6f);
  // A number edit that mends it is a tweak again, without the errors.
  write_file(path, with(kScene, "0.125", "0.5"));
  ASSERT_EQ(scene.prepare(), ReloadStatus::Swapped);
  EXPECT_TRUE(scene.latest_diagnostics().empty()) << join(scene.latest_diagnostics());
  scene.commit();
  EXPECT_TRUE(scene.tweaked());
  EXPECT_TRUE(scene.diagnostics().empty());
  EXPECT_NEAR(render(scene, {4, 4}).pixel(0, 0)[2], 0.5f, 1e-6f);
}

// A number of a constant, a global or a #define is a tweak too; where the
// driver rejects that twin (an int constant needs a float one), the twin of
// the function bodies stands in, and such a number is a code edit again.
TEST_F(TweakGpu, AConstantsNumberIsATweakUnlessAnotherConstantNeedsIt) {
  const std::string constants = "#define kGreen 0.5\n" + with(kScene, "0.125", "kBlue");
  const std::string scene = with(constants, "const float kSize = 0.5;", "const float kSize = 0.5;\nfloat kBlue = 0.125;");
  const auto path = dir_ / "scene.frag";
  Scene wide(path, {});
  ASSERT_NO_FATAL_FAILURE(load_with_twin(wide, path, with(scene, "step(kSize, uv.y) * 0.5", "step(kSize, uv.y) * kGreen")));
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"kSize = 0.5", "kSize = 0.25"}, {"kBlue = 0.125", "kBlue = 0.75"}, {"kGreen 0.5", "kGreen 0.375"}}) {
    const std::string tweaked = with(test::read_file(path), from, to);
    write_file(path, tweaked);
    ASSERT_EQ(wide.prepare(), ReloadStatus::Swapped) << from;
    EXPECT_EQ(wide.times().driver, 0.0) << from << ": no compile";
    wide.commit();
    ASSERT_TRUE(wide.tweaked()) << from;
    TempDir other;
    write_file(other / "scene.frag", tweaked);
    Scene exact(other / "scene.frag", {});
    ASSERT_EQ(exact.reload(), ReloadStatus::Swapped);
    EXPECT_EQ(max_difference(render(wide, {16, 8}), render(exact, {16, 8})), 0.0f) << from;
  }
  EXPECT_NEAR(render(wide, {16, 8}).pixel(0, 0)[1], 0.375f, 1e-6f);
  EXPECT_NEAR(render(wide, {16, 8}).pixel(0, 0)[2], 0.75f, 1e-6f);
  EXPECT_FALSE(wide.constants_twin_rejected());

  // An int constant made from kSize: that twin does not compile, and the
  // error says where (for -v). It is glslang's: glslang checks a twin before
  // the driver sees it, as it checks every text.
  const auto needed = dir_ / "needed.frag";
  Scene narrow(needed, {});
  ASSERT_NO_FATAL_FAILURE(load_with_twin(narrow, needed, with(scene, "float kBlue", "const int kCount = int(kSize * 4.0);\nfloat kBlue")));
  const std::optional<Diagnostic>& why = narrow.constants_twin_rejected();
  ASSERT_TRUE(why);
  EXPECT_EQ(fs::path(why->path), needed);
  EXPECT_EQ(why->line, 3) << why->str();
  EXPECT_EQ(why->column, 18) << why->str();
  EXPECT_EQ(why->message, "'=' : global const initializers must be constant 'const int'");
  write_file(needed, with(test::read_file(needed), "uv.x * 0.25", "uv.x * 0.5"));
  ASSERT_EQ(narrow.prepare(), ReloadStatus::Swapped);
  EXPECT_EQ(narrow.times().driver, 0.0) << "a function body's number is still a tweak";
  narrow.commit();
  EXPECT_TRUE(narrow.tweaked());
  write_file(needed, with(test::read_file(needed), "kSize = 0.5", "kSize = 0.25"));
  ASSERT_EQ(narrow.prepare(), ReloadStatus::Swapped);
  EXPECT_GT(narrow.times().driver, 0.0) << "the constant's number compiles";
}

// A knob's number is a tweak, and the knobs (the panel's) show its new value
// at once: what the exact program that follows has.
TEST_F(TweakGpu, AKnobsNumberShowsInTheKnobsWithTheTweak) {
  const auto path = dir_ / "scene.frag";
  SourceOptions options;
  options.shaderlib_dir = shaderlib_dir();
  Scene scene(path, options);
  const std::string text = "#define RM_HIT_PIXELS 0.35\n#define RM_OMEGA (1.0 + 0.25)\n#include <rm/march.glsl>\n"
                           "float map(vec3 p) { return length(p) - 1.0; }\n" + std::string(kScene);
  ASSERT_NO_FATAL_FAILURE(load_with_twin(scene, path, text));
  auto knobs = [&] {
    std::map<std::string, std::string> out;
    for (const KnobValue& k : scene.knobs()) out[k.knob->name] = k.value;
    return out;
  };
  EXPECT_EQ(knobs().at("RM_HIT_PIXELS"), "0.35");
  EXPECT_EQ(knobs().at("RM_OMEGA"), "(1.0 + 0.25)");
  write_file(path, with(with(text, "0.35", "0.5e0"), "0.25)", "0.125)"));
  ASSERT_EQ(scene.prepare(), ReloadStatus::Swapped);
  EXPECT_EQ(scene.times().driver, 0.0) << "a tweak";
  scene.commit();
  ASSERT_TRUE(scene.tweaked());
  const auto tweaked = knobs();
  EXPECT_EQ(tweaked.at("RM_HIT_PIXELS"), "0.5e0");
  EXPECT_EQ(tweaked.at("RM_OMEGA"), "(1.0 + 0.125)");
  ASSERT_EQ(scene.prepare(), ReloadStatus::Swapped);  // the exact program
  scene.commit();
  ASSERT_FALSE(scene.tweaked());
  EXPECT_EQ(knobs(), tweaked);
}

// A -D's number is a tweak too: the window's controls set the knobs so,
// and the second change of a knob shows without a compile.
TEST_F(TweakGpu, AnOptionsNumberIsATweak) {
  const auto path = dir_ / "scene.frag";
  SourceOptions options = with_shaderlib({{"GAIN", "0.25"}, {"RM_HIT_PIXELS", "0.5"}});
  Scene scene(path, options);
  ASSERT_NO_FATAL_FAILURE(load_with_twin(scene, path, marched(with(kScene, "uv.x * 0.25", "uv.x * GAIN"))));
  options.defines = {{"GAIN", "0.75"}, {"RM_HIT_PIXELS", "2.0"}};
  scene.set_options(options);
  ASSERT_EQ(scene.prepare(), ReloadStatus::Swapped);
  EXPECT_EQ(scene.times().driver, 0.0) << "a tweak";
  scene.commit();
  ASSERT_TRUE(scene.tweaked());
  std::string hit;
  for (const KnobValue& k : scene.knobs())
    if (std::string(k.knob->name) == "RM_HIT_PIXELS") hit = k.value;
  EXPECT_EQ(hit, "2.0");
  Scene exact(path, options);
  ASSERT_EQ(exact.reload(), ReloadStatus::Swapped);
  EXPECT_EQ(max_difference(render(scene, {16, 8}), render(exact, {16, 8})), 0.0f);
  EXPECT_NEAR(render(scene, {16, 8}).pixel(15, 0)[0], 0.75f * 15.5f / 16.0f, 1e-6f);
}

// The window's controls apply a float knob while it is dragged only where
// each change is a tweak: the twin is the running program's and reads the
// knob's -D from a lifted literal.
TEST_F(TweakGpu, AKnobIsTweakedOnlyByTheRunningProgramsTwin) {
  const auto path = dir_ / "scene.frag";
  SourceOptions options = with_shaderlib({{"RM_HIT_PIXELS", "0.5"}, {"RM_MAX_STEPS", "40"}});
  Scene scene(path, options);
  const std::string text = marched(kScene);
  write_file(path, text);
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped) << join(scene.diagnostics());
  EXPECT_FALSE(scene.tweaks_knob("RM_HIT_PIXELS")) << "no twin yet";
  ASSERT_TRUE(scene.prepare_twin());
  scene.commit_twin();
  EXPECT_TRUE(scene.tweaks_knob("RM_HIT_PIXELS"));
  EXPECT_FALSE(scene.tweaks_knob("RM_MAX_STEPS")) << "an int is never lifted";
  EXPECT_FALSE(scene.tweaks_knob("RM_OMEGA")) << "a knob the program does not use";

  options.defines = {{"RM_HIT_PIXELS", "2.0"}, {"RM_MAX_STEPS", "40"}};
  scene.set_options(options);
  ASSERT_EQ(scene.prepare(), ReloadStatus::Swapped);
  scene.commit();
  ASSERT_TRUE(scene.tweaked());
  EXPECT_TRUE(scene.tweaks_knob("RM_HIT_PIXELS")) << "while a tweak shows";

  write_file(path, text + "float unused_name() { return 1.0; }\n");  // new code: compiled
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped);
  ASSERT_FALSE(scene.tweaked());
  EXPECT_FALSE(scene.tweaks_knob("RM_HIT_PIXELS")) << "the twin is the last program's";
  EXPECT_TRUE(scene.prepare_twin());
  scene.commit_twin();
  EXPECT_TRUE(scene.tweaks_knob("RM_HIT_PIXELS"));

  write_file(path, text);  // back to a program the cache holds: the twin kept is not its
  ASSERT_EQ(scene.reload(), ReloadStatus::Swapped);
  EXPECT_FALSE(scene.tweaks_knob("RM_HIT_PIXELS"));
}

// Every example's twin draws the exact program's picture: the literals it
// reads from rm_Tweak are the ones a constant may not need. (The edit
// appends a 0 to the scene's last decimal number: new text, the same value.)
class ExampleTwin : public TweakGpu, public ::testing::WithParamInterface<std::string> {
 protected:
  fs::path original() const { return fs::path(RM_SOURCE_DIR) / "examples" / GetParam(); }

  // The example is loaded and its twin built; then its file reads as
  // `edited`, a save that must be a tweak drawing the exact picture.
  void expect_tweak_draws_exact_picture(const std::string& edited) {
    const fs::path path = original();
    bool edit = false;
    FileSystem files = disk_file_system();
    files.read = [&, disk = files.read](const fs::path& p, Diagnostic* why) -> std::optional<std::string> {
      if (edit && p == path) return edited;
      return disk(p, why);
    };
    SourceOptions options;
    options.shaderlib_dir = shaderlib_dir();
    Scene scene(path, options, files);
    ASSERT_EQ(scene.reload(), ReloadStatus::Swapped) << join(scene.diagnostics());
    const Image exact = render(scene, {64, 36});
    ASSERT_TRUE(scene.prepare_twin()) << "the driver rejected both twins, or nothing was lifted";
    scene.commit_twin();
    edit = true;
    ASSERT_EQ(scene.prepare(), ReloadStatus::Swapped);
    EXPECT_EQ(scene.times().driver, 0.0) << "a compile: a number was not lifted";
    scene.commit();
    ASSERT_TRUE(scene.tweaked());
    EXPECT_LT(max_difference(render(scene, {64, 36}), exact), 1e-3f);
  }
};

TEST_P(ExampleTwin, DrawsTheExactPicture) {
  const std::string text = test::read_file(original());
  const std::regex decimal(R"(\b\d+\.\d+\b)");
  std::smatch last;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), decimal);
       it != std::sregex_iterator(); ++it)
    last = *it;
  ASSERT_FALSE(last.empty());
  std::string edited = text;
  edited.insert(static_cast<size_t>(last.position(0) + last.length(0)), "0");
  expect_tweak_draws_exact_picture(edited);
}

// ... and with every decimal number of its code edited at once (a 0 appended:
// new text, the same values), #defines and constants included: all are
// lifted, and the twin still draws the exact picture.
TEST_P(ExampleTwin, EveryDecimalNumberIsATweak) {
  expect_tweak_draws_exact_picture(std::regex_replace(lexing::strip_comments(test::read_file(original())),
                                                      std::regex(R"(\b\d+\.\d+\b)"), "$&0"));
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleTwin,
                         ::testing::Values("abstract.frag", "cubes.frag", "gallery.frag", "menger.frag",
                                           "optics.frag", "room.frag", "shadertoy.frag", "tori.frag"),
                         [](const auto& info) { return info.param.substr(0, info.param.find('.')); });

}  // namespace
}  // namespace rm
