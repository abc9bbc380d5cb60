#include "core/views.h"

#include <algorithm>

namespace rm {

const char* to_string(View view) {
  switch (view) {
    case View::Picture: return "picture";
    case View::Steps: return "steps";
    case View::Normals: return "normals";
    case View::Depth: return "depth";
    case View::Nan: return "nan";
    case View::Data: return "data";
  }
  return "picture";
}

std::optional<View> view_from_string(const std::string& name) {
  for (View v : {View::Steps, View::Normals, View::Depth, View::Nan})
    if (name == to_string(v)) return v;
  return std::nullopt;
}

View next_view(View view) {
  switch (view) {
    case View::Picture: return View::Steps;
    case View::Steps: return View::Normals;
    case View::Normals: return View::Depth;
    case View::Depth: return View::Nan;
    default: return View::Picture;
  }
}

SourceOptions with_view(SourceOptions options, View view) {
  if (view == View::Picture) return options;
  options.defines.push_back({"RM_VIEW", std::to_string(static_cast<int>(view))});
  if (view == View::Steps || view == View::Data) options.defines.push_back({"RM_COUNT", ""});
  return options;
}

std::optional<std::string> view_problem(const Source& source, View view) {
  if (view == View::Picture) return std::nullopt;
  if (source.kind != ShaderKind::Shadertoy)
    return std::string("the ") + to_string(view) + " view needs a mainImage shader";
  if (view == View::Nan) return std::nullopt;
  const bool marches = std::any_of(source.files.begin(), source.files.end(), [](const fs::path& f) {
    return f.filename() == "march.glsl" && f.parent_path().filename() == "rm";
  });
  if (!marches)
    return std::string("the ") + to_string(view) + " view needs a scene that marches with shaderlib (rm/march.glsl)";
  return std::nullopt;
}

}  // namespace rm
