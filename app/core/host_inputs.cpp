#include "core/host_inputs.h"

#include <cmath>
#include <cstdio>

#include "core/program.h"
#include "core/supersampling.h"

namespace rm {

namespace {

// Shortest text that reads back as the same float; never "-0".
std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v == 0.0 ? 0.0 : v);
  return buf;
}

template <int N>
void set_vec(const Program& p, const char* name, const glm::vec<N, float>& v) {
  p.set(name, &v.x, N);
}

std::string record_mouse(const FrameInputs& in) {
  const glm::vec4& m = in.mouse;
  return number(m.x) + "," + number(m.y) + "," + number(m.z) + "," + number(m.w);
}

std::string record_date(const FrameInputs& in) { return date_text(in.date); }

}  // namespace

const std::vector<HostInput>& host_inputs() {
  using P = const Program&;
  using I = const FrameInputs&;
  static const std::vector<HostInput> table = {
      // Shadertoy's names.
      {"iResolution", "uniform vec3 iResolution;", Changes::Never,
       [](P p, const char* n, I in) { set_vec<3>(p, n, in.resolution); }, "", nullptr},
      {"iTime", "uniform float iTime;", Changes::Clock, [](P p, const char* n, I in) { p.set(n, in.time); },
       "--time", [](I in) { return number(in.time); }},
      {"iTimeDelta", "uniform float iTimeDelta;", Changes::Clock,
       [](P p, const char* n, I in) { p.set(n, in.time_delta); }, "", nullptr},
      {"iFrameRate", "uniform float iFrameRate;", Changes::Clock,
       [](P p, const char* n, I in) { p.set(n, in.frame_rate); }, "", nullptr},
      {"iFrame", "uniform int iFrame;", Changes::Clock,
       [](P p, const char* n, I in) { p.set(n, static_cast<float>(in.frame)); }, "--frame",
       [](I in) { return std::to_string(in.frame); }},
      {"iMouse", "uniform vec4 iMouse;", Changes::Drag, [](P p, const char* n, I in) { set_vec<4>(p, n, in.mouse); },
       "--mouse", record_mouse},
      {"iDate", "uniform vec4 iDate;", Changes::Clock, [](P p, const char* n, I in) { set_vec<4>(p, n, in.date); },
       "--date", record_date},
      {"iSampleRate", "uniform float iSampleRate;", Changes::Never,
       [](P p, const char* n, I in) { p.set(n, in.sample_rate); }, "", nullptr},
      {"iChannelTime", "uniform float iChannelTime[4];", Changes::Clock,
       [](P p, const char* n, I in) {
         for (int i = 0; i < 4; ++i) p.set_element(n, i, &in.time, 1);
       },
       "", nullptr},
      // What gl_FragCoord is moved by (core/source.cpp): where a tile starts,
      // for pictures drawn in tiles, plus a supersample's sub-pixel offset.
      {"rm_FragCoordOffset", "uniform vec2 rm_FragCoordOffset;", Changes::Never,
       [](P p, const char* n, I in) { set_vec<2>(p, n, in.frag_coord_offset + sample_offset(in.sample)); }, "",
       nullptr},
      // Which face a Cube A pass draws (0..5: +X, -X, +Y, -Y, +Z, -Z).
      {"rm_CubeFace", "uniform int rm_CubeFace;", Changes::Never,
       [](P p, const char* n, I in) { p.set(n, static_cast<float>(in.cube_face)); }, "", nullptr},
      // The picture's size in pixels, for glslViewer's v_texcoord (core/source.cpp).
      {"rm_Resolution", "", Changes::Never,
       [](P p, const char* n, I in) { set_vec<2>(p, n, glm::vec2(in.resolution)); }, "", nullptr},
      // glslViewer / Book of Shaders names.
      {"u_resolution", "", Changes::Never,
       [](P p, const char* n, I in) { set_vec<2>(p, n, glm::vec2(in.resolution)); }, "", nullptr},
      {"u_time", "", Changes::Clock, [](P p, const char* n, I in) { p.set(n, in.time); }, "", nullptr},
      {"u_delta", "", Changes::Clock, [](P p, const char* n, I in) { p.set(n, in.time_delta); }, "", nullptr},
      {"u_frame", "", Changes::Clock, [](P p, const char* n, I in) { p.set(n, static_cast<float>(in.frame)); }, "",
       nullptr},
      {"u_mouse", "", Changes::Pointer, [](P p, const char* n, I in) { set_vec<2>(p, n, in.cursor); }, "", nullptr},
      {"u_date", "", Changes::Clock, [](P p, const char* n, I in) { set_vec<4>(p, n, in.date); }, "", nullptr},
  };
  return table;
}

std::string host_input_declarations() {
  std::string out;
  for (const HostInput& input : host_inputs()) {
    if (input.declaration.empty()) continue;
    out += input.declaration;
    out += '\n';
  }
  return out;
}

void set_host_inputs(const Program& program, const FrameInputs& in) {
  for (const HostInput& input : host_inputs()) {
    const std::string name(input.name);
    if (program.uses(name)) input.set(program, name.c_str(), in);
  }
}

InputUse inputs_read(const Program& program) {
  InputUse use;
  for (const HostInput& input : host_inputs()) {
    if (!program.uses(std::string(input.name))) continue;
    use.time = use.time || input.changes == Changes::Clock;
    use.drag = use.drag || input.changes == Changes::Drag;
    use.pointer = use.pointer || input.changes == Changes::Pointer;
  }
  return use;
}

}  // namespace rm
