// Views: the debug views of `render --view` and the window's V key. A view is
// the scene compiled with RM_VIEW (shaderlib's rm/views.glsl and the
// Shadertoy wrapper do the drawing); this module names them, sets the
// defines, and says when a scene cannot show one.
#pragma once
#include <optional>
#include <string>

#include "core/source.h"

namespace rm {

// The numbers match RM_VIEW_* in shaderlib/rm/views.glsl.
enum class View { Picture = 0, Steps = 1, Normals = 2, Depth = 3, Nan = 4, Data = 5 };

const char* to_string(View view);
std::optional<View> view_from_string(const std::string& name);  // "steps", "normals", "depth", "nan"
View next_view(View view);  // the V key's cycle: picture, steps, normals, depth, nan, picture

// `options` with the defines that compile `view` in (none for Picture).
SourceOptions with_view(SourceOptions options, View view);

// Why `source` cannot show `view`, or nullopt if it can: every view needs a
// mainImage shader, and all but nan a scene that marches with shaderlib.
std::optional<std::string> view_problem(const Source& source, View view);

}  // namespace rm
