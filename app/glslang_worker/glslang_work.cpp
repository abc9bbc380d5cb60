#include "glslang_worker/glslang_work.h"

#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <set>
#include <string>

#include "core/deep_stack.h"
#include "glslang_worker/sandbox.h"
#include "glslang_worker/tree_checks.h"

namespace rm {

namespace {

// glslang's preprocessor over `text` in `shader`, or nullopt if it fails
// (its log says why). Call on a big stack.
std::optional<std::string> preprocessed(const std::string& text, glslang::TShader* shader) {
  const char* chars = text.c_str();
  const int length = static_cast<int>(text.size());
  shader->setStringsWithLengths(&chars, &length, 1);
  glslang::TShader::ForbidIncluder includer;  // includes are already expanded
  std::string expanded;
  if (!shader->preprocess(GetDefaultResources(), 100, ENoProfile, false, false, EShMsgDefault, &expanded, includer))
    return std::nullopt;
  return expanded;
}

// The verdict line ("DEPTH LINE CHAIN LINE", from check_tree), then
// glslang's log and check_tree's; with `active_text`, then a NUL and its
// preprocessed text (a NUL never comes out of the log).
std::string parse_in_child(const std::string& source_text, const std::string* active_text) {
  std::string verdict;
  // glslang's traversals recurse once per level of the tree, and a 30,000-term
  // sum (60 KB of text) overflows an 8 MiB stack.
  run_with_deep_stack([&] {
    glslang::TShader shader(EShLangFragment);
    const char* text = source_text.c_str();
    const int length = static_cast<int>(source_text.size());
    shader.setStringsWithLengths(&text, &length, 1);
    // No client API is set: plain GLSL semantics, as the GL driver applies them.
    const bool parsed = shader.parse(GetDefaultResources(), 100, false, EShMsgDefault);
    glslang::TIntermediate* tree = parsed ? shader.getIntermediate() : nullptr;
    const TreeVerdict checked = check_tree(tree ? tree->getTreeRoot() : nullptr);
    verdict = std::to_string(checked.depth) + " " + std::to_string(checked.depth_line) + " " +
              std::to_string(checked.chain) + " " + std::to_string(checked.chain_line) + "\n" + shader.getInfoLog() +
              checked.log;
    if (active_text) {
      glslang::TShader active(EShLangFragment);
      verdict += '\0' + preprocessed(*active_text, &active).value_or("");
    }
  }, kValidationStack);
  return verdict;
}

// glslang builds the built-in symbols of each #version once per process, in
// about 80 ms, and keeps them. A sandboxed child would build them again every
// time and throw them away, so the worker builds them first, from a shader
// that holds nothing of the user's but the #version line preprocess() checked.
void build_builtins_for(const std::string& version_line) {
  static std::set<std::string> built;
  if (version_line.empty() || !built.insert(version_line).second) return;
  glslang::TShader shader(EShLangFragment);
  const std::string text = version_line + "\nvoid main() {}\n";
  const char* chars = text.c_str();
  shader.setStrings(&chars, 1);
  shader.parse(GetDefaultResources(), 100, false, EShMsgDefault);
}

}  // namespace

std::optional<GlslangReply> serve(const GlslangRequest& request, int requester) {
  SandboxLimits limits;
  limits.seconds = kValidationSeconds;
  limits.bytes = kValidationBytes;
  limits.requester = requester;
  SandboxResult child;
  if (request.kind == GlslangRequest::Kind::Validate) {
    build_builtins_for(request.version_line);
    const std::string* active = request.active_text ? &*request.active_text : nullptr;
    child = run_sandboxed([&] { return parse_in_child(request.text, active); }, limits);
  } else {
    child = run_sandboxed(
        [&] {
          std::string out;
          run_with_deep_stack([&] {
            glslang::TShader shader(EShLangFragment);
            if (auto expanded = preprocessed(request.text, &shader)) out = "+" + *expanded;
            else out = "-" + std::string(shader.getInfoLog());
          }, kValidationStack);
          return out;
        },
        limits);
  }
  GlslangReply reply;
  reply.signal = child.signal;
  reply.output = std::move(child.output);
  switch (child.status) {
    case SandboxResult::Status::Ok: reply.status = GlslangReply::Status::Ok; break;
    case SandboxResult::Status::TimedOut: reply.status = GlslangReply::Status::TimedOut; break;
    case SandboxResult::Status::OutOfMemory: reply.status = GlslangReply::Status::OutOfMemory; break;
    case SandboxResult::Status::Crashed: reply.status = GlslangReply::Status::Crashed; break;
    case SandboxResult::Status::Abandoned: return std::nullopt;
  }
  return reply;
}

}  // namespace rm
