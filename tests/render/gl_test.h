// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>

#include <gtest/gtest.h>

#include "render/gl_context.h"

namespace render_test {

/** Base of the *_gltest fixtures: one headless EGL context (llvmpipe on CI) per test suite. */
class GlTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        auto context = render::HeadlessContext::create();
        ASSERT_TRUE(context) << context.error();
        s_context = std::move(context).value();
    }
    static void TearDownTestSuite() { s_context.reset(); }

    inline static std::unique_ptr<render::HeadlessContext> s_context;
};

} // namespace render_test
