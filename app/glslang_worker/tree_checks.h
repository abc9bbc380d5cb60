// What the GL driver cannot take though glslang does, found in glslang's
// tree of a parsed shader: nesting and chains too deep for the driver's
// compiler to recurse on, calls to functions no body defines, arrays too
// large for it to compile, and inputs no vertex shader of the host's feeds.
// This file builds without RTTI, as Debian's glslang does, so that it may
// derive from glslang's traverser.
#pragma once
#include <string>

class TIntermNode;

namespace rm {

struct TreeVerdict {
  int depth = 0, depth_line = 0;  // the tree's deepest nesting, and its final source line
  int chain = 0, chain_line = 0;  // the deepest chain through variables and calls, and where it passes the limit
  std::string log;                // glslang's log lines for the calls and the arrays
};

// All zero for no tree (a shader that did not parse).
TreeVerdict check_tree(TIntermNode* root);

}  // namespace rm
