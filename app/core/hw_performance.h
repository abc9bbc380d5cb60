// Shadertoy's HW_PERFORMANCE for the window's renderer. Shaders choose
// their cost by it: Happy Jumping draws 2x2 samples a pixel at 1 and one at
// 0. Shadertoy gives a desktop 1 and a phone 0. A renderer on the CPU such
// as llvmpipe draws more slowly than a phone's GPU, so the window there
// gives 0; its own supersampling still refines a picture at rest. `render`
// keeps 1 (core/source.cpp) on any machine: frames of a sequence split
// across machines must match, and an offline picture may take its time.
#pragma once

#include <string>
#include <string_view>

#include "core/source.h"

namespace rm {

// Whether GL_RENDERER names a renderer that runs on the CPU.
bool is_software_renderer(std::string_view gl_renderer);

// `options` with -D HW_PERFORMANCE=0 for a software renderer, unless a -D
// sets it already. A -D rather than a hidden default, so that the command
// line a screenshot or a take records gives the same picture on any machine.
SourceOptions for_renderer(SourceOptions options, std::string_view gl_renderer);

// GL_RENDERER of the current context.
std::string current_renderer();

}  // namespace rm
