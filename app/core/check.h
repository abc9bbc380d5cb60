// Check: validates the final source with glslang before any GL call, and
// maps compiler logs (glslang's and the driver's) back to the user's files
// and lines. glslang runs in the host's worker process (core/glslang_client),
// within the limits in glslang_worker/protocol.h.
#pragma once
#include <optional>
#include <string>

#include "core/diagnostics.h"
#include "core/source.h"
#include "glslang_worker/protocol.h"

namespace rm {

// How deep the program's tree may nest (operator chains, calls, parentheses)
// before validate() refuses it. Real shaders stay far below it.
constexpr int kMaxTreeDepth = 2000;

// Runs glslang's parser and semantic checks on source.text (fragment stage)
// within the validation limits, and refuses a tree deeper than kMaxTreeDepth
// and a chain through variables and calls deeper than kMaxChainDepth
// (glslang_worker/protocol.h: the worker finds where it passes the limit).
// With `active`, the same request also runs glslang's preprocessor over
// source.text followed by `appended`, and leaves the result there, line for
// line (what active_code() gives; empty if the preprocessor fails): the
// uniforms and the knobs read it, and a reload asks glslang once, not three
// times.
Diagnostics validate(const Source& source, std::string* active = nullptr, const std::string& appended = {});

// What the compiler sees: source.text after glslang's own preprocessor, with
// macros expanded and the #if branches not taken removed (a compiler's -E).
// With LineMarkers::On, lines are placed as cpp places them: a `# LINE
// "FILE"` line where the next line does not follow the one before, blank
// lines for a short gap. Off (cpp -P): the lines alone, which a GLSL
// compiler takes as they are. nullopt, with *diags, if the preprocessor
// fails.
enum class LineMarkers { On, Off };
std::optional<std::string> expand_preprocessor(const Source& source, Diagnostics* diags,
                                               LineMarkers markers = LineMarkers::On);

// `text` after glslang's preprocessor, within the validation limits: the code
// the compiler would see. nullopt if the preprocessor fails. `version_line`
// is text's first line, a Source's version_line (checked): the worker keeps
// the built-in symbols of its #version, which glslang builds for a
// preprocess too.
std::optional<std::string> active_code(const std::string& text, const std::string& version_line);

enum class LogFormat { Glslang, Mesa };
// Turns a compiler or linker log into diagnostics located in the user's files.
Diagnostics map_log(const std::string& log, const Source& source, LogFormat format);

}  // namespace rm
