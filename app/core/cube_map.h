// Cube maps on the CPU: the six faces a samplerCube channel reads, made from
// the three layouts people have (six files, a cross, a panorama), and the
// direction each face texel looks along. No GL here: core/channels.h uploads.
//
// Faces are in GL's order (+X, -X, +Y, -Y, +Z, -Z) and GL's layout: a face's
// first row is its top, as an image file stores it, so the files upload
// unflipped. Shadertoy uses the same layout.
#pragma once
#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "core/channel_spec.h"
#include "core/image.h"

namespace rm {

struct CubeFaces {
  int size = 0;                // pixels a side
  std::array<Image, 6> faces;  // +X, -X, +Y, -Y, +Z, -Z
};

// The direction that samples face `face` at `st` (-1..1 across the face,
// s to the right, t down the rows). Unnormalised.
glm::vec3 cube_direction(int face, glm::vec2 st);

// A horizontal cross, 4:3:          +Y
//                               -X  +Z  +X  -Z
//                                   -Y
std::optional<CubeFaces> cube_from_cross(const Image& cross, std::string* error);
// An equirectangular panorama, 2:1: the middle column looks along -Z, the
// top row straight up. Faces are half the panorama's height, bilinearly sampled.
CubeFaces cube_from_panorama(const Image& panorama);
// Six square images of one size, in face order.
std::optional<CubeFaces> cube_from_faces(std::array<Image, 6> faces, std::string* error);

// Reads a cube map file (or its six face files) in whichever layout it has.
std::optional<CubeFaces> load_cube_map(const std::filesystem::path& path, std::string* error);

}  // namespace rm
