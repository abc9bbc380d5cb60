// Probe: evaluates a GLSL expression at thousands of sample points in one
// draw into a float target and reads the results back. The points travel in
// an RGBA32F texture; fragment i reads point i (and an optional second input)
// and writes vec4 result i.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/data_paths.h"
#include "core/renderer.h"
#include "core/scene.h"
#include "support.h"

namespace rm::test {

class Probe {
 public:
  // `expression` may use `vec4 P` (the sample), `vec4 Q` (its second input,
  // zero unless given) and anything the `prelude`
  // (e.g. "#include <rm/sdf.glsl>") defines; it must give a vec4.
  // Returns nullptr (with *error) if the shader does not build.
  static std::unique_ptr<Probe> build(const std::string& prelude, const std::string& expression, std::string* error) {
    TempDir dir;
    write_file(dir / "probe.frag", "#version 450 core\n" + prelude +
                                       "\nuniform sampler2D points;\nuniform sampler2D extras;\nout vec4 result;\n"
                                       "void main() {\n  vec4 P = texelFetch(points, ivec2(gl_FragCoord.xy), 0);\n"
                                       "  vec4 Q = texelFetch(extras, ivec2(gl_FragCoord.xy), 0);\n"
                                       "  result = " + expression + ";\n}\n");
    SourceOptions options;
    options.shaderlib_dir = shaderlib_dir();
    auto scene = std::make_unique<Scene>(dir / "probe.frag", options);
    if (scene->reload() != ReloadStatus::Swapped) {
      *error = join(scene->diagnostics());
      return nullptr;
    }
    return std::unique_ptr<Probe>(new Probe(std::move(scene)));
  }

  std::vector<glm::vec4> run(const std::vector<glm::vec4>& points, const std::vector<glm::vec4>& extras = {}) {
    constexpr int kWidth = 256;
    const int count = static_cast<int>(points.size());
    const int height = std::max(1, (count + kWidth - 1) / kWidth);
    auto upload = [&](const std::vector<glm::vec4>& values, GLuint unit, const char* name) {
      std::vector<float> texels(static_cast<size_t>(kWidth) * height * 4, 0.0f);
      for (size_t i = 0; i < std::min(values.size(), points.size()); ++i)
        for (int c = 0; c < 4; ++c) texels[i * 4 + c] = values[i][c];
      gl::Texture texture = gl::make_texture(GL_TEXTURE_2D);
      glTextureStorage2D(texture.get(), 1, GL_RGBA32F, kWidth, height);
      glTextureSubImage2D(texture.get(), 0, 0, 0, kWidth, height, GL_RGBA, GL_FLOAT, texels.data());
      glBindTextureUnit(unit, texture.get());
      scene_->program()->set_sampler(name, static_cast<int>(unit));
      return texture;
    };
    const gl::Texture point_texture = upload(points, 0, "points");
    const gl::Texture extra_texture = upload(extras, 1, "extras");

    RenderTarget target(kWidth, height);
    target.bind();
    glUseProgram(scene_->program()->id());
    glViewport(0, 0, kWidth, height);
    gl::VertexArray vao = gl::make_vertex_array();
    glBindVertexArray(vao.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    const Image image = target.read().flipped();  // back to GL order: row 0 = points 0..255
    std::vector<glm::vec4> out(points.size());
    for (int i = 0; i < count; ++i) out[static_cast<size_t>(i)] = glm::make_vec4(&image.rgba[static_cast<size_t>(i) * 4]);
    return out;
  }

 private:
  explicit Probe(std::unique_ptr<Scene> scene) : scene_(std::move(scene)) {}
  std::unique_ptr<Scene> scene_;
};

// One-shot probe: build, run once. Returns nullopt (with *error) if the shader does not build.
inline std::optional<std::vector<glm::vec4>> probe(const std::string& prelude, const std::string& expression,
                                                   const std::vector<glm::vec4>& points, std::string* error,
                                                   const std::vector<glm::vec4>& extras = {}) {
  auto p = Probe::build(prelude, expression, error);
  if (!p) return std::nullopt;
  return p->run(points, extras);
}

}  // namespace rm::test
