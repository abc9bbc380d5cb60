#include "glslang_worker/glslang_work.h"

#include <glslang/Include/intermediate.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <pthread.h>

#include <algorithm>
#include <functional>
#include <map>
#include <set>

#include "glslang_worker/sandbox.h"

namespace rm {

namespace {

// Runs `work` on a thread with a stack of `bytes`, and waits for it. Only the
// pages the work touches are ever backed by memory.
void run_with_stack(size_t bytes, const std::function<void()>& work) {
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_t thread;
  auto call = [](void* w) -> void* {
    (*static_cast<const std::function<void()>*>(w))();
    return nullptr;
  };
  const bool started = pthread_attr_setstacksize(&attr, bytes) == 0 &&
                       pthread_create(&thread, &attr, call, const_cast<std::function<void()>*>(&work)) == 0;
  pthread_attr_destroy(&attr);
  if (!started) {
    work();  // no such stack to be had: run here, with the stack there is
    return;
  }
  pthread_join(thread, nullptr);
}

// The deepest nesting of the program's tree (one level per operator in a
// chain like x+x+x, per call, per parenthesis) and the final source line
// where it is reached. (This file builds without RTTI, as Debian's glslang
// does, so that it may derive from glslang's traverser.)
class DeepestNode : public glslang::TIntermTraverser {
 public:
  int line = 0;
  bool visitBinary(glslang::TVisit, glslang::TIntermBinary* node) override { return note(node); }
  bool visitUnary(glslang::TVisit, glslang::TIntermUnary* node) override { return note(node); }
  bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* node) override { return note(node); }
  bool visitSelection(glslang::TVisit, glslang::TIntermSelection* node) override { return note(node); }
  bool visitLoop(glslang::TVisit, glslang::TIntermLoop* node) override { return note(node); }

 private:
  bool note(TIntermNode* node) {
    // Called before the node's own level is counted: depth + 1 is its level.
    if (depth + 1 > maxDepth) line = node->getLoc().line;
    return true;
  }
};

// The calls to functions that no body defines, each with the final source
// line of its first call. The driver's linker refuses any such call, reached
// or not. glslang's own link finds them too, but its call-graph checks grow
// with the square of the calls (a chain of 20,000 functions took 81 s); this
// is one walk over the tree.
class CallsWithoutBody : public glslang::TIntermTraverser {
 public:
  bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* node) override {
    if (node->getOp() == glslang::EOpFunction) {
      defined_.insert(node->getName().c_str());
    } else if (node->getOp() == glslang::EOpFunctionCall && node->isUserDefined()) {
      const int line = node->getLoc().line;
      auto [at, added] = first_call_.emplace(node->getName().c_str(), line);
      if (!added) at->second = std::min(at->second, line);
    }
    return true;
  }
  // glslang's log lines for them, in the order of their lines.
  std::string log() const {
    std::vector<std::pair<int, std::string>> missing;
    for (const auto& [mangled, line] : first_call_)
      if (!defined_.count(mangled)) missing.emplace_back(line, mangled.substr(0, mangled.find('(')));
    std::sort(missing.begin(), missing.end());
    std::string out;
    for (const auto& [line, name] : missing)
      out += "ERROR: 0:" + std::to_string(line) + ": '" + name + "' : function is called but no body defines it\n";
    return out;
  }

 private:
  std::set<std::string> defined_;               // mangled names: "f(vf3;"
  std::map<std::string, int> first_call_;
};

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

// The verdict line ("DEPTH LINE"), then glslang's log; with `active_text`,
// then a NUL and its preprocessed text (a NUL never comes out of the log).
std::string parse_in_child(const std::string& source_text, const std::string* active_text) {
  std::string verdict;
  // glslang's traversals recurse once per level of the tree, and a 30,000-term
  // sum (60 KB of text) overflows an 8 MiB stack.
  run_with_stack(kValidationStack, [&] {
    glslang::TShader shader(EShLangFragment);
    const char* text = source_text.c_str();
    const int length = static_cast<int>(source_text.size());
    shader.setStringsWithLengths(&text, &length, 1);
    // No client API is set: plain GLSL semantics, as the GL driver applies them.
    const bool parsed = shader.parse(GetDefaultResources(), 100, false, EShMsgDefault);
    glslang::TIntermediate* tree = parsed ? shader.getIntermediate() : nullptr;
    DeepestNode deepest;
    CallsWithoutBody calls;
    if (tree && tree->getTreeRoot()) {
      tree->getTreeRoot()->traverse(&deepest);
      tree->getTreeRoot()->traverse(&calls);
    }
    verdict = std::to_string(deepest.getMaxDepth()) + " " + std::to_string(deepest.line) + "\n" + shader.getInfoLog() +
              calls.log();
    if (active_text) {
      glslang::TShader active(EShLangFragment);
      verdict += '\0' + preprocessed(*active_text, &active).value_or("");
    }
  });
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
          run_with_stack(kValidationStack, [&] {
            glslang::TShader shader(EShLangFragment);
            if (auto expanded = preprocessed(request.text, &shader)) out = "+" + *expanded;
            else out = "-" + std::string(shader.getInfoLog());
          });
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
