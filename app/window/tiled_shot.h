// A screenshot (F12) drawn in tiles between the window's own, a slice of the
// frame budget at a time, so that a shot of a heavy shader does not hold the
// window: keys, saves and Q are answered while it is drawn. A shot larger
// than the renderer's largest target is drawn in parts of at most that
// size, each in tiles, and put together in memory.
#pragma once
#include <filesystem>
#include <functional>
#include <memory>
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
  // smallest tile first), for `path` with `metadata`.
  TiledShot(const FrameInputs& inputs, glm::ivec2 size, int max_part, double tile_ms, double per_pixel_ms,
            std::filesystem::path path, Metadata metadata);

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
};

}  // namespace rm
