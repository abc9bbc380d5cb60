#include "window/tiled_shot.h"

#include <algorithm>
#include <chrono>
#include <utility>

namespace rm {

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// The next tile of `plan`, drawn by draw(tile) and waited for (the window
// reads input before the next), its time told to the plan.
template <typename Draw>
void draw_tile(TilePlan& plan, const std::function<void()>& finish, Draw draw) {
  const glm::ivec4 tile = plan.next();
  const auto start = Clock::now();
  draw(tile);
  if (finish) finish();
  else glFinish();
  plan.drawn(tile, ms_since(start));
}

}  // namespace

TiledShot::TiledShot(const FrameInputs& inputs, glm::ivec2 size, int max_part, double tile_ms, double per_pixel_ms,
                     std::filesystem::path path, Metadata metadata, bool own_buffers)
    : inputs_(inputs),
      tile_ms_(tile_ms),
      plan_(size, tile_ms, per_pixel_ms),
      path_(std::move(path)),
      metadata_(std::move(metadata)),
      buffers_(own_buffers ? std::make_unique<FrameGraph::BufferSet>() : nullptr) {
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
  const auto slice_start = Clock::now();
  // The shot's own buffers stand in for the graph's while it draws, and
  // only then: the window draws between slices.
  struct SwappedIn {
    FrameGraph& graph;
    FrameGraph::BufferSet* set;
    ~SwappedIn() {
      if (set) graph.swap_buffers(*set);
    }
  } swapped{graph, buffers_.get()};
  if (buffers_) graph.swap_buffers(*buffers_);
  while (buffers_ && buffer_tile(graph, project, finish)) {
    if (ms_since(slice_start) >= slice_ms) return false;
  }
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
    draw_tile(plan_, finish, [&](glm::ivec4 tile) {
      FrameInputs in = inputs_;
      in.frag_coord_offset = glm::vec2(part.x, part.y);  // gl_FragCoord is the whole shot's
      graph.draw_image(project, in, glm::ivec2(part.z, part.w), target_->framebuffer(), tile);
    });
    ++tiles_;
    if (ms_since(slice_start) >= slice_ms) break;
  }
  return part_ == parts_.size();
}

bool TiledShot::buffer_tile(FrameGraph& graph, const Project& project, const std::function<void()>& finish) {
  const glm::ivec2 size(inputs_.resolution);
  while (next_buffer_ + 1 < project.passes().size()) {
    if (!buffer_plan_) {
      if (!graph.begin_pass(project, next_buffer_, size)) {  // static, and drawn for this shot
        ++next_buffer_;
        continue;
      }
      buffer_plan_.emplace(graph.pass_size(project, next_buffer_, size), tile_ms_);
    }
    draw_tile(*buffer_plan_, finish,
              [&](glm::ivec4 tile) { graph.draw_pass_region(project, next_buffer_, inputs_, tile); });
    ++tiles_;
    if (buffer_plan_->done()) {
      graph.end_pass(project, next_buffer_);
      buffer_plan_.reset();
      ++next_buffer_;
    }
    return true;
  }
  return false;
}

void TiledShot::restart(Metadata metadata) {
  metadata_ = std::move(metadata);
  start_part(0);
  tiles_ = 0;
  next_buffer_ = 0;  // a new program's buffers are drawn again (a static one of the same program is kept)
  buffer_plan_.reset();
}

}  // namespace rm
