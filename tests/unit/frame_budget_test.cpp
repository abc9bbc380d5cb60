// The frame budget's two decisions, fed synthetic draw times: the scale of a
// changing picture converges, holds and does not oscillate; tiles cover the
// picture once and take about the time asked.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "core/frame_budget.h"

namespace rm {
namespace {

constexpr double kBudget = 1000.0 / 30.0;

// A deterministic wobble of +-`amount` around 1, like a busy machine's.
struct Noise {
  double amount;
  unsigned state = 12345;
  double operator()() {
    state = state * 1103515245u + 12345u;
    return 1.0 + amount * (((state >> 8) % 2001) / 1000.0 - 1.0);
  }
};

// Runs `frames` frames of a scene whose frame at scale s takes cost(s);
// returns the scale each frame was drawn at.
std::vector<double> run(ScaleController& c, int frames, const std::function<double(double)>& cost) {
  std::vector<double> scales;
  for (int i = 0; i < frames; ++i) {
    const double s = c.scale();
    scales.push_back(s);
    c.measured(s, cost(s));
  }
  return scales;
}

int changes(const std::vector<double>& scales, size_t from = 0) {
  int n = 0;
  for (size_t i = from + 1; i < scales.size(); ++i) n += scales[i] != scales[i - 1];
  return n;
}

TEST(ScaleController, AHeavySceneConvergesWithinAFewFramesAndHolds) {
  ScaleController c(kBudget);
  Noise noise{0.1};
  const auto scales = run(c, 200, [&](double s) { return 240.0 * s * s * noise(); });
  // 240 ms at full size: the budget holds from the third frame on.
  for (size_t i = 2; i < scales.size(); ++i) EXPECT_LE(240.0 * scales[i] * scales[i], kBudget) << "frame " << i;
  EXPECT_LE(changes(scales, 2), 0) << "the scale moved after it had converged";
  // And it is not needlessly small: the next step up would be over the budget's raise line.
  const double s = scales.back();
  EXPECT_GT(240.0 * std::pow(s * std::pow(2.0, 0.125), 2), ScaleController::kRaiseAt * kBudget);
}

TEST(ScaleController, ACheapSceneStaysAtFullSize) {
  ScaleController c(kBudget);
  Noise noise{0.2};
  const auto scales = run(c, 100, [&](double s) { return 12.0 * s * s * noise(); });
  for (double s : scales) EXPECT_EQ(s, 1.0);
}

TEST(ScaleController, OneSlowFrameDoesNotMoveIt) {
  ScaleController c(kBudget);
  int frame = 0;
  const auto scales = run(c, 60, [&](double s) { return (++frame == 30 ? 400.0 : 20.0) * s * s; });
  for (double s : scales) EXPECT_EQ(s, 1.0);
}

TEST(ScaleController, FollowsACostThatChangesBothWays) {
  ScaleController c(kBudget);
  double full = 20.0;
  run(c, 20, [&](double s) { return full * s * s; });
  EXPECT_EQ(c.scale(), 1.0);
  full = 800.0;  // a heavier shader after a reload
  auto scales = run(c, 30, [&](double s) { return full * s * s; });
  for (size_t i = 3; i < scales.size(); ++i) EXPECT_LE(full * scales[i] * scales[i], kBudget) << "frame " << i;
  full = 20.0;  // and a light one again
  scales = run(c, 30, [&](double s) { return full * s * s; });
  EXPECT_EQ(scales.back(), 1.0);
  for (size_t i = 0; i < scales.size() && scales[i] != 1.0; ++i) EXPECT_LT(i, 8u) << "too slow to come back up";
}

TEST(ScaleController, DoesNotOscillateOnTheEdgeOfAStep) {
  // For every cost between 40 and 400 ms, with 15% noise: after settling,
  // the scale moves at most once in 300 frames.
  for (double full = 40.0; full <= 400.0; full *= 1.07) {
    ScaleController c(kBudget);
    Noise noise{0.15};
    const auto scales = run(c, 300, [&](double s) { return full * s * s * noise(); });
    EXPECT_LE(changes(scales, 10), 1) << "full-size cost " << full << " ms";
  }
}

TEST(ScaleController, AFixedCostThatNoScaleRemovesEndsAtTheLowestStep) {
  ScaleController c(kBudget);
  const auto scales = run(c, 40, [&](double s) { return 60.0 + 100.0 * s * s; });
  EXPECT_EQ(scales.back(), 0.125);
  EXPECT_GT(c.predict_ms(0.125), kBudget) << "the window must then draw in tiles";
}

// The present and the events cost 8 ms a frame whatever the scale: drawing
// and that overhead together hold the budget, where drawing alone at the
// step it would pick without the overhead would not leave room for it.
TEST(ScaleController, TheFrameOverheadCountsAgainstTheBudget) {
  constexpr double kOverhead = 8.0;
  ScaleController c(kBudget), blind(kBudget);
  Noise noise{0.1};
  std::vector<double> scales;
  for (int i = 0; i < 100; ++i) {
    const double s = c.scale();
    scales.push_back(s);
    c.measured(s, 240.0 * s * s * noise(), kOverhead * noise());
    blind.measured(blind.scale(), 240.0 * blind.scale() * blind.scale());
  }
  for (size_t i = 3; i < scales.size(); ++i)
    EXPECT_LE(240.0 * scales[i] * scales[i] + kOverhead, kBudget) << "frame " << i;
  EXPECT_LE(changes(scales, 3), 0);
  EXPECT_GT(240.0 * blind.scale() * blind.scale() + kOverhead, ScaleController::kHoldAt * kBudget)
      << "without the overhead the same scene would be drawn larger";
  EXPECT_NEAR(c.overhead_ms(), kOverhead, kOverhead * 0.1);
}

TEST(ScaleController, ForgetStartsAgainFromTheNextFrame) {
  ScaleController c(kBudget);
  run(c, 10, [](double s) { return 500.0 * s * s; });
  c.forget();
  EXPECT_EQ(c.full_frame_ms(), 0.0);
  c.measured(c.scale(), 1.0);
  EXPECT_NEAR(c.full_frame_ms(), 1.0 / (c.scale() * c.scale()), 1e-9);
}

// A window made larger costs more at once: the scale drops before its first
// frame at the new size, as far as the pixels say, and that frame fits; made
// smaller again, the scale comes back up at once. (Before, the first frames
// after 320x180 became 1900x1000 were drawn at full size: 270 ms each.)
TEST(ScaleController, AResizedWindowIsScaledAtOnceByItsPixels) {
  ScaleController c(kBudget);
  double pixels = 320.0 * 180;
  c.resized(pixels);
  auto cost = [&](double s) { return 8.5 * (pixels / (320.0 * 180)) * s * s; };
  run(c, 10, cost);
  EXPECT_EQ(c.scale(), 1.0);
  pixels = 1900.0 * 1000;
  c.resized(pixels);
  EXPECT_NEAR(c.full_frame_ms(), cost(1.0), 1e-6);
  EXPECT_LE(cost(c.scale()), ScaleController::kHoldAt * kBudget);
  EXPECT_LT(c.scale(), 0.4);
  const double scale_large = c.scale();
  run(c, 10, cost);
  EXPECT_EQ(c.scale(), scale_large) << "the scale chosen at the resize was the one the frames hold";
  pixels = 320.0 * 180;
  c.resized(pixels);
  EXPECT_EQ(c.scale(), 1.0);
  c.resized(0);  // a minimised window: nothing to scale
  EXPECT_EQ(c.scale(), 1.0);
  EXPECT_NEAR(c.full_frame_ms(), 8.5, 1e-6);
}

// A window a few pixels small draws in what any draw costs, whatever its
// pixels: scaled up with them, that made a light scene look thousands of
// times heavier. (1x1 grown to 6000x4000: tori's first picture took 2250
// tiles, and an F12 right after was not done in 25 s.) The estimates start
// over from the lowest step, as a new program's do.
TEST(ScaleController, AWindowGrownFromAFewPixelsMeasuresAgainFromTheLowestStep) {
  ScaleController c(kBudget);
  c.resized(1);
  run(c, 10, [](double) { return 0.2; });
  EXPECT_EQ(c.scale(), 1.0);
  c.resized(6000.0 * 4000);
  EXPECT_EQ(c.full_frame_ms(), 0.0) << "no estimate is scaled up from one pixel";
  EXPECT_EQ(c.scale(), ScaleController::scale_of(ScaleController::kSteps - 1));
  auto cost = [](double s) { return 0.2 + 600.0 * s * s; };  // a light scene, 6000x4000
  const std::vector<double> scales = run(c, 10, cost);
  EXPECT_GT(scales.back(), ScaleController::scale_of(ScaleController::kSteps - 1)) << "it climbed";
  EXPECT_LE(cost(scales.back()), ScaleController::kHoldAt * kBudget);
  // From a window large enough, the estimates grow with the pixels, as before.
  const double measured = c.full_frame_ms();
  c.resized(6000.0 * 4500);
  EXPECT_NEAR(c.full_frame_ms(), 1.125 * measured, 1e-6);
}

// Every pixel in exactly one tile.
void expect_covers_once(glm::ivec2 size, const std::vector<glm::ivec4>& tiles) {
  std::vector<int> hits(static_cast<size_t>(size.x) * size.y, 0);
  for (const glm::ivec4& t : tiles) {
    ASSERT_GE(t.x, 0);
    ASSERT_GE(t.y, 0);
    ASSERT_GT(t.z, 0);
    ASSERT_GT(t.w, 0);
    ASSERT_LE(t.x + t.z, size.x);
    ASSERT_LE(t.y + t.w, size.y);
    for (int y = t.y; y < t.y + t.w; ++y)
      for (int x = t.x; x < t.x + t.z; ++x) ++hits[static_cast<size_t>(y) * size.x + x];
  }
  for (size_t i = 0; i < hits.size(); ++i) ASSERT_EQ(hits[i], 1) << "pixel " << i % size.x << "," << i / size.x;
}

// Draws a whole plan where pixel (x, y) costs per_pixel(x, y) ms, and each
// draw per_draw ms besides.
std::vector<glm::ivec4> draw_all(TilePlan& plan, const std::function<double(int, int)>& per_pixel,
                                 std::vector<double>* times = nullptr, double per_draw = 0) {
  std::vector<glm::ivec4> tiles;
  while (!plan.done() && tiles.size() < 100000) {
    const glm::ivec4 t = plan.next();
    double ms = per_draw;
    for (int y = t.y; y < t.y + t.w; ++y)
      for (int x = t.x; x < t.x + t.z; ++x) ms += per_pixel(x, y);
    plan.drawn(t, ms);
    tiles.push_back(t);
    if (times) times->push_back(ms);
  }
  return tiles;
}

TEST(TilePlan, AnUnknownCostStartsWithTheSmallestTileAtTheTop) {
  TilePlan plan({160, 90}, 30.0);
  EXPECT_EQ(plan.next(), glm::ivec4(0, 90 - TilePlan::kSmallest, TilePlan::kSmallest, TilePlan::kSmallest));
}

TEST(TilePlan, TilesCoverThePictureOnceWhateverTheCost) {
  for (glm::ivec2 size : {glm::ivec2(160, 90), glm::ivec2(7, 5), glm::ivec2(1280, 720), glm::ivec2(33, 17)}) {
    for (double cost : {1e-6, 1e-3, 0.05, 3.0}) {
      TilePlan plan(size, 30.0);
      expect_covers_once(size, draw_all(plan, [&](int, int) { return cost; }));
    }
  }
  // A cost that varies across the picture: cheap sky above, a heavy object below.
  TilePlan plan({320, 180}, 30.0);
  expect_covers_once({320, 180}, draw_all(plan, [](int x, int y) { return y > 90 ? 1e-4 : (x > 100 ? 0.5 : 0.01); }));
}

TEST(TilePlan, KnownCostTilesTakeAboutTheTimeAsked) {
  TilePlan plan({640, 360}, 30.0);
  std::vector<double> times;
  draw_all(plan, [](int, int) { return 0.002; }, &times);  // 460 ms a picture
  ASSERT_GT(times.size(), 10u);
  for (size_t i = 1; i + 1 < times.size(); ++i) EXPECT_LE(times[i], 31.0) << "tile " << i;
  EXPECT_NEAR(plan.drawn_ms(), 640 * 360 * 0.002, 1e-6);
}

// Cheap sky above a heavy object: the sky's tiles must not carry the object.
double heavy_below(int, int y) { return y > 180 ? 1e-6 : 0.01; }

TEST(TilePlan, WithTheAverageKnownAHeavyTileTakesAtMostTwiceTheTime) {
  TilePlan plan({640, 360}, 30.0, (1e-6 + 0.01) / 2);  // the last frame's average
  std::vector<double> times;
  draw_all(plan, heavy_below, &times);
  for (size_t i = 0; i < times.size(); ++i) EXPECT_LE(times[i], 2 * 30.0 + 1e-9) << "tile " << i;
}

TEST(TilePlan, WithTheCostUnknownTilesGrowAtMostTwofoldAndComeBackWithinTime) {
  TilePlan plan({640, 360}, 30.0);
  std::vector<double> times;
  const auto tiles = draw_all(plan, heavy_below, &times);
  size_t first_over = times.size();
  // Twice the last tile the plan sized (a band's last part is what was left
  // of the band), or a probe, at most.
  int last_sized = 0;
  for (size_t i = 0; i < times.size(); ++i) {
    const int pixels = tiles[i].z * tiles[i].w;
    if (i > 0) EXPECT_LE(pixels, 2 * std::max(last_sized, 256)) << "tile " << i;
    const bool rest_of_band = tiles[i].x > 0 && tiles[i].x + tiles[i].z == 640;
    last_sized = rest_of_band ? std::max(last_sized, pixels) : pixels;
    if (times[i] > 31.0 && first_over == times.size()) first_over = i;
  }
  ASSERT_LT(first_over + 1, times.size());
  for (size_t i = first_over + 2; i + 1 < times.size(); ++i) EXPECT_LE(times[i], 31.0) << "tile " << i;
}

// A reload's first picture of cubes in the window, as -v logged it: 476x268,
// 20 ms in all, and about 0.15 ms a draw besides. A band's rest 4 pixels
// wide, drawn alone, measured mostly its draw and sent the next tile back to
// a probe, band after band: 61 tiles.
TEST(TilePlan, NoSliverIsLeftOfABandAndTheTilesKeepGrowing) {
  TilePlan plan({476, 268}, 33.3);
  const auto tiles = draw_all(plan, [](int, int) { return 1.54e-4; }, nullptr, 0.15);
  expect_covers_once({476, 268}, tiles);
  for (const glm::ivec4& t : tiles) EXPECT_GE(t.z, t.w) << t.x << "," << t.y << " " << t.z << "x" << t.w;
  EXPECT_LE(tiles.size(), 12u);
}

// A shader too heavy for a probe in a tile's time: its tiles shrink to the
// time, down to the smallest, and a band's rest is not drawn with a tile
// when both would overrun it. A 16x16 probe of such a shader held the window
// for as long as 16 of the smallest tiles, and a band's rest drawn with one
// for up to twice that.
TEST(TilePlan, AShaderTooHeavyForAProbeIsDrawnInTilesOfTheTimeDownToTheSmallest) {
  for (glm::ivec2 size : {glm::ivec2(100, 40), glm::ivec2(160, 90), glm::ivec2(47, 21)}) {
    for (double cost : {0.5, 5.0}) {  // 128 and 1280 ms a probe
      TilePlan plan(size, 33.3);
      std::vector<double> times;
      const auto tiles = draw_all(plan, [&](int, int) { return cost; }, &times);
      expect_covers_once(size, tiles);
      const double smallest_ms = cost * TilePlan::kSmallest * TilePlan::kSmallest;
      for (size_t i = 0; i < tiles.size(); ++i)
        EXPECT_LE(times[i], std::max(33.3, smallest_ms)) << size.x << "x" << size.y << " at " << cost << ": "
                                                          << tiles[i].x << "," << tiles[i].y << " " << tiles[i].z
                                                          << "x" << tiles[i].w;
    }
  }
}

TEST(TilePlan, APictureCheaperThanOneTileIsOneTileOnceItsCostIsKnown) {
  TilePlan plan({160, 90}, 30.0, 1e-5);
  EXPECT_EQ(plan.next(), glm::ivec4(0, 0, 160, 90));
}

}  // namespace
}  // namespace rm
