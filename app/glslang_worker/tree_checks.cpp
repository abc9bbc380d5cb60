#include "glslang_worker/tree_checks.h"

#include <glslang/Include/intermediate.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <unordered_map>
#include <utility>
#include <vector>

#include "glslang_worker/protocol.h"

namespace rm {

namespace {

// The entry point's mangled name: every call the driver inlines starts there.
constexpr const char* kEntryPoint = "main(";

// A line of glslang's log, as the host maps it to the user's file and line.
std::string error_line(int line, const std::string& name, const std::string& message) {
  return "ERROR: 0:" + std::to_string(line) + ": '" + name + "' : " + message + "\n";
}

// The deepest nesting of the program's tree (one level per operator in a
// chain like x+x+x, per call, per parenthesis) and the final source line
// where it is reached.
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
      out += error_line(line, name, "function is called but no body defines it");
    return out;
  }

 private:
  std::set<std::string> defined_;               // mangled names: "f(vf3;"
  std::map<std::string, int> first_call_;
};

// The inputs from a vertex shader the code uses (an `in` or `varying`
// variable or block), as the driver's linker names them. The host's vertex
// shader passes nothing on, so the linker refuses any such use, reached or
// not; glslang checks one stage and lets them pass. The log lines are the
// linker's, so that `check` and a build say the same, at the declaration.
class InputsNothingFeeds : public glslang::TIntermTraverser {
 public:
  void visitSymbol(glslang::TIntermSymbol* symbol) override {
    const glslang::TType& type = symbol->getType();
    const int line = symbol->getLoc().line;  // 0 for the list of globals: not a use
    if (type.getQualifier().storage != glslang::EvqVaryingIn || line <= 0) return;
    const bool block = type.getBasicType() == glslang::EbtBlock;
    if (!block && symbol->getName().compare(0, 3, "gl_") == 0) return;
    auto [at, added] = first_use_.emplace(Input{block, block ? type.getTypeName().c_str() : symbol->getName().c_str()}, line);
    if (!added) at->second = std::min(at->second, line);
  }
  // The linker's lines for them, in the order of their first uses.
  std::string log() const {
    std::vector<std::pair<int, Input>> used;
    for (const auto& [input, line] : first_use_) used.emplace_back(line, input);
    std::sort(used.begin(), used.end());
    std::string out;
    for (const auto& [line, input] : used)
      out += input.first ? "error: Input block `" + input.second + "' is not an output of the previous stage\n"
                         : "error: fragment shader input `" + input.second + "' has no matching output in the previous stage\n";
    return out;
  }

 private:
  using Input = std::pair<bool, std::string>;  // a block?, and its name
  std::map<Input, int> first_use_;
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
    return error_line(largest->line, largest->name,
                      "an array of " + whole(largest->scalars) + " components" +
                          (largest_calls > 1 ? " in each of " + whole(largest_calls) + " calls of " + function : "") +
                          (total > largest_scalars ? ", and " + whole(total) + " in all the shader's arrays" : "") +
                          "; at most " + whole(kMaxArrayScalars) +
                          " are allowed in a shader's arrays (the GL driver compiles code for each)");
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
    if (function == kEntryPoint) return 1;
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

// How deep the GL driver's expression trees may grow once it inlines every
// call and puts the expression of each variable set once and read once in
// place of its read (Mesa's tree grafting): a chain of 10,000 such
// variables (`float x1 = x0 * 1.0001 + 0.1; ...`), or 10,000 calls
// `x = f(x);`, crashed llvmpipe's compile on an 8 MiB stack, and on a larger
// one took it 27 s and 12 s (5,000 calls: 2.7 s; 2,500 variables, a chain
// of 5,000 here: 1.6 s). Counted as an upper bound:
// a read of a variable counts the depth of its value, whatever its uses; a
// loop's body counts once; a call adds what its function's body adds.
class ChainDepth {
 public:
  explicit ChainDepth(TIntermNode* root) {
    auto* program = root->getAsAggregate();
    if (!program) return;
    for (TIntermNode* item : program->getSequence()) {
      auto* function = item->getAsAggregate();
      if (function && function->getOp() == glslang::EOpFunction) functions_[function->getName().c_str()] = function;
      else value(item);  // a global's initialiser
    }
    added_by(kEntryPoint);
  }
  int deepest = 0;  // operations, through variables and calls
  int line = 0;     // the final source line where a chain first passes kMaxChainDepth, else of the deepest

