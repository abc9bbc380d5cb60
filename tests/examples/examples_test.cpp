// Every scene in examples/ renders headless as a user runs it (`raymarching
// render`): at two times, with no NaN or Inf, a picture that is not constant
// and that matches its committed reference; the picture changes over time and
// when the mouse moves the light. scripts/example-references regenerates the
// references.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/data_paths.h"
#include "support.h"

namespace rm::test {
namespace {

namespace fs = std::filesystem;

const char* kSize = "160x90";
const char* kMouse = "40,60";  // the references' light
const char* kOtherMouse = "130,20";

std::vector<std::string> examples() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(default_scene().parent_path()))
    if (entry.path().extension() == ".frag") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

class Example : public ::testing::TestWithParam<std::string> {
 protected:
  // The example rendered to EXR (raw floats, the shader's exact output).
  std::vector<float> render(double time, const char* mouse) {
    const fs::path out = dir_ / ("frame" + std::to_string(count_++) + ".exr");
    const Outcome r = run_binary("render '" + (default_scene().parent_path() / (GetParam() + ".frag")).string() +
                                 "' -o '" + out.string() + "' --size " + kSize + " --time " + std::to_string(time) +
                                 " --mouse " + mouse);
    EXPECT_EQ(r.status, 0) << r.err;
    return read_pixels(out);
  }

  TempDir dir_;
  int count_ = 0;
};

double mean_abs_difference(const std::vector<float>& a, const std::vector<float>& b) {
  double sum = 0;
  for (size_t i = 0; i < a.size(); ++i) sum += std::abs(std::clamp(a[i], 0.0f, 1.0f) - std::clamp(b[i], 0.0f, 1.0f));
  return a.empty() ? 0.0 : sum / static_cast<double>(a.size());
}

TEST_P(Example, RendersFiniteVariedPicturesThatMatchTheReferences) {
  for (double time : {0.5, 2.5}) {
    SCOPED_TRACE("t = " + std::to_string(time));
    const std::vector<float> px = render(time, kMouse);
    ASSERT_EQ(px.size(), 160u * 90u * 4u);
    size_t non_finite = 0;
    double sum = 0, sum2 = 0;
    for (size_t i = 0; i < px.size(); i += 4) {
      for (int c = 0; c < 4; ++c) non_finite += !std::isfinite(px[i + c]);
      const double luma = 0.2126 * px[i] + 0.7152 * px[i + 1] + 0.0722 * px[i + 2];
      sum += luma;
      sum2 += luma * luma;
    }
    EXPECT_EQ(non_finite, 0u);
    const double n = px.size() / 4.0, stddev = std::sqrt(std::max(0.0, sum2 / n - (sum / n) * (sum / n)));
    EXPECT_GT(stddev, 0.03) << "the picture is (nearly) constant";

    char name[64];
    std::snprintf(name, sizeof name, "%s_t%.1f.png", GetParam().c_str(), time);
    const std::vector<float> reference = read_pixels(fs::path(RM_SOURCE_DIR) / "tests/data/examples" / name);
    ASSERT_EQ(reference.size(), px.size()) << name << " is missing: run scripts/example-references";
    double squared = 0;
    size_t far_off = 0;
    for (size_t i = 0; i < px.size(); ++i) {
      const double d = std::clamp(px[i], 0.0f, 1.0f) - reference[i];
      squared += d * d;
      far_off += std::abs(d) > 0.1;
    }
    EXPECT_LT(std::sqrt(squared / static_cast<double>(px.size())), 0.02) << "differs from " << name;
    EXPECT_LT(static_cast<double>(far_off) / static_cast<double>(px.size()), 0.01) << "differs from " << name;
  }
}

TEST_P(Example, IsAnimatedAndItsLightFollowsTheMouse) {
  const std::vector<float> early = render(0.5, kMouse), late = render(2.5, kMouse), moved = render(2.5, kOtherMouse);
  EXPECT_GT(mean_abs_difference(early, late), 0.003) << "the picture does not change with iTime";
  EXPECT_GT(mean_abs_difference(late, moved), 0.003) << "the picture does not change with iMouse";
}

INSTANTIATE_TEST_SUITE_P(Examples, Example, ::testing::ValuesIn(examples()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// The example projects: each directory of examples/ holds one, opened at its
// image.frag. They render finite, varied pictures after a few frames with
// the button held (paint paints).
std::vector<std::string> projects() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(default_scene().parent_path()))
    if (fs::exists(entry.path() / "image.frag")) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

class ExampleProject : public ::testing::TestWithParam<std::string> {};

TEST_P(ExampleProject, RendersAFiniteVariedPicture) {
  TempDir dir;
  const fs::path out = dir / "out.exr";
  const Outcome r = run_binary("render '" + (default_scene().parent_path() / GetParam() / "image.frag").string() +
                               "' -o '" + out.string() + "' --size " + kSize + " --frame 3 --mouse 40,60,40,60");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<float> px = read_pixels(out);
  ASSERT_EQ(px.size(), 160u * 90u * 4u);
  size_t non_finite = 0;
  float lo = 1e9f, hi = -1e9f;
  for (size_t i = 0; i < px.size(); ++i) {
    non_finite += !std::isfinite(px[i]);
    if (i % 4 == 1) lo = std::min(lo, px[i]), hi = std::max(hi, px[i]);
  }
  EXPECT_EQ(non_finite, 0u);
  EXPECT_GT(hi - lo, 0.2f) << "the picture is (nearly) constant";
}

INSTANTIATE_TEST_SUITE_P(Projects, ExampleProject, ::testing::ValuesIn(projects()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace rm::test
