// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/gl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdio>
#include <string>

namespace render {

struct HeadlessContext::Impl {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
};

namespace {
core::Error eglError(const char* what) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", unsigned(eglGetError()));
    return core::Error{std::string("OpenGL: ") + what + " failed (EGL error " + code + ")"};
}
} // namespace

core::Result<std::unique_ptr<HeadlessContext>> HeadlessContext::create() {
    std::unique_ptr<HeadlessContext> self(new HeadlessContext);
    self->m_impl = std::make_unique<Impl>();
    Impl& d = *self->m_impl;

    if (!epoxy_has_egl())
        return core::Error{"OpenGL: libEGL is not available"};
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    const bool surfaceless =
        clientExtensions &&
        std::string(clientExtensions).find("EGL_MESA_platform_surfaceless") != std::string::npos;
    if (surfaceless)
        d.display =
            eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d.display == EGL_NO_DISPLAY)
        d.display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (d.display == EGL_NO_DISPLAY)
        return core::Error{"OpenGL: no EGL display"};
    EGLint major = 0, minor = 0;
    if (!eglInitialize(d.display, &major, &minor))
        return eglError("eglInitialize");
    if (!eglBindAPI(EGL_OPENGL_API))
        return eglError("eglBindAPI");

    EGLConfig config = nullptr;
    if (!epoxy_has_egl_extension(d.display, "EGL_KHR_no_config_context")) {
        const EGLint attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLint count = 0;
        if (!eglChooseConfig(d.display, attributes, &config, 1, &count) || count < 1)
            return eglError("eglChooseConfig");
    }
    const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                        4,
                                        EGL_CONTEXT_MINOR_VERSION,
                                        5,
                                        EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                        EGL_NONE};
    d.context = eglCreateContext(d.display, config, EGL_NO_CONTEXT, contextAttributes);
    if (d.context == EGL_NO_CONTEXT)
        return eglError("creating an OpenGL 4.5 core context");
    if (!self->makeCurrent())
        return eglError("eglMakeCurrent");
    return self;
}

HeadlessContext::~HeadlessContext() {
    if (!m_impl)
        return;
    if (m_impl->display != EGL_NO_DISPLAY) {
        eglMakeCurrent(m_impl->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (m_impl->context != EGL_NO_CONTEXT)
            eglDestroyContext(m_impl->display, m_impl->context);
        // The display is left initialized: other contexts in the process may share it.
    }
}

bool HeadlessContext::makeCurrent() {
    return eglMakeCurrent(m_impl->display, EGL_NO_SURFACE, EGL_NO_SURFACE, m_impl->context);
}

std::string HeadlessContext::rendererName() {
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return name ? name : "";
}

} // namespace render
