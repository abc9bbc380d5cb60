#include "window/tiled_shot.h"

#include <chrono>
#include <utility>

namespace rm {

TiledShot::TiledShot(const FrameInputs& inputs, glm::ivec2 size, double tile_ms, double per_pixel_ms,
                     std::filesystem::path path, Metadata metadata)
    : inputs_(inputs),
      size_(size),
      tile_ms_(tile_ms),
      target_(size.x, size.y),
      plan_(size, tile_ms, per_pixel_ms),
      path_(std::move(path)),
      metadata_(std::move(metadata)) {}

bool TiledShot::draw(FrameGraph& graph, const Project& project, double slice_ms) {
  using Clock = std::chrono::steady_clock;
  const auto slice_start = Clock::now();
  auto ms_since = [](Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); };
  while (!plan_.done()) {
    const glm::ivec4 tile = plan_.next();
    const auto start = Clock::now();
    graph.draw_image(project, inputs_, size_, target_.framebuffer(), tile);
    glFinish();  // the tile is done: the window reads input before the next
    plan_.drawn(tile, ms_since(start));
    ++tiles_;
    if (ms_since(slice_start) >= slice_ms) break;
  }
  return plan_.done();
}

void TiledShot::restart() {
  plan_ = TilePlan(size_, tile_ms_, plan_.per_pixel_ms());
  tiles_ = 0;
}

}  // namespace rm
