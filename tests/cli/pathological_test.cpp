// Pathological input, as editors, generators and accidents make it: each case
// either works or fails with one line naming the problem, within 10 s and
// 1 GB (30 s and 2 GB sanitized), and never crashes or hangs. A case that
// checks clean is rendered too, so the GL driver sees it as the window would.
#include <gtest/gtest.h>
#include <sched.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "support.h"

namespace rm {
namespace {

using test::children_of;
using test::TempDir;
using test::write_file;

constexpr size_t kTenMB = 10u << 20;
#ifdef RM_SANITIZED
// ASan's shadow memory and quarantine come on top, and every check of it
// takes time: 10 MB of newlines took 10.2 s to check and 14.5 to render
// sanitized on a slow day here, against 1.3 and 1.9 unsanitized.
constexpr double kMaxSeconds = 30.0;
constexpr long kMaxKiB = 2l << 20;
#else
constexpr double kMaxSeconds = 10.0;
constexpr long kMaxKiB = 1l << 20;
#endif

const std::string kMain = "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n";

// Whether process `pid` has ended: gone, or a zombie that no one reaped.
bool ended(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return true;
  const size_t name_end = line.rfind(')');
  return name_end != std::string::npos && line.compare(name_end, 4, ") Z ") == 0;
}

// The lines of `err` that are the host's: not blank, and not Mesa's
// loader's own `libEGL warning:` lines, which it writes as it fails.
std::vector<std::string> host_lines(const std::string& err) {
  std::istringstream lines(err);
  std::vector<std::string> ours;
  for (std::string line; std::getline(lines, line);)
    if (!line.empty() && line.rfind("libEGL warning: ", 0) != 0) ours.push_back(line);
  return ours;
}

struct Case {
  std::string name;     // the file in the test directory, or the arguments after the command
  int status;           // of `check`; `render` must agree
  std::string says;     // part of the one line on stderr (for status != 0)
  bool render = true;   // also render it (cases whose check passes)
};

class Pathological : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  void expect_case(const std::string& command, const Case& c) {
    SCOPED_TRACE(command + " " + c.name);
    const test::Outcome r = test::run_binary(command + " " + c.name);
    EXPECT_EQ(r.status, c.status) << r.err;
    if (c.status == 0) {
      EXPECT_EQ(r.err, "");
    } else {
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
      EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    }
    EXPECT_LT(r.seconds, kMaxSeconds);
    EXPECT_LT(r.peak_kib, kMaxKiB);
    // The figures docs/reliability.md gives.
    std::printf("  %-6s %-22s status %d  %5.2f s  %4ld MB\n", command.substr(0, command.find(' ')).c_str(),
                std::filesystem::path(c.name).filename().c_str(), r.status, r.seconds, r.peak_kib / 1024);
  }

  void run_table(const std::vector<Case>& cases) {
    for (const Case& c : cases) {
      expect_case("check", c);
      if (c.status == 0 && c.render) expect_case("render -o " + path("out.png") + " --size 8x8", c);
    }
  }

