// The supersample sequence that the window's --refine and render --samples
// share: sample 0 is the pixel centre, and any count covers the pixel evenly.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

#include "core/supersampling.h"

namespace rm {

TEST(Supersampling, SampleZeroIsThePixelCentreWithTheWholeWeight) {
  EXPECT_EQ(sample_offset(0), glm::vec2(0.0f));
  EXPECT_EQ(sample_weight(0), 1.0f);
  EXPECT_EQ(sample_weight(3), 0.25f);
}

TEST(Supersampling, OffsetsStayInsideThePixelAndNeverRepeat) {
  std::set<std::pair<float, float>> seen;
  for (int i = 0; i < kMaxSamples; ++i) {
    const glm::vec2 o = sample_offset(i);
    ASSERT_GE(o.x, -0.5f) << i;
    ASSERT_LT(o.x, 0.5f) << i;
    ASSERT_GE(o.y, -0.5f) << i;
    ASSERT_LT(o.y, 0.5f) << i;
    ASSERT_TRUE(seen.insert({o.x, o.y}).second) << i;
  }
}

// For every count, the share of samples in each quarter of the pixel is near
// a quarter: a refinement stopped early is still an even box filter.
TEST(Supersampling, EveryPrefixCoversThePixelEvenly) {
  for (int count : {4, 8, 16, 32, 64, 256}) {
    int quarters[2][2] = {{0, 0}, {0, 0}};
    glm::vec2 mean(0.0f);
    for (int i = 0; i < count; ++i) {
      const glm::vec2 o = sample_offset(i);
      ++quarters[o.x < 0.0f][o.y < 0.0f];
      mean += o / static_cast<float>(count);
    }
    for (auto& row : quarters)
      for (int n : row) EXPECT_NEAR(n, count / 4.0, count / 8.0 + 1.0) << count;
    EXPECT_LT(glm::length(mean), 0.6f / std::sqrt(static_cast<float>(count)) + 0.05f) << count;
  }
}

}  // namespace rm
