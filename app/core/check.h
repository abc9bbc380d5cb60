// Check: validates the final source with glslang, in-process, before any GL
// call, and maps compiler logs (glslang's and the driver's) back to the
// user's files and lines.
#pragma once
#include <optional>
#include <string>

#include "core/diagnostics.h"
#include "core/source.h"

namespace rm {

// Runs glslang's parser and semantic checks on source.text (fragment stage).
Diagnostics validate(const Source& source);

// What the compiler sees: source.text after glslang's own preprocessor, with
// macros expanded and the #if branches not taken removed (a compiler's -E).
// nullopt, with *diags, if the preprocessor fails.
std::optional<std::string> expand_preprocessor(const Source& source, Diagnostics* diags);

enum class LogFormat { Glslang, Mesa };
// Turns a compiler or linker log into diagnostics located in the user's files.
Diagnostics map_log(const std::string& log, const Source& source, LogFormat format);

}  // namespace rm
