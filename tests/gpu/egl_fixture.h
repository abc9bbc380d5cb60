// A test suite base that holds one headless EGL context for all its tests.
#pragma once
#include <gtest/gtest.h>

#include <memory>
#include <string>

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

 private:
  static std::unique_ptr<EglContext>& context() {
    static std::unique_ptr<EglContext> instance;
    return instance;
  }
};

}  // namespace rm::test
