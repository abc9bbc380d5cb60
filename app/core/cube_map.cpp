#include "core/cube_map.h"

#include <algorithm>
#include <cmath>

#include "core/channels.h"
#include "core/files.h"

namespace rm {

namespace {

Image crop(const Image& from, int x0, int y0, int size) {
  Image face;
  face.width = face.height = size;
  face.rgba.resize(static_cast<size_t>(size) * size * 4);
  for (int y = 0; y < size; ++y)
    std::copy_n(from.pixel(x0, y0 + y), static_cast<size_t>(size) * 4, &face.rgba[static_cast<size_t>(y) * size * 4]);
  return face;
}

// Bilinear, wrapping around in x and clamped in y, at pixel-centre coordinates.
glm::vec4 sample_panorama(const Image& p, float u, float v) {
  const float x = u * static_cast<float>(p.width) - 0.5f, y = v * static_cast<float>(p.height) - 0.5f;
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
  auto at = [&](int xi, int yi) {
    xi = ((xi % p.width) + p.width) % p.width;
    yi = std::clamp(yi, 0, p.height - 1);
    const float* px = p.pixel(xi, yi);
    return glm::vec4(px[0], px[1], px[2], px[3]);
  };
  return glm::mix(glm::mix(at(x0, y0), at(x0 + 1, y0), fx), glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), fx), fy);
}

}  // namespace

glm::vec3 cube_direction(int face, glm::vec2 st) {
  switch (face) {
    case 0: return {1.0f, -st.y, -st.x};
    case 1: return {-1.0f, -st.y, st.x};
    case 2: return {st.x, 1.0f, st.y};
    case 3: return {st.x, -1.0f, -st.y};
    case 4: return {st.x, -st.y, 1.0f};
    default: return {-st.x, -st.y, -1.0f};
  }
}

std::optional<CubeFaces> cube_from_cross(const Image& cross, std::string* error) {
  if (cross.width * 3 != cross.height * 4 || cross.width % 4 != 0) {
    *error = "a cross is 4:3 with square faces; this is " + std::to_string(cross.width) + "x" +
             std::to_string(cross.height);
    return std::nullopt;
  }
  const int n = cross.width / 4;
  // Where each face sits in the cross, in cells.
  const glm::ivec2 cell[6] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}};
  CubeFaces cube;
  cube.size = n;
  for (int f = 0; f < 6; ++f) cube.faces[static_cast<size_t>(f)] = crop(cross, cell[f].x * n, cell[f].y * n, n);
  return cube;
}

CubeFaces cube_from_panorama(const Image& panorama) {
  constexpr float kPi = 3.14159265358979f;
  CubeFaces cube;
  cube.size = std::max(1, panorama.height / 2);
  const int n = cube.size;
  for (int f = 0; f < 6; ++f) {
    Image& face = cube.faces[static_cast<size_t>(f)];
    face.width = face.height = n;
    face.rgba.resize(static_cast<size_t>(n) * n * 4);
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const glm::vec2 st = (glm::vec2(x, y) + 0.5f) / static_cast<float>(n) * 2.0f - 1.0f;
        const glm::vec3 d = glm::normalize(cube_direction(f, st));
        const float u = 0.5f + std::atan2(d.x, -d.z) / (2.0f * kPi);
        const float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi;
        const glm::vec4 c = sample_panorama(panorama, u, v);
        std::copy_n(&c.x, 4, &face.rgba[(static_cast<size_t>(y) * n + x) * 4]);
      }
    }
  }
  return cube;
}

std::optional<CubeFaces> cube_from_faces(std::array<Image, 6> faces, std::string* error) {
  CubeFaces cube;
  cube.size = faces[0].width;
  for (int f = 0; f < 6; ++f) {
    const Image& face = faces[static_cast<size_t>(f)];
    if (face.width != face.height || face.width != cube.size) {
      *error = "face " + std::to_string(f) + " is " + std::to_string(face.width) + "x" + std::to_string(face.height) +
               "; the six faces must be square and of one size (" + std::to_string(cube.size) + ")";
      return std::nullopt;
    }
  }
  cube.faces = std::move(faces);
  return cube;
}

std::optional<CubeFaces> load_cube_map(const std::filesystem::path& path, std::string* error) {
  const std::vector<std::filesystem::path> files = cube_face_files(path, exists_on_disk);
  if (files.size() == 6) {
    std::array<Image, 6> faces;
    for (size_t f = 0; f < 6; ++f) {
      std::string why;
      auto face = load_channel_image(files[f], &why);
      if (!face) {
        *error = "face '" + files[f].filename().string() + "': " + why;
        return std::nullopt;
      }
      faces[f] = std::move(*face);
    }
    return cube_from_faces(std::move(faces), error);
  }
  if (!files.empty()) {
    *error = "has " + std::to_string(files.size()) + " of the six face files (NAME.ext, NAME_1.ext .. NAME_5.ext)";
    return std::nullopt;
  }
  auto image = load_channel_image(path, error);
  if (!image) return std::nullopt;
  if (image->width * 3 == image->height * 4) return cube_from_cross(*image, error);
  if (image->width == image->height * 2) return cube_from_panorama(*image);
  *error = "is " + std::to_string(image->width) + "x" + std::to_string(image->height) +
           "; a cube map is six face files (NAME.ext, NAME_1.ext .. NAME_5.ext), a 4:3 cross or a 2:1 panorama";
  return std::nullopt;
}

}  // namespace rm