  TempDir dir_;
};

TEST_F(Pathological, LongRunsOfBlanksNewlinesAndComments) {
  const std::vector<std::pair<std::string, char>> blanks = {
      {"space", ' '}, {"tab", '\t'}, {"cr", '\r'}, {"formfeed", '\f'}, {"vtab", '\v'}};
  std::vector<Case> cases;
  for (const auto& [name, blank] : blanks) {
    write_file(dir_ / (name + ".frag"), "float a;" + std::string(kTenMB, blank) + "float b;\n" + kMain);
    cases.push_back({path(name + ".frag"), 0, ""});
  }
  write_file(dir_ / "newlines.frag", std::string(kTenMB, '\n') + kMain);
  write_file(dir_ / "comment.frag", "/*" + std::string(kTenMB, '*') + "*/\n" + kMain);
  write_file(dir_ / "line_comment.frag", "//" + std::string(kTenMB, 'x') + "\n" + kMain);
  write_file(dir_ / "unterminated.frag", kMain + "/* never closed\n");
  // 10 MB of code: more than glslang parses in its 512 MiB (4 MiB is), so
  // the line names the shader's size rather than guessing at a macro.
  write_file(dir_ / "code.frag", test::many_lines_of_code(kTenMB) + kMain);
  cases.push_back({path("newlines.frag"), 0, ""});
  cases.push_back({path("comment.frag"), 0, ""});
  cases.push_back({path("line_comment.frag"), 0, ""});
  cases.push_back({path("unterminated.frag"), 1, "unterminated.frag:2: error: 'comment' : End of input in comment"});
  // Out of its memory; under ASan, perhaps of its time first: the same end.
  cases.push_back({path("code.frag"), 1, "this shader of 10.0 MiB in 350777 lines (more code than one shader can hold?)"});
  run_table(cases);
}

// glslang goes on past an error to name the next, parsing the rest: after
// an error in 10 MB of statements it ran out of its 512 MiB. A text this
// large is parsed to its first error, which is named.
TEST_F(Pathological, TenMegabytesOfErrorsNameTheFirst) {
  std::string scene = "void mainImage(out vec4 c, in vec2 f) {\n";
  while (scene.size() < kTenMB) scene += "  u;\n";
  write_file(dir_ / "errors.frag", scene + "}\n");
  run_table({{path("errors.frag"), 1, "errors.frag:2:3: error: 'u' : undeclared identifier"}});
}

TEST_F(Pathological, DeepNestsAndLongMacroChains) {
  const std::string open(100000, '('), close(100000, ')');
  write_file(dir_ / "parens.frag", "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(" + open + "1.0" + close + ");\n}\n");
  std::string ifs;
  for (int i = 0; i < 10000; ++i) ifs += "#if 1\n";
  ifs += kMain;
  for (int i = 0; i < 10000; ++i) ifs += "#endif\n";
  write_file(dir_ / "ifs.frag", ifs);
  std::string chain = "#define M0 1.0\n";
  for (int i = 1; i < 10000; ++i) chain += "#define M" + std::to_string(i) + " M" + std::to_string(i - 1) + "\n";
  write_file(dir_ / "chain.frag", chain + "void mainImage(out vec4 c, in vec2 f) { c = vec4(M9999); }\n");
  write_file(dir_ / "self.frag", "#define X X\n#define Y (Y + 1.0)\n"
                                 "void mainImage(out vec4 c, in vec2 f) { float X = 1.0; c = vec4(X); }\n");
  write_file(dir_ / "self_used.frag", "#define Y (Y + 1.0)\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(Y); }\n");
  // A 30,000-term sum: 60 KB of text, and a tree 30,000 levels deep that
  // crashed glslang, and at 15,000 Mesa's compiler, on an 8 MiB stack.
  std::string sum = "void mainImage(out vec4 c, in vec2 f) {\n  float x = 1.0;\n  x = x";
  for (int i = 1; i < 30000; ++i) sum += "+x";
  write_file(dir_ / "sum.frag", sum + ";\n  c = vec4(x);\n}\n");
  // A macro that doubles 25 times: 2^26 terms from 1 KB, which glslang
  // expands without a bound of its own (minutes and gigabytes, unchecked).
  std::string bomb = "#define A0 x+x\n";
  for (int i = 1; i <= 25; ++i)
    bomb += "#define A" + std::to_string(i) + " A" + std::to_string(i - 1) + "+A" + std::to_string(i - 1) + "\n";
  write_file(dir_ / "bomb.frag", bomb + "void mainImage(out vec4 c, in vec2 f) { float x = 1.0; c = vec4(A25); }\n");
  run_table({
      {path("bomb.frag"), 1, "bomb.frag: error: glslang "},
      {path("parens.frag"), 1, "parens.frag:2: error: nested too deeply for glslang's parser"},
      {path("ifs.frag"), 1, "ifs.frag:66:1: error: '#if' : maximum nesting depth exceeded"},
      {path("chain.frag"), 0, ""},
      {path("self.frag"), 0, ""},
      {path("self_used.frag"), 1, "self_used.frag:2:"},  // Y stays Y, undeclared
      {path("sum.frag"), 1, "sum.frag:3: error: an expression nested 300"},
  });
}

// A shader that sums 2^26 terms in an #if, which takes glslang's
// preprocessor seconds but no memory, so only the time limit would end it.
std::string slow_to_validate() {
  std::string sum = "#define A0 1+1\n";
  for (int i = 1; i <= 25; ++i)
    sum += "#define A" + std::to_string(i) + " A" + std::to_string(i - 1) + "+A" + std::to_string(i - 1) + "\n";
  return sum + "#if A25 > 0\n#endif\n" + kMain;
}

// The host run as `raymarching ARGS...` (stderr to `err`), and once glslang
// runs on its shader: its worker, and the worker's child (the sandbox).
struct HostInGlslang {
  pid_t host = 0, worker = 0, sandbox = 0;
};

HostInGlslang start_host_until_glslang_runs(const std::vector<std::string>& args, const std::filesystem::path& err) {
  HostInGlslang p;
  p.host = fork();
  if (p.host == 0) {
    freopen(err.c_str(), "w", stderr);
    std::vector<char*> argv{const_cast<char*>(RM_BINARY)};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(RM_BINARY, argv.data());
    _exit(127);
  }
  const auto start = std::chrono::steady_clock::now();
  while (p.host > 0 && !p.sandbox &&
         std::chrono::steady_clock::now() - start < std::chrono::duration<double>(kMaxSeconds)) {
    for (pid_t child : children_of(p.host)) {
      if (const std::vector<pid_t> grandchildren = children_of(child); !grandchildren.empty()) {
        p.worker = child;
        p.sandbox = grandchildren[0];
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return p;
}

// A host that dies while glslang works on a shader for seconds takes its
// worker, and the worker's child, with it: the worker sees the socket close
// and kills the child at once. (They used to live on until the child's 5 s
// were up.)
TEST_F(Pathological, AHostKilledDuringALongShaderLeavesNoWorkerBehind) {
  write_file(dir_ / "bomb.frag", slow_to_validate());
  const HostInGlslang p = start_host_until_glslang_runs({"check", path("bomb.frag")}, "/dev/null");
  ASSERT_GT(p.host, 0);
  kill(p.host, SIGKILL);
  int status = 0;
  waitpid(p.host, &status, 0);
  ASSERT_NE(p.sandbox, 0) << "the host never ran glslang in its worker's child";
  const auto killed = std::chrono::steady_clock::now();
  while (!(ended(p.worker) && ended(p.sandbox)) && std::chrono::steady_clock::now() - killed < std::chrono::seconds(3))
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - killed).count();
  EXPECT_TRUE(ended(p.worker));
  EXPECT_TRUE(ended(p.sandbox));
  EXPECT_LT(seconds, 2.0);  // not the child's 5 s
  std::printf("  the worker and its child ended %.0f ms after the host was killed\n", seconds * 1000);
}

// Slurm's scancel and its time limit send SIGTERM to every process of a job,
// not at one instant. The glslang worker and its child ignore it, and end
// when the host that stops closes their socket: a render stopped while its
// shader is validated says it was stopped, not that glslang crashed on the
// shader (it did, exit 1, when the child died first).
TEST_F(Pathological, ASignalToTheWholeJobIsAStopNotAGlslangCrash) {
  write_file(dir_ / "bomb.frag", slow_to_validate());
  const std::filesystem::path err = dir_ / "err.txt";
  const HostInGlslang p = start_host_until_glslang_runs(
      {"render", path("bomb.frag"), "-o", path("out.png"), "--size", "8x8"}, err);
  ASSERT_GT(p.host, 0);
  ASSERT_NE(p.sandbox, 0) << "the host never ran glslang in its worker's child";
  kill(p.sandbox, SIGTERM);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  kill(p.host, SIGTERM);
  kill(p.worker, SIGTERM);
  int status = 0;
  waitpid(p.host, &status, 0);
  const std::string said = test::read_file(err);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGTERM) << said;
  EXPECT_EQ(said, "raymarching: error: the render was stopped by SIGTERM; nothing was written\n");
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out.png"));
}

// Arrays that a CPU driver compiles code for element by element: on
// llvmpipe 16,384 floats took 24 s and 0.9 GB, and 16,777,216 crashed the
// process after 39 s and 7 GB. Validation refuses arrays past 16,384
// scalars in all, at the largest; an array never used, or in a function
// never called, costs nothing (the driver drops it).
TEST_F(Pathological, ArraysPastWhatTheDriverCanCompile) {
  const std::string open = "void mainImage(out vec4 c, in vec2 f) {\n";
  write_file(dir_ / "huge.frag", open + "  float a[16777216];\n  a[int(f.x)] = 1.0;\n  c = vec4(a[int(f.y)]);\n}\n");
  // 2^32 elements: glslang's own count, an int, overflows.
  write_file(dir_ / "square.frag", open + "  float a[65536][65536];\n  c = vec4(a[int(f.x)][int(f.y)]);\n}\n");
  write_file(dir_ / "structs.frag", "struct S { vec4 p[64]; mat4 m; };\n" + open +
                                        "  S s[256];\n  c = s[int(f.x)].p[int(f.y)];\n}\n");
  write_file(dir_ / "global.frag", "vec3 big[8192];\nfloat at(int i) { return big[i].x; }\n" + open +
                                       "  c = vec4(at(int(f.x)));\n}\n");
  write_file(dir_ / "small.frag", open + "  float a[64];\n  a[int(f.x)] = 1.0;\n  c = vec4(a[int(f.y)]);\n}\n");
  write_file(dir_ / "unused.frag", "float unused[16777216];\n" + kMain);
  write_file(dir_ / "uncalled.frag", "float never(int i) { float b[16777216]; b[i] = 1.0; return b[i]; }\n" + kMain);
  const std::string past = "at most 16384 are allowed in a shader's arrays (the GL driver compiles code for each)";
  run_table({
      {path("huge.frag"), 1, "huge.frag:3:3: error: 'a' : an array of 16777216 components; " + past},
      {path("square.frag"), 1, "square.frag:3:12: error: 'a' : an array of 4294967296 components"},
      {path("structs.frag"), 1, "structs.frag:4:7: error: 's' : an array of 69632 components"},
      {path("global.frag"), 1, "global.frag:2:26: error: 'big' : an array of 24576 components"},
      {path("small.frag"), 0, ""},
      {path("unused.frag"), 0, ""},
      {path("uncalled.frag"), 0, ""},
  });
  expect_case("render -o " + path("huge.png") + " --size 8x8", {path("huge.frag"), 1, "huge.frag:3:3: error: 'a'"});
  EXPECT_FALSE(std::filesystem::exists(dir_ / "huge.png"));
}

// Chains the GL driver turns into deep trees: it inlines every call and puts
// the expression of a variable set once and read once in place of its read.
// On an 8 MiB stack llvmpipe crashed (SIGSEGV) on 7,000 such variables
// (`float x1 = x0 * 1.0001 + 0.1;` ...), on 10,000 calls `x = f(x);`, and on
// 818 bytes that nest calls ten times five deep (100,000 inlined calls);
// validation refuses chains past 5000 operations, where they pass it.
TEST_F(Pathological, ChainsThatTheDriverBuildsIntoDeepTrees) {
  const auto variables = [](int n) {
    std::string text = "void mainImage(out vec4 c, in vec2 f) {\n  float x0 = f.x;\n";
    for (int i = 1; i < n; ++i)
      text += "  float x" + std::to_string(i) + " = x" + std::to_string(i - 1) + " * 1.0001 + 0.1;\n";
    return text + "  c = vec4(x" + std::to_string(n - 1) + ");\n}\n";
  };
  write_file(dir_ / "variables.frag", variables(7000));
  write_file(dir_ / "fewer.frag", variables(1000));
  std::string calls = "float f(float x) { return x * 1.0001 + 0.1; }\nvoid mainImage(out vec4 c, in vec2 p) {\n"
                      "  float x = p.x;\n";
  for (int i = 0; i < 10000; ++i) calls += "  x = f(x);\n";
  write_file(dir_ / "calls.frag", calls + "  c = vec4(x);\n}\n");
  std::string nested = "float f0(float x) { return x * 1.0001 + 0.1; }\n";
  for (int level = 1; level <= 5; ++level) {
    nested += "float f" + std::to_string(level) + "(float x) {";
    for (int i = 0; i < 10; ++i) nested += " x = f" + std::to_string(level - 1) + "(x);";
    nested += " return x; }\n";
  }
  write_file(dir_ / "nested.frag", nested + "void mainImage(out vec4 c, in vec2 p) { c = vec4(f5(p.x)); }\n");
  // 10,000 variables, each with an if: shallow, but validation copied every
  // variable's depth at each if, and took glslang's worker past its 5 s.
  std::string ifs = "uniform float u;\nvoid mainImage(out vec4 c, in vec2 f) {\n";
  for (int i = 0; i < 10000; ++i) {
    const std::string x = "x" + std::to_string(i);
    ifs += "  float " + x + " = u * " + std::to_string(i) + ".0; if (" + x + " > 3.0) " + x + " -= 1.0;\n";
  }
  write_file(dir_ / "ifs.frag", ifs + "  c = vec4(x0 + x9999);\n}\n");
  const std::string past = "; at most 5000 are allowed (the GL driver inlines the calls, puts each expression in place "
                           "of its variable, and recurses on the tree)";
  run_table({
      {path("variables.frag"), 1, "variables.frag:2502: error: a value computed 14004 operations deep, through "
                                  "variables and calls" + past},
      {path("calls.frag"), 1, "calls.frag:1670: error: a value computed 30006 operations deep"},
      {path("nested.frag"), 1, "nested.frag:5: error: a value computed 311117 operations deep"},
      {path("fewer.frag"), 0, ""},
      {path("ifs.frag"), 0, ""},
  });
  for (const char* name : {"variables.frag", "nested.frag"})
    expect_case("render -o " + path("chain.png") + " --size 8x8", {path(name), 1, "operations deep"});
  EXPECT_FALSE(std::filesystem::exists(dir_ / "chain.png"));
}

TEST_F(Pathological, ManyIncludesOfOneFile) {
  std::string includes;
  for (int i = 0; i < 100000; ++i) includes += "#include \"one.glsl\"\n";
  write_file(dir_ / "one.glsl", "const float ONE = 1.0;\n");
  write_file(dir_ / "includes.frag", includes + "void mainImage(out vec4 c, in vec2 f) { c = vec4(ONE); }\n");
  run_table({{path("includes.frag"), 0, ""}});
}

TEST_F(Pathological, NulBytesAndInvalidUtf8) {
  write_file(dir_ / "nul_code.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0);" + std::string(1, '\0') + " }\n");
  write_file(dir_ / "nul_comment.frag", "// a " + std::string(1, '\0') + " in a comment\n" + kMain);
  write_file(dir_ / "utf8_code.frag", "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); \xff\xfe }\n");
  write_file(dir_ / "utf8_comment.frag", "// caf\xc3 \xff\xfe\n" + kMain);
  run_table({
      {path("nul_code.frag"), 1, "nul_code.frag: error: not a text file (it contains NUL bytes)"},
      {path("nul_comment.frag"), 1, "nul_comment.frag: error: not a text file (it contains NUL bytes)"},
      // glslang quotes the byte; it prints escaped, so the line stays clean.
      {path("utf8_code.frag"), 1, "utf8_code.frag:1: error: '\\x"},
      {path("utf8_comment.frag"), 0, ""},
  });
}

TEST_F(Pathological, FilesThatAreNotRegularFiles) {
  std::filesystem::create_symlink("loop_b.frag", dir_ / "loop_a.frag");
  std::filesystem::create_symlink("loop_a.frag", dir_ / "loop_b.frag");
  ASSERT_EQ(mkfifo(path("fifo.glsl").c_str(), 0644), 0);
  std::filesystem::create_directories(dir_ / "adir");
  auto includer = [&](const std::string& name, const std::string& target) {
    write_file(dir_ / name, "#include \"" + target + "\"\n" + kMain);
    return path(name);
  };
  write_file(dir_ / "good.frag", kMain);
  const std::string good = path("good.frag");
  const std::string render = "render " + good + " -o " + path("out.png") + " --size 8x8 --channel0 ";
  run_table({
      {path("loop_a.frag"), 2, "loop_a.frag': is a symbolic link loop"},
      {includer("fifo.frag", "fifo.glsl"), 1, "fifo.frag:1:10: error: cannot read include '" + path("fifo.glsl") +
                                                  "': is a named pipe (FIFO), not a regular file"},
      {includer("zero.frag", "/dev/zero"), 1, "zero.frag:1:10: error: cannot read include '/dev/zero': is a character device"},
      {includer("dir.frag", "adir"), 1, "dir.frag:1:10: error: cannot read include '" + path("adir") + "': is a directory"},
      {path("fifo.glsl"), 2, "fifo.glsl': is a named pipe (FIFO), not a regular file"},
      {"/dev/zero", 2, "'/dev/zero': is a character device"},
  });
  for (const auto& [image, says] : std::vector<std::pair<std::string, std::string>>{
           {path("fifo.glsl"), "is a named pipe (FIFO), not a regular file"},
           {"/dev/zero", "is a character device, not a regular file"},
           {path("adir"), "is a directory"}}) {
    const test::Outcome r = test::run_binary(render + image);
    EXPECT_EQ(r.status, 2) << image << "\n" << r.err;
    EXPECT_EQ(r.err, "raymarching: error: --channel0 '" + image + "': " + says + "\n");
  }
  // Cube maps and volumes go through the same check as flat images.
  ASSERT_EQ(mkfifo(path("sky.png").c_str(), 0644), 0);
  ASSERT_EQ(mkfifo(path("noise.bin").c_str(), 0644), 0);
  for (const std::string shape : {"sky.png\" cube", "noise.bin\" volume"}) {
    const std::string file = shape.substr(0, shape.find('"'));
    write_file(dir_ / "shaped.frag", "#pragma channel0 \"" + shape + "\n" + kMain);
    const test::Outcome r = test::run_binary("render " + path("shaped.frag") + " -o " + path("out.png") + " --size 8x8");
    EXPECT_EQ(r.status, 2) << shape << "\n" << r.err;
    EXPECT_EQ(r.err, "raymarching: error: iChannel0 of shaped.frag '" + path(file) +
                         "': is a named pipe (FIFO), not a regular file\n");
  }
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out.png"));
}

// What no real shader or image reaches is refused by its size, before it is read.
// A picture larger than the memory there is (4 GiB of floats for the
// largest --size, under a 3 GB limit of address space), or a channel image:
// one line, exit 2, nothing written. Both used to abort on std::bad_alloc. ASan reserves more
// address space than the limit allows, so a sanitized build does not run it.
#ifndef RM_SANITIZED
TEST_F(Pathological, APictureLargerThanTheMemoryIsOneLine) {
  write_file(dir_ / "white.frag", kMain);
  const test::Outcome r = test::run_binary(
      "render " + path("white.frag") + " -o " + path("big.png") + " --size 16384x16384", "ulimit -v 3000000; ");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err, "raymarching: error: not enough memory to render 16384x16384 pixels (4096 MiB a picture as "
                   "floats)\n");
  EXPECT_FALSE(std::filesystem::exists(dir_ / "big.png"));

  // A channel image within the size limit, but more than that memory as
  // floats (16384x8192: 3.5 GiB): a black PPM, its pixels a hole in the file.
  {
    std::ofstream ppm(dir_ / "huge.ppm", std::ios::binary);
    ppm << "P6\n16384 8192\n255\n";
  }
  std::filesystem::resize_file(dir_ / "huge.ppm", std::filesystem::file_size(dir_ / "huge.ppm") + 16384ull * 8192 * 3);
  const test::Outcome channel = test::run_binary("render " + path("white.frag") + " -o " + path("small.png") +
                                                     " --size 16x9 --channel0 " + path("huge.ppm"),
                                                 "ulimit -v 3000000; ");
  EXPECT_EQ(channel.status, 2) << channel.err;
  EXPECT_NE(channel.err.find("'" + path("huge.ppm") + "': not enough memory to read its pixels\n"), std::string::npos)
      << channel.err;
  EXPECT_EQ(std::count(channel.err.begin(), channel.err.end(), '\n'), 1) << channel.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "small.png"));
}

