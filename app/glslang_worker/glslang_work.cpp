#include "glslang_worker/glslang_work.h"

#include <glslang/Include/intermediate.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <pthread.h>

#include <algorithm>
#include <cstdio>
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

// Scalars in a value of `type`: its components, times its array sizes,
// through structs. In double: glslang's own count, an int, overflows for
// float a[65536][65536].
double scalars(const glslang::TType& type) {
  double n = 0;
  if (type.isStruct()) {
    for (const auto& member : *type.getStruct()) n += scalars(*member.type);
  } else {
    n = type.isMatrix() ? type.getMatrixCols() * type.getMatrixRows() : type.getVectorSize();
  }
  if (type.isArray())
    for (int d = 0; d < type.getArraySizes()->getNumDims(); ++d) n *= std::max(type.getArraySizes()->getDimSize(d), 1);
  return n;
}

// The most scalars the arrays of one shader may hold in all (64 KB of
// floats; as many as llvmpipe allows a fragment shader's uniforms). A CPU
// driver took 24 s and 0.9 GB to compile an array of 16,384 floats.
constexpr double kMaxArrayScalars = 16384;

// The shader's own arrays (locals, globals, constants, parameters; not
// uniforms, buffers or the stage's inputs and outputs), counted in scalars.
// A CPU driver compiles code for every element of an array it indexes by a
// variable: on llvmpipe 4,096 floats took 5.8 s and 360 MB, 65,536 took
// 95 s and 2.8 GB, and 16,777,216 crashed the process. The driver inlines
// every call, so a function's locals and parameters count once a call that
// main() reaches (a function it never reaches costs nothing); globals and
// constants count once.
class LargeArrays : public glslang::TIntermTraverser {
 public:
  LargeArrays() : TIntermTraverser(true, false, true) {}  // after a function too: where it ends

  bool visitAggregate(glslang::TVisit visit, glslang::TIntermAggregate* node) override {
    if (node->getOp() == glslang::EOpFunction)
      function_ = visit == glslang::EvPreVisit ? node->getName().c_str() : "";
    else if (node->getOp() == glslang::EOpFunctionCall && node->isUserDefined() && visit == glslang::EvPreVisit)
      ++calls_[node->getName().c_str()][function_];
    return true;
  }

  void visitSymbol(glslang::TIntermSymbol* symbol) override {
    const glslang::TType& type = symbol->getType();
    if (!type.containsArray()) return;  // a struct of plain members the driver splits into scalars
    const glslang::TStorageQualifier storage = type.getQualifier().storage;
    switch (storage) {
      case glslang::EvqUniform: case glslang::EvqBuffer: case glslang::EvqVaryingIn: case glslang::EvqVaryingOut:
        return;
      default: break;
    }
    // The first line the tree names it on: an uninitialised local has no
    // node of its own, so that is its first use. A global's entry in the
    // list of globals has no line; one never used costs the driver nothing.
    if (symbol->getLoc().line <= 0) return;
    const bool once = storage == glslang::EvqGlobal || storage == glslang::EvqConst;
    auto [at, added] = arrays_.emplace(symbol->getId(), Array{symbol->getName().c_str(), symbol->getLoc().line,
                                                              scalars(type), once ? "" : function_});
    if (!added) at->second.line = std::min(at->second.line, symbol->getLoc().line);
  }

  // glslang's log line for arrays past the limit in all, at the largest.
  std::string log() {
    double total = 0;
    const Array* largest = nullptr;
    double largest_scalars = 0, largest_calls = 1;
    for (const auto& [id, array] : arrays_) {
      const double calls = array.function.empty() ? 1 : times_inlined(array.function);
      total += array.scalars * calls;
      if (!largest || array.scalars * calls > largest_scalars)
        largest = &array, largest_scalars = array.scalars * calls, largest_calls = calls;
    }
    if (total <= kMaxArrayScalars) return "";
    const auto whole = [](double n) {
      char text[32];
      std::snprintf(text, sizeof text, "%.15g", n);
      return std::string(text);
    };
    const std::string function = largest->function.substr(0, largest->function.find('(') + 1) + ")";
    return "ERROR: 0:" + std::to_string(largest->line) + ": '" + largest->name + "' : an array of " +
           whole(largest->scalars) + " components" +
           (largest_calls > 1 ? " in each of " + whole(largest_calls) + " calls of " + function : "") +
           (total > largest_scalars ? ", and " + whole(total) + " in all the shader's arrays" : "") + "; at most " +
           whole(kMaxArrayScalars) + " are allowed in a shader's arrays (the GL driver compiles code for each)\n";
  }

 private:
  struct Array {
    std::string name;
    int line;
    double scalars;
    std::string function;  // the function whose every call holds a copy; empty: one copy
  };

  // How many copies of `function` the driver's inlining makes: one for
  // main(), and for any other, the sum over its calls of their caller's.
  double times_inlined(const std::string& function) {
    if (function == "main(") return 1;
    auto [at, added] = inlined_.emplace(function, 0.0);
    if (!added) return at->second;  // known, or a cycle (an error of its own) under way
    double n = 0;
    for (const auto& [caller, count] : calls_[function]) n += count * times_inlined(caller);
    return inlined_[function] = n;
  }

  std::string function_;  // mangled, as "f(vf3;"; empty outside functions
  std::map<std::string, std::map<std::string, double>> calls_;  // callee: caller: call sites
  std::map<std::string, double> inlined_;
  std::map<long long, Array> arrays_;
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
    LargeArrays arrays;
    if (tree && tree->getTreeRoot()) {
      tree->getTreeRoot()->traverse(&deepest);
      tree->getTreeRoot()->traverse(&calls);
      tree->getTreeRoot()->traverse(&arrays);
    }
    verdict = std::to_string(deepest.getMaxDepth()) + " " + std::to_string(deepest.line) + "\n" + shader.getInfoLog() +
              calls.log() + arrays.log();
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