 private:
  int note(TIntermNode* node, int depth) { return note(node->getLoc().line, depth); }
  int note(int at, int depth) {
    if (at <= 0) return depth;  // the tree's own nodes, with no line
    if (depth > deepest && deepest <= kMaxChainDepth) line = at;
    deepest = std::max(deepest, depth);
    if (depth > here_.depth) here_ = {depth, at};
    return depth;
  }
  // The variable an assignment writes (through indices, fields, swizzles).
  static glslang::TIntermSymbol* written(TIntermNode* node) {
    while (node && !node->getAsSymbolNode()) {
      auto* binary = node->getAsBinaryNode();
      node = binary ? binary->getLeft() : nullptr;
    }
    return node ? node->getAsSymbolNode() : nullptr;
  }
  void set(TIntermNode* target, int depth, bool whole) {
    if (auto* symbol = written(target)) {
      const long long id = symbol->getId();
      hold(id, whole ? depth : std::max(values_[id], depth));
    }
  }
  void hold(long long id, int depth) {
    int& held = values_[id];
    if (!journal_.empty()) journal_.back().emplace(id, held);  // the first write of the branch under way
    held = depth;
  }
  // Walks one branch of an `if` into `depth`, then puts back what it wrote:
  // returns each written variable's depth at the branch's end.
  std::unordered_map<long long, int> undone(TIntermNode* branch, int* depth) {
    journal_.emplace_back();
    *depth = value(branch);
    std::unordered_map<long long, int> wrote;
    for (const auto& [id, before] : journal_.back()) {
      wrote[id] = values_[id];
      values_[id] = before;
    }
    journal_.pop_back();
    return wrote;
  }

  int value(TIntermNode* node) {
    using namespace glslang;
    if (!node || node->getAsConstantUnion()) return 0;
    if (auto* symbol = node->getAsSymbolNode()) {
      auto at = values_.find(symbol->getId());
      return at == values_.end() ? 0 : at->second;
    }
    if (auto* binary = node->getAsBinaryNode()) {
      const TOperator op = binary->getOp();
      const int right = value(binary->getRight());
      if (op >= EOpAssign && op <= EOpRightShiftAssign) {
        const bool whole = op == EOpAssign && binary->getLeft()->getAsSymbolNode();
        const int depth = op == EOpAssign ? right : 1 + std::max(right, value(binary->getLeft()));
        set(binary->getLeft(), note(node, depth), whole);
        return depth;
      }
      return note(node, 1 + std::max(value(binary->getLeft()), right));
    }
    if (auto* unary = node->getAsUnaryNode()) {
      const int depth = note(node, 1 + value(unary->getOperand()));
      const TOperator op = unary->getOp();
      if (op == EOpPostIncrement || op == EOpPostDecrement || op == EOpPreIncrement || op == EOpPreDecrement)
        set(unary->getOperand(), depth, true);
      return depth;
    }
    if (auto* selection = node->getAsSelectionNode()) {
      const int condition = value(selection->getCondition());
      int yes = 0, no = 0;
      const auto yes_wrote = undone(selection->getTrueBlock(), &yes);
      const auto no_wrote = undone(selection->getFalseBlock(), &no);
      // After the if, a variable holds what either branch left in it: its
      // value before the if (values_ now) where a branch did not write it.
      for (const auto& [id, depth] : yes_wrote) {
        auto other = no_wrote.find(id);
        hold(id, std::max(depth, other != no_wrote.end() ? other->second : values_[id]));
      }
      for (const auto& [id, depth] : no_wrote)
        if (!yes_wrote.count(id)) hold(id, std::max(depth, values_[id]));
      return note(node, 1 + std::max({condition, yes, no}));
    }
    if (auto* loop = node->getAsLoopNode()) {
      value(loop->getTest());
      value(loop->getBody());
      value(loop->getTerminal());
      return 0;
    }
    if (auto* branch = node->getAsBranchNode()) {
      const int depth = value(branch->getExpression());
      returned_ = std::max(returned_, depth);
      return depth;
    }
    if (auto* choice = node->getAsSwitchNode()) {
      value(choice->getCondition());
      value(choice->getBody());
      return 0;
    }
    auto* aggregate = node->getAsAggregate();
    if (!aggregate) return 0;
    const TOperator op = aggregate->getOp();
    if (op == EOpLinkerObjects || op == EOpParameters || op == EOpFunction) return 0;
    int last = 0, most = 0;
    for (TIntermNode* child : aggregate->getSequence()) most = std::max(most, last = value(child));
    if (op == EOpSequence || op == EOpComma || op == EOpNull) return last;
    if (op == EOpFunctionCall && aggregate->isUserDefined()) {
      // Named where most of the depth comes from: the arguments, or the
      // function's body (the host's main() calls mainImage).
      const Deepest body = added_by(aggregate->getName().c_str());
      const int depth = note(body.depth > most ? body.line : node->getLoc().line,
                             static_cast<int>(std::min<long long>(kDeepEnough, 1LL + most + body.depth)));
      const TQualifierList& qualifiers = aggregate->getQualifierList();
      for (size_t i = 0; i < qualifiers.size() && i < aggregate->getSequence().size(); ++i)
        if (qualifiers[i] == EvqOut || qualifiers[i] == EvqInOut) set(aggregate->getSequence()[i], depth, true);
      return depth;
    }
    return note(node, 1 + most);  // a constructor or a built-in function
  }