// Under an address-space limit too small for llvmpipe, Mesa cannot map its
// driver and says "No such file or directory": the host's line names the
// limit, not a missing package. (On 2026-12-06, with one malloc arena under
// a limit, a video rendered from 475 MB; from 275 to 375 MB Mesa mapped its
// driver but, with too little room left to make a context in, crashed
// making it, until the host asked for that room first.)
TEST_F(Pathological, AnAddressSpaceLimitTooSmallForTheDriverIsNamed) {
  write_file(dir_ / "white.frag", kMain);
  // A video needs no image module (core/image_codecs.h): the driver is the first to want more.
  const test::Outcome r = test::run_binary(
      "render " + path("white.frag") + " -o " + path("out.mp4") + " --frames 1 --size 16x8", "ulimit -v 300000; ");
  EXPECT_EQ(r.status, 2) << r.err;
  const std::string last = r.err.substr(r.err.rfind('\n', r.err.size() - 2) + 1);
  EXPECT_EQ(last, "raymarching: error: no EGL display offers an OpenGL 4.5 core context within this process's "
                  "address-space limit (ulimit -v 300000 KiB; with Mesa's llvmpipe a render needs about 1 GiB)\n")
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out.mp4"));
  // A picture's image module is loaded first, and under this limit cannot be.
  const test::Outcome png =
      test::run_binary("render " + path("white.frag") + " -o " + path("out.png") + " --size 16x9", "ulimit -v 400000; ");
  EXPECT_EQ(png.status, 2) << png.err;
  EXPECT_EQ(png.err.rfind("raymarching: error: cannot load the image module within this process's address-space limit "
                          "(ulimit -v 400000 KiB): ",
                          0),
            0u)
      << png.err;
  EXPECT_EQ(std::count(png.err.begin(), png.err.end(), '\n'), 1) << png.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out.png"));
}

