// The one table of what the host hands every shader. Each row is a uniform:
// its GLSL declaration, how a frame sets it, what makes it change, and how a
// screenshot records it. The Shadertoy prelude, the renderer, inputs_read()
// and the capture metadata all read this table, so a new input is one row.
// The channel uniforms (iChannelN, iChannelResolution) belong to a pass's
// bindings instead: core/passes.h declares and sets them.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "core/inputs.h"

namespace rm {

class Program;

// What makes an input's value change between frames.
enum class Changes {
  Never,    // fixed for a run (iSampleRate) or per picture (iResolution)
  Clock,    // the shader clock or the wall clock: an animated picture
  Drag,     // the left-button drag (Shadertoy's iMouse)
  Pointer,  // the pointer, button or not (glslViewer's u_mouse)
};

struct HostInput {
  std::string_view name;
  std::string_view declaration;  // in the Shadertoy prelude; empty for glslViewer names, which shaders declare
  Changes changes;
  void (*set)(const Program& program, const char* name, const FrameInputs& in);
  // The `render` option that reproduces the value in a screenshot, and the
  // value as that option reads it; empty: not recorded.
  std::string_view render_option;
  std::string (*record)(const FrameInputs& in);
};

const std::vector<HostInput>& host_inputs();

// The prelude's uniform declarations, one per line, in table order.
std::string host_input_declarations();

// Sets every host input the program reads.
void set_host_inputs(const Program& program, const FrameInputs& in);

// What can change a program's picture, read from its active uniforms: a
// shader that reads no clock draws the same picture until an input it reads
// changes, so the window need not draw it again.
struct InputUse {
  bool time = false;     // any Changes::Clock input
  bool drag = false;     // any Changes::Drag input: changes while the left button is held, and on press and release
  bool pointer = false;  // any Changes::Pointer input
};
InputUse inputs_read(const Program& program);

}  // namespace rm
