// Shadertoy's HW_PERFORMANCE by renderer: 0 for one on the CPU, unless a -D
// sets it; then the preprocessor takes the phone's branch of a shader.
#include "core/hw_performance.h"

#include <gtest/gtest.h>

#include "core/check.h"
#include "support.h"

namespace rm {
namespace {

TEST(HwPerformance, RenderersOnTheCpuAreSoftware) {
  for (const char* cpu : {"llvmpipe (LLVM 15.0.6, 256 bits)", "softpipe", "zink Vulkan 1.3(llvmpipe (LLVM 15.0.6, 256 bits) (MESA_LLVMPIPE))",
                          "Google SwiftShader", "Microsoft Basic Render Driver", "GDI Generic"})
    EXPECT_TRUE(is_software_renderer(cpu)) << cpu;
  for (const char* gpu : {"NVIDIA H100 80GB HBM3/PCIe/SSE2", "AMD Radeon RX 6600 (navi23, LLVM 15.0.6, DRM 3.49, 6.1.0)",
                          "Mesa Intel(R) UHD Graphics 620 (KBL GT2)", "Apple M2", "unknown"})
    EXPECT_FALSE(is_software_renderer(gpu)) << gpu;
}

TEST(HwPerformance, ASoftwareRendererGetsZeroUnlessACommandLineSetsIt) {
  const char* llvmpipe = "llvmpipe (LLVM 15.0.6, 256 bits)";
  SourceOptions none;
  none.defines = {{"FAST", "1"}};
  EXPECT_EQ(for_renderer(none, llvmpipe).defines, (std::vector<Define>{{"FAST", "1"}, {"HW_PERFORMANCE", "0"}}));
  EXPECT_EQ(for_renderer(none, "NVIDIA H100 80GB HBM3/PCIe/SSE2").defines, none.defines);
  SourceOptions desktop;
  desktop.defines = {{"HW_PERFORMANCE", "1"}};
  EXPECT_EQ(for_renderer(desktop, llvmpipe).defines, desktop.defines);

  // The scene sees it as any -D: its phone branch, with no redefinition.
  test::TempDir dir;
  test::write_file(dir / "scene.frag",
                   "void mainImage(out vec4 c, in vec2 f) { c = vec4(HW_PERFORMANCE); }\n"
                   "#if HW_PERFORMANCE == 0\nfloat phone;\n#endif\n");
  const Source source = preprocess(dir / "scene.frag", for_renderer({}, llvmpipe));
  ASSERT_TRUE(source.ok());
  std::string active;
  EXPECT_TRUE(validate(source, &active).empty());
  EXPECT_NE(active.find("float phone"), std::string::npos);
}

}  // namespace
}  // namespace rm