// Between a limit too small to load anything and one large enough, each
// part of the process runs out in turn, and each says so in its own way. On
// this machine (2026-11-29), 790-810 MB ended in log4cplus's std::terminate
// as the image module loaded (134), 1000-1010 MB in a draw that never
// finished (llvmpipe started one of its two threads; a Slurm job would sit
// until its time limit), and 1030 MB in libepoxy's abort at the first GL
// call. Since malloc keeps one arena under a limit (2026-12-06), a render
// needs less: tori's said at 500-675 MB that no EGL display offers a
// context, at 750-850 that the driver has no room to build the shader
// (Mesa's compiler would have crashed), and drew from 875 MB. A video needs
// no image module, and its bands lie lower: at 275-300 MB Mesa crashed as it
// made the context, until the host asked for room first. Every limit must
// end in the picture (or the video), or in one line, status 2 and no file.
// The bands move with the libraries' sizes: the sweeps are fine.
TEST_F(Pathological, EveryAddressSpaceLimitEndsInThePictureOrOneLine) {
  write_file(dir_ / "white.frag", kMain);
  struct Sweep {
    std::string out, options;
    long from, to, step;
  };
  for (const Sweep& sweep : {Sweep{"out.png", "--size 16x9", 770000, 1070000, 10000},
                             Sweep{"out.mp4", "--size 16x8 --frames 1", 200000, 500000, 25000}}) {
    const std::filesystem::path out = dir_ / sweep.out;
    int pictures = 0;
    for (long kib = sweep.from; kib <= sweep.to; kib += sweep.step) {
      SCOPED_TRACE(sweep.out + " under ulimit -v " + std::to_string(kib));
      // --timeout: a hang ends as 124, not as a test that never ends.
      const test::Outcome r =
          test::run_binary("render " + path("white.frag") + " -o " + out.string() + " " + sweep.options + " --timeout 20",
                           "ulimit -v " + std::to_string(kib) + "; ");
      if (r.status == 0) {
        EXPECT_TRUE(std::filesystem::exists(out));
        std::filesystem::remove(out);
        ++pictures;
        continue;
      }
      EXPECT_EQ(r.status, 2) << r.err;
      EXPECT_FALSE(std::filesystem::exists(out));
      // Mesa's loader warns on its own as it fails to map the driver; the host's line is the last and only one.
      const std::vector<std::string> ours = host_lines(r.err);
      ASSERT_EQ(ours.size(), 1u) << r.err;
      EXPECT_EQ(ours[0].rfind("raymarching: error: ", 0), 0u) << r.err;
    }
    EXPECT_GT(pictures, 0) << "no limit in the " << sweep.out << " sweep was large enough for it";
  }
}

