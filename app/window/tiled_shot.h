// A screenshot (F12) drawn in tiles between the window's own, a slice of the
// frame budget at a time, so that a shot of a heavy shader does not hold the
// window: keys, saves and Q are answered while it is drawn. A shot larger
// than the renderer's largest target is drawn in parts of at most that
// size, each in tiles, and put together in memory. A shot of a size the
// window's buffers do not have draws the buffer passes anew first, into
// buffers of its own, in tiles too.
#pragma once
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "core/capture.h"
#include "core/frame_budget.h"
#include "core/frame_graph.h"
#include "core/inputs.h"
#include "core/project.h"
#include "core/renderer.h"

namespace rm {

class TiledShot {
 public:
  // The image pass of `inputs` at `size`, in parts of at most max_part
  // pixels a side, in tiles of about tile_ms at per_pixel_ms (0: unknown, the
  // smallest tile first), for `path` with `metadata`. With `own_buffers`,
  // after every buffer pass at `size` (FrameGraph::buffers_sized_for says
  // when the graph's will not do).
  TiledShot(const FrameInputs& inputs, glm::ivec2 size, int max_part, double tile_ms, double per_pixel_ms,
            std::filesystem::path path, Metadata metadata, bool own_buffers = false);

  // Draws tiles for about slice_ms; true once the picture is whole.
  // `finish` waits for each tile (glFinish where none is given).
  bool draw(FrameGraph& graph, const Project& project, double slice_ms, const std::function<void()>& finish = {});
  // A new program: the shot is drawn again from its first tile, with the
  // metadata that says what that program is.
  void restart(Metadata metadata);

  const Image& read() const { return whole_; }  // once draw() returned true
  const std::filesystem::path& path() const { return path_; }
  const Metadata& metadata() const { return metadata_; }
  const FrameInputs& inputs() const { return inputs_; }
  int tiles() const { return tiles_; }  // drawn so far, since the last restart

 private:
  void start_part(size_t index);  // its target and its tiles, from the first
  // One tile of the next buffer pass still to draw into buffers_; false
  // once they are all drawn.
  bool buffer_tile(FrameGraph& graph, const Project& project, const std::function<void()>& finish);

  FrameInputs inputs_;
  double tile_ms_;
  std::vector<glm::ivec4> parts_;  // x, y, width, height in GL's coordinates
  size_t part_ = 0;                // the one being drawn
  std::unique_ptr<RenderTarget> target_;  // the part's
  TilePlan plan_;                         // the part's tiles
  Image whole_;  // once drawn; a shot in parts is put together here
  std::filesystem::path path_;
  Metadata metadata_;
  int tiles_ = 0;
  std::unique_ptr<FrameGraph::BufferSet> buffers_;  // the shot's own, or none
  size_t next_buffer_ = 0;                          // the buffer pass being drawn
  std::optional<TilePlan> buffer_plan_;             // its tiles
};

}  // namespace rm
