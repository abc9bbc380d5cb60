#include "window/tiled_shot.h"

#include <algorithm>
#include <chrono>
#include <utility>

namespace rm {

TiledShot::TiledShot(const FrameInputs& inputs, glm::ivec2 size, int max_part, double tile_ms, double per_pixel_ms,
                     std::filesystem::path path, Metadata metadata)
    : inputs_(inputs),
      tile_ms_(tile_ms),
      plan_(size, tile_ms, per_pixel_ms),
      path_(std::move(path)),
      metadata_(std::move(metadata)) {
  inputs_.resolution = glm::vec3(size, 1.0f);
  for (int y = 0; y < size.y; y += max_part)
    for (int x = 0; x < size.x; x += max_part)
      parts_.emplace_back(x, y, std::min(max_part, size.x - x), std::min(max_part, size.y - y));
  start_part(0);
}

void TiledShot::start_part(size_t index) {
  part_ = index;
  const glm::ivec4 part = parts_[index];
  if (!target_ || target_->width() != part.z || target_->height() != part.w)
    target_ = std::make_unique<RenderTarget>(part.z, part.w);
  plan_ = TilePlan(glm::ivec2(part.z, part.w), tile_ms_, plan_.per_pixel_ms());
}

bool TiledShot::draw(FrameGraph& graph, const Project& project, double slice_ms, const std::function<void()>& finish) {
  using Clock = std::chrono::steady_clock;
  const auto slice_start = Clock::now();
  auto ms_since = [](Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); };
  while (part_ < parts_.size()) {
    const glm::ivec4 part = parts_[part_];
    if (plan_.done()) {  // the part is whole: into the picture, and on to the next
      if (parts_.size() == 1) {
        whole_ = target_->read();  // the picture itself: no second copy of it
      } else {
        const glm::ivec2 size(inputs_.resolution);
        if (whole_.rgba.empty()) whole_ = Image{size.x, size.y, std::vector<float>(static_cast<size_t>(size.x) * size.y * 4)};
        paste(whole_, target_->read(), part.x, part.y);
      }
      if (part_ + 1 == parts_.size()) {
        part_ = parts_.size();
        break;
      }
      start_part(part_ + 1);
      continue;
    }
    const glm::ivec4 tile = plan_.next();
    FrameInputs in = inputs_;
    in.frag_coord_offset = glm::vec2(part.x, part.y);  // gl_FragCoord is the whole shot's
    const auto start = Clock::now();
    graph.draw_image(project, in, glm::ivec2(part.z, part.w), target_->framebuffer(), tile);
    if (finish) finish();  // the tile is done: the window reads input before the next
    else glFinish();
    plan_.drawn(tile, ms_since(start));
    ++tiles_;
    if (ms_since(slice_start) >= slice_ms) break;
  }
  return part_ == parts_.size();
}

void TiledShot::restart(Metadata metadata) {
  metadata_ = std::move(metadata);
  start_part(0);
  tiles_ = 0;
}

}  // namespace rm