// With no thread to be had (out of memory for stacks, or past a limit of
// threads), a command that needs none runs on the caller's stack, and one
// that needs one ends in one line and status 2. Both used to abort (134) on
// an uncaught std::system_error. ASan's runtime must be loaded first, so a
// sanitized build does not preload the library that refuses threads.
TEST_F(Pathological, NoThreadToBeHadIsOneLine) {
  write_file(dir_ / "white.frag", kMain);
  const std::string preload = std::string("LD_PRELOAD=") + RM_NO_THREADS + " ";
  const test::Outcome check = test::run_binary("check " + path("white.frag"), preload);
  EXPECT_EQ(check.status, 0) << check.err;
  EXPECT_EQ(check.err, "");

  // render's guard of --timeout and signals is a thread of its own.
  const test::Outcome render =
      test::run_binary("render " + path("white.frag") + " -o " + path("out.png") + " --size 16x9", preload);
  EXPECT_EQ(render.status, 2) << render.err;
  EXPECT_EQ(render.err, "raymarching: error: a thread could not be started: Resource temporarily unavailable (out "
                        "of memory or of threads)\n");
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out.png"));
}
#endif

// Whether this test process now has a mount namespace of its own, where a
// test may mount a file system that nothing outside sees (needs root).
bool own_mount_namespace() {
  static const bool own = unshare(CLONE_NEWNS) == 0 && mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) == 0;
  return own;
}

