// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>
#include <string>

#include "core/base/result.h"

namespace render {

/**
 * A headless OpenGL 4.5 core context on EGL (Mesa's surfaceless platform, no display needed),
 * for the CLI, tests and benchmarks. create() makes it current on the calling thread; it renders
 * only into framebuffer objects.
 */
class HeadlessContext {
public:
    /** Returns the context, or an Error saying why EGL or GL 4.5 is unavailable. */
    static core::Result<std::unique_ptr<HeadlessContext>> create();
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    bool makeCurrent();
    /** GL_RENDERER of the current context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)". */
    static std::string rendererName();

private:
    HeadlessContext() = default;
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace render
