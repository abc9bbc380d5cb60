// Every module in shaderlib/rm: compiles on its own (it includes what it
// needs), compiles when its text appears twice (its include guard works even
// where a tool does not include each file once), and documents itself: a
// header naming the module, what it provides and needs, and one comment per
// function, naming the distance class of every sd* function; and its loops
// test at the bottom.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>

#include "core/data_paths.h"
#include "gpu/egl_fixture.h"
#include "gpu/probe.h"
#include "support.h"

namespace rm::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> modules() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(shaderlib_dir() / "rm"))
    if (entry.path().extension() == ".glsl") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string module_text(const std::string& name) { return read_file(shaderlib_dir() / "rm" / (name + ".glsl")); }

// What a scene supplies: Shadertoy inputs (rm/render's default light reads
// iMouse), the knobs a module requires (rm/grid's cell size) before the
// include, and map() (rm/grid: mapCell()) and material() after it, as the
// contract allows.
std::string scene_inputs(const std::string& name) {
  std::string inputs = "uniform vec4 iMouse;\nuniform vec3 iResolution;\n";
  if (name == "grid") inputs += "#define RM_GRID_PERIOD vec3(2.0)\n#define RM_GRID_RADIUS 0.5\n";
  return inputs;
}
std::string scene_stub(const std::string& name) {
  if (name == "grid") return "float mapCell(vec3 q, vec3 cell) { return length(q) - 0.4; }\n";
  std::string stub = "float map(vec3 p) { return length(p) - 1.0; }\n";
  if (name == "render") stub += "RmMaterial material(vec3 p, vec3 n) { return rmMaterial(vec3(1.0)); }\n";
  return stub;
}

class Module : public EglTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(Module, CompilesOnItsOwn) {
  const std::string& name = GetParam();
  std::string error;
  EXPECT_TRUE(Probe::build(scene_inputs(name) + ("#include <rm/" + name + ".glsl>\n") + scene_stub(name), "vec4(0.0)", &error))
      << error;
}

TEST_P(Module, CompilesWhenItsTextAppearsTwice) {
  const std::string& name = GetParam();
  const std::string text = module_text(name);
  std::string error;
  EXPECT_TRUE(Probe::build(scene_inputs(name) + text + "\n" + text + "\n" + scene_stub(name), "vec4(0.0)", &error)) << error;
}

TEST_P(Module, HasAHeaderAndAnIncludeGuard) {
  const std::string& name = GetParam();
  const std::string text = module_text(name);
  std::string guard = "RM_" + name + "_GLSL";
  std::transform(guard.begin(), guard.end(), guard.begin(), [](unsigned char c) { return std::toupper(c); });
  EXPECT_EQ(text.rfind("// rm/" + name + ".glsl: ", 0), 0u) << "the first line names the module";
  EXPECT_NE(text.find("\n// Provides: "), std::string::npos);
  EXPECT_NE(text.find("\n// Needs: "), std::string::npos);
  EXPECT_NE(text.find("#ifndef " + guard + "\n#define " + guard + "\n"), std::string::npos);
  EXPECT_NE(text.find("#endif  // " + guard), std::string::npos);
}

// Every function and struct definition follows a comment; sd* comments give
// the class; every function and type is listed under Provides.
TEST_P(Module, DocumentsEveryFunction) {
  const std::string& name = GetParam();
  const std::string text = module_text(name);
  const std::string provides = text.substr(text.find("// Provides:"), text.find("// Needs:") - text.find("// Provides:"));
  static const std::regex function(R"(^(?:float|[iub]?vec[234]|mat[234]|int|uint|bool|Rm\w+) (\w+)\(.*\) \{|^struct (\w+) \{)");
  std::istringstream lines(text);
  std::string line, previous;
  std::set<std::string> seen;
  while (std::getline(lines, line)) {
    std::smatch m;
    if (std::regex_search(line, m, function)) {
      const std::string fn = m[1].matched ? m[1].str() : m[2].str();
      if (fn.rfind("sd", 0) == 0) {
        EXPECT_TRUE(std::regex_search(previous, std::regex(R"(\b(exact|bound|approximate)\b)")) ||
                    std::regex_search(previous, function))
            << fn << ": the comment must give the distance class";
      }
      // Overloads may share the comment above the first of them.
      std::smatch before;
      const bool overload = std::regex_search(previous, before, function) && before[1] == fn;
      EXPECT_TRUE(previous.rfind("//", 0) == 0 || overload) << fn << " has no comment";
      if (seen.insert(fn).second) {
        EXPECT_TRUE(std::regex_search(provides, std::regex("\\b" + fn + "\\b"))) << fn << " is not under Provides";
      }
    }
    previous = line;
  }
  // Nothing seen means the patterns above failed, unless the module is macros only.
  EXPECT_TRUE(!seen.empty() || text.find("\n#define RM_") != std::string::npos) << "no functions found";
}

// Every loop tests at the bottom (rm/common.glsl says why): on llvmpipe a
// loop tested at the top runs one more turn, with every lane masked off,
// whenever its last lane leaves by that test.
TEST_P(Module, LoopsTestAtTheBottom) {
  const std::string text = module_text(GetParam());
  static const std::regex top_tested(R"(\bfor \(|\bwhile \([^\n]*\) *\{)");
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number)
    EXPECT_FALSE(std::regex_search(line, top_tested)) << GetParam() << ".glsl:" << number << ": " << line;
}

INSTANTIATE_TEST_SUITE_P(Shaderlib, Module, ::testing::ValuesIn(modules()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace rm::test