// A disk of 64 KiB (16 pages), for real: a tmpfs made at `at` in a mount
// namespace of this test process's own, unmounted when it goes. False where
// the process cannot have a namespace of its own (the test skips: `why()`);
// a mount that fails in a namespace of its own is a test failure.
class SmallDisk {
 public:
  explicit SmallDisk(const std::filesystem::path& at, unsigned long flags = 0) : at_(at) {
    std::filesystem::create_directory(at_);
    if (!own_mount_namespace()) {
      why_ = std::string("no mount namespace of its own (needs root): ") + std::strerror(errno);
      return;
    }
    mounted_ = mount("tmpfs", at_.c_str(), "tmpfs", flags, "size=64k") == 0;
    if (!mounted_) ADD_FAILURE() << "cannot mount a tmpfs at " << at_ << ": " << std::strerror(errno);
  }
  ~SmallDisk() {
    if (mounted_) umount2(at_.c_str(), MNT_DETACH);
  }
  explicit operator bool() const { return mounted_; }
  const std::string& why() const { return why_; }

 private:
  std::filesystem::path at_;
  bool mounted_ = false;
  std::string why_;
};

// The names in `dir`, sorted.
std::vector<std::string> names_in(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// A full disk, for real: a 64 KiB tmpfs, mounted in a mount namespace of
// this test process's own (nothing outside sees it). ffmpeg 5 exits 0 when
// its last write fails ("Error writing trailer of ...: No space left on
// device"), and the cut video was renamed into place with status 0. Every
// output must now end in status 2 and one line that names the file the
// person asked for, and leave nothing on the disk: no temporary, no part of
// a file, and a file already there keeps its bytes. An import wrote the
// files of a project that fitted and left the rest out.
TEST_F(Pathological, AFullDiskLeavesNothingAndSaysSo) {
  write_file(dir_ / "white.frag", kMain);
  write_file(dir_ / "noise.frag",  // a picture that does not compress
             "void mainImage(out vec4 c, in vec2 f) { c = vec4(fract(sin(dot(f, vec2(12.9898, 78.233)) + "
             "iTime) * 43758.5453)); }\n");
  const std::filesystem::path disk = dir_ / "disk";
  const SmallDisk mounted(disk);
  if (!mounted) GTEST_SKIP() << mounted.why();
  write_file(disk / "kept.png", "the bytes of an older picture");
  const std::vector<std::pair<std::string, std::string>> outputs = {
      {"out.mp4", "--size 640x360 --frames 40"},
      {"out.webm", "--size 640x360 --frames 40"},
      {"out.gif", "--size 320x180 --frames 20"},
      {"out.exr", "--size 320x180"},
      {"kept.png", "--size 320x180"},
      {"frame%03d.png", "--size 320x180 --frames 3"},
  };
  for (const auto& [out, args] : outputs) {
    SCOPED_TRACE("render -o " + out + " " + args);
    const test::Outcome r = test::run_binary("render " + path("noise.frag") + " -o " + (disk / out).string() + " " + args);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
    const std::string named = (disk / (out.find('%') != std::string::npos ? "frame000.png" : out)).string();
    EXPECT_NE(r.err.find(named + "':"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find(".tmp"), std::string::npos) << r.err;  // not the temporary's name
    EXPECT_EQ(names_in(disk), std::vector<std::string>{"kept.png"});
    EXPECT_EQ(test::read_file(disk / "kept.png"), "the bytes of an older picture");
  }
  // A project's files, with one page of the disk left: all of them or none,
  // and the folders the import made are gone again.
  write_file(disk / "filler", std::string(14 * 4096, 'x'));
  const test::Outcome r = test::run_binary("import " + std::string(RM_TEST_DATA_DIR) + "/shadertoy/cube_pass.json " +
                                           (disk / "made/project").string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(disk / "made")) << "a half-imported project";
}

// An accuracy report is four files: on a full disk it is written whole or
// not at all, and an older report in the folder keeps all of its files (a
// new reference.png beside an old table would mislead).
TEST_F(Pathological, AnAccuracyReportOnAFullDiskKeepsTheOlderOne) {
  write_file(dir_ / "ball.frag", "#include <rm/sdf.glsl>\n#include <rm/render.glsl>\n"
                                 "float map(vec3 p) { return min(sdSphere(p, 1.0), p.y + 1.0); }\n"
                                 "RmMaterial material(vec3 p, vec3 n) { return rmMaterial(vec3(0.8)); }\n"
                                 "void mainImage(out vec4 c, in vec2 f) {\n"
                                 "  RmCamera cam = rmLookAt(vec3(0.0, 1.0, 5.0), vec3(0.0), 0.8);\n"
                                 "  c = vec4(rmRenderPixel(cam, f, iResolution), 1.0);\n}\n");
  const std::filesystem::path disk = dir_ / "disk";
  const SmallDisk mounted(disk);
  if (!mounted) GTEST_SKIP() << mounted.why();
  const std::vector<std::string> report = {"accuracy.csv", "accuracy.svg", "reference.png", "steps.png"};
  for (const std::string& name : report) write_file(disk / name, "older " + name);
  write_file(disk / "filler", std::string(10 * 4096, 'x'));  // two pages left of sixteen
  const test::Outcome r =
      test::run_binary("accuracy " + path("ball.frag") + " --size 32x18 --out " + disk.string());
  EXPECT_EQ(r.status, 2) << r.err;
  const std::string last = r.err.substr(r.err.rfind('\n', r.err.size() - 2) + 1);
  EXPECT_NE(last.find("No space left on device"), std::string::npos) << r.err;
  EXPECT_EQ(last.find(".tmp"), std::string::npos) << r.err;
  EXPECT_EQ(names_in(disk), (std::vector<std::string>{"accuracy.csv", "accuracy.svg", "filler", "reference.png", "steps.png"}));
  for (const std::string& name : report) EXPECT_TRUE(test::read_file(disk / name) == "older " + name) << name << " replaced";
}

// A read-only file system, for real (root may write anywhere else, so the
// tests stood a file in for it): each output is refused before anything is
// drawn, in one line that says why.
TEST_F(Pathological, AReadOnlyDiskIsRefusedWithItsReason) {
  write_file(dir_ / "white.frag", kMain);
  const std::filesystem::path disk = dir_ / "read-only";
  const SmallDisk mounted(disk, MS_RDONLY);
  if (!mounted) GTEST_SKIP() << mounted.why();
  const std::string render = "render " + path("white.frag") + " -o " + disk.string();
  const std::vector<std::pair<std::string, std::string>> commands = {
      {render + "/a.png --size 16x9", "is not writable: read-only file system"},
      {render + "/a.mp4 --size 16x8 --frames 2", "is not writable: read-only file system"},
      {"import " + std::string(RM_TEST_DATA_DIR) + "/shadertoy/cube_pass.json " + (disk / "p").string(),
       "cannot create the directory: read-only file system"},
  };
  for (const auto& [command, says] : commands) {
    SCOPED_TRACE(command);
    const test::Outcome r = test::run_binary(command);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
  }
}

// A small stack limit (ulimit -s 32, in KiB) is the main thread's in each
// process the host starts. The glslang worker built glslang's built-ins and
// read its child's answer on that stack, and crashed on every shader: "the
// glslang worker failed: it was ended by Segmentation fault". It now does
// both on a stack of its own, as the host does its work. ffmpeg's encoder
// threads crash on such a stack in ffmpeg itself, now and then: that must be
// one line that names the signal, with no file left.
TEST_F(Pathological, ASmallStackLimitChecksAndRenders) {
  write_file(dir_ / "white.frag", kMain);
  // Not 16 KiB, the least a thread may have: glibc's loader then overflowed
  // the main thread now and then as the process exited (1 in 40), sorting
  // the libraries, and ASan's pthread_create did as it started.
  for (const std::string kib : {"32", "64"}) {
    SCOPED_TRACE("under ulimit -s " + kib);
    const std::string limit = "ulimit -s " + kib + "; ";
    const test::Outcome check = test::run_binary("check " + path("white.frag"), limit);
    EXPECT_EQ(check.status, 0) << check.err;
    EXPECT_EQ(check.err, "");
    const test::Outcome picture =
        test::run_binary("render " + path("white.frag") + " -o " + path("out.png") + " --size 16x9", limit);
    EXPECT_EQ(picture.status, 0) << picture.err;
    EXPECT_EQ(picture.err, "");
    EXPECT_TRUE(std::filesystem::exists(dir_ / "out.png"));
    std::filesystem::remove(dir_ / "out.png");
    const test::Outcome video = test::run_binary(
        "render " + path("white.frag") + " -o " + path("out.mp4") + " --size 16x8 --frames 2", limit);
    if (video.status == 0) {
      EXPECT_TRUE(std::filesystem::exists(dir_ / "out.mp4"));
      std::filesystem::remove(dir_ / "out.mp4");
      continue;
    }
    EXPECT_EQ(video.status, 2) << video.err;
    // "could not write" or "stopped while writing", as ffmpeg died before or after it read every frame
    EXPECT_EQ(video.err.rfind("raymarching: error: ffmpeg ", 0), 0u) << video.err;
    EXPECT_NE(video.err.find(path("out.mp4") + "' (killed by signal "), std::string::npos) << video.err;
    EXPECT_EQ(std::count(video.err.begin(), video.err.end(), '\n'), 1) << video.err;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "out.mp4"));
  }
}

