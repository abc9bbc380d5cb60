// Check: validates the final source with glslang, in-process, before any GL
// call, and maps compiler logs (glslang's and the driver's) back to the
// user's files and lines.
#pragma once
#include <string>

#include "core/diagnostics.h"
#include "core/source.h"

namespace rm {

// Runs glslang's parser and semantic checks on source.text (fragment stage).
Diagnostics validate(const Source& source);

enum class LogFormat { Glslang, Mesa };
// Turns a compiler or linker log into diagnostics located in the user's files.
Diagnostics map_log(const std::string& log, const Source& source, LogFormat format);

}  // namespace rm
