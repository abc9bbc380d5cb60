// A screenshot (F12) drawn in tiles between the window's own, a slice of the
// frame budget at a time, so that a shot of a heavy shader does not hold the
// window: keys, saves and Q are answered while it is drawn.
#pragma once
#include <filesystem>

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
  // The image pass of `inputs` at `size` (at most the renderer's largest
  // tile), in tiles of about tile_ms at per_pixel_ms (0: unknown, a probe
  // tile first), for `path` with `metadata`.
  TiledShot(const FrameInputs& inputs, glm::ivec2 size, double tile_ms, double per_pixel_ms,
            std::filesystem::path path, Metadata metadata);

  // Draws tiles for about slice_ms; true once the picture is whole.
  bool draw(FrameGraph& graph, const Project& project, double slice_ms);
  // A new program: the shot is drawn again from its first tile.
  void restart();

  Image read() const { return target_.read(); }
  const std::filesystem::path& path() const { return path_; }
  const Metadata& metadata() const { return metadata_; }
  int tiles() const { return tiles_; }  // drawn so far, since the last restart

 private:
  FrameInputs inputs_;
  glm::ivec2 size_;
  double tile_ms_;
  RenderTarget target_;
  TilePlan plan_;
  std::filesystem::path path_;
  Metadata metadata_;
  int tiles_ = 0;
};

}  // namespace rm