// Few file descriptors (ulimit -n): each command ends in its output or in
// one line of the host's with status 2, whichever step runs out first
// (Mesa's loader may warn first, where it got as far as its driver). libepoxy aborted
// when it could not open libEGL (ulimit -n 8: "Couldn't open libEGL.so.1",
// status 134), and a glslang worker that could not start was a shader error
// (status 1).
TEST_F(Pathological, EveryFileDescriptorLimitEndsInTheOutputOrOneLine) {
  write_file(dir_ / "white.frag", kMain);
  for (int fds = 4; fds <= 16; ++fds) {
    const std::string limit = "ulimit -n " + std::to_string(fds) + "; ";
    for (const std::string out : {"", "out.png", "out.mp4"}) {
      SCOPED_TRACE("under " + limit + (out.empty() ? "check" : "render -o " + out));
      const std::string args = out.empty() ? "check " + path("white.frag")
                                           : "render " + path("white.frag") + " -o " + path(out) + " --size 16x8" +
                                                 (out == "out.mp4" ? " --frames 2" : "");
      const test::Outcome r = test::run_binary(args, limit);
      const bool written = !out.empty() && std::filesystem::exists(dir_ / out);
      if (r.status == 0) {
        EXPECT_EQ(r.err, "");
        EXPECT_TRUE(out.empty() || written);
      } else {
        EXPECT_EQ(r.status, 2) << r.err;
        // Mesa's loader warns on its own where it got as far as its driver
        // (which step runs out first races with the glslang worker's start).
        const std::vector<std::string> ours = host_lines(r.err);
        EXPECT_EQ(ours.size(), 1u) << r.err;
        // The system's words, or the limit named where a library gives none (Mesa's EGL)
        const std::string said = ours.empty() ? "" : ours.back();
        EXPECT_TRUE(said.find("Too many open files") != std::string::npos ||
                    said.find("limit of open files (" + limit.substr(0, limit.size() - 2) + ")") != std::string::npos)
            << r.err;
        EXPECT_FALSE(written);
      }
      if (!out.empty()) std::filesystem::remove(dir_ / out);
    }
  }
}