  struct Deepest {
    int depth = 0;
    int line = 0;
  };
  static constexpr int kDeepEnough = 1 << 30;  // calls nested ten times twelve deep would pass an int

  // The depth a call of `function` adds to its arguments': what its body
  // returns or writes to its parameters, from parameters at 0; and the line
  // of its body's deepest value.
  Deepest added_by(const std::string& function) {
    auto [at, added] = added_.emplace(function, Deepest{});
    if (!added) return at->second;  // known, or a cycle (an error of its own) under way
    auto body = functions_.find(function);
    if (body == functions_.end()) return {};
    auto values = std::exchange(values_, {});
    auto journal = std::exchange(journal_, {});  // the caller's branches are not this body's
    const int returned = std::exchange(returned_, 0);
    const Deepest here = std::exchange(here_, {});
    for (TIntermNode* part : body->second->getSequence()) value(part);
    Deepest result{returned_, here_.line};
    for (TIntermNode* part : body->second->getSequence()) {
      auto* parameters = part->getAsAggregate();
      if (!parameters || parameters->getOp() != glslang::EOpParameters) continue;
      for (TIntermNode* parameter : parameters->getSequence())  // what an out parameter holds at the end
        if (auto* symbol = parameter->getAsSymbolNode()) result.depth = std::max(result.depth, values_[symbol->getId()]);
    }
    values_ = std::move(values);
    journal_ = std::move(journal);
    returned_ = returned;
    here_ = here;
    return added_[function] = result;
  }

  std::map<std::string, glslang::TIntermAggregate*> functions_;  // by mangled name, "f(vf3;"
  std::map<std::string, Deepest> added_;
  Deepest here_;  // the deepest value of the function being walked
  std::unordered_map<long long, int> values_;  // a variable's depth now, by symbol id
  // For each branch of an `if` under way, innermost last, what its writes
  // replaced: a branch is undone in the time its writes take. (A copy of
  // every variable at each `if` took 10,000 variables and as many ifs past
  // the worker's 5 s.)
  std::vector<std::unordered_map<long long, int>> journal_;
  int returned_ = 0;                 // the deepest value the function walked returns
};

}  // namespace

TreeVerdict check_tree(TIntermNode* root) {
  TreeVerdict verdict;
  if (!root) return verdict;
  DeepestNode deepest;
  CallsWithoutBody calls;
  LargeArrays arrays;
  InputsNothingFeeds inputs;
  root->traverse(&deepest);
  root->traverse(&calls);
  root->traverse(&arrays);
  root->traverse(&inputs);
  const ChainDepth chains(root);
  verdict.depth = deepest.getMaxDepth(), verdict.depth_line = deepest.line;
  verdict.chain = chains.deepest, verdict.chain_line = chains.line;
  verdict.log = calls.log() + arrays.log() + inputs.log();
  return verdict;
}

}  // namespace rm
