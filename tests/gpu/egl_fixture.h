// A test suite base that holds one headless EGL context for all its tests,
// and fails any test during which the driver reported a GL error.
#pragma once
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "core/gl_debug.h"
#include "headless/egl_context.h"

namespace rm::test {

class EglTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::string error;
    context() = EglContext::create(&error);
    ASSERT_TRUE(context()) << error;
  }
  static void TearDownTestSuite() { context().reset(); }
  void SetUp() override { gl_errors_before_ = gl_errors_reported(); }
  void TearDown() override {
    EXPECT_EQ(gl_errors_reported(), gl_errors_before_) << "the driver reported GL errors (see stderr)";
  }

 private:
  int gl_errors_before_ = 0;
  static std::unique_ptr<EglContext>& context() {
    static std::unique_ptr<EglContext> instance;
    return instance;
  }
};

}  // namespace rm::test