TEST_F(Pathological, SizeLimits) {
  const std::string over(16u * 1024 * 1024 + 1, ' ');
  write_file(dir_ / "huge.frag", kMain + over);
  write_file(dir_ / "huge.glsl", over);
  write_file(dir_ / "includes_huge.frag", "#include \"huge.glsl\"\n" + kMain);
  // Two includes under the limit each, over it together.
  write_file(dir_ / "half_a.glsl", std::string(9u << 20, ' '));
  write_file(dir_ / "half_b.glsl", std::string(9u << 20, ' '));
  const std::string halves = "#include \"half_a.glsl\"\n#include \"half_b.glsl\"\n" + kMain;
  write_file(dir_ / "halves.frag", halves);
  const std::string scene_bytes = std::to_string(kMain.size() + over.size());
  const std::string halves_bytes = std::to_string(halves.size() + (18u << 20));
  run_table({
      {path("huge.frag"), 2, "huge.frag': is " + scene_bytes + " bytes, over the 16 MiB limit for shader files"},
      {path("includes_huge.frag"), 1, "includes_huge.frag:1:10: error: cannot read include '" + path("huge.glsl") +
                                          "': is 16777217 bytes, over the 16 MiB limit for shader files"},
      {path("halves.frag"), 1, "halves.frag:2:10: error: cannot read include '" + path("half_b.glsl") +
                                   "': the scene with its includes would be " + halves_bytes + " bytes, over the 16 MiB limit"},
  });
  // An image whose header claims 100000x100000 pixels: 160 GB, had it been read.
  write_file(dir_ / "huge.ppm", "P6\n100000 100000\n255\n" + std::string(64, '\x7f'));
  write_file(dir_ / "good.frag", kMain);
  const test::Outcome r = test::run_binary("render " + path("good.frag") + " -o " + path("out.png") +
                                           " --channel0 " + path("huge.ppm"));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("is 100000x100000 pixels; a channel image may be 1 to 16384 pixels a side"), std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace rm
