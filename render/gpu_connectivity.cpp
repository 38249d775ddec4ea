// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/gpu_connectivity.h"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <string>

#include <epoxy/gl.h>
#include <glm/trigonometric.hpp>

#include "core/base/text.h"
#include "render/gl_buffer.h"
#include "render/shader_library.h"
#include "render/software_gl.h"

namespace render {

namespace {
using Clock = std::chrono::steady_clock;

// The shader reads core::SurfaceTriangle as std430 { vec4 plane; uvec4 corners_component; }, so
// the geometry goes up in one copy.
static_assert(sizeof(core::SurfaceTriangle) == 32);
static_assert(offsetof(core::SurfaceTriangle, plane) == 0);
static_assert(offsetof(core::SurfaceTriangle, corners) == 16);
static_assert(offsetof(core::SurfaceTriangle, component) == 28);
static_assert(sizeof(float) == 4 && std::numeric_limits<float>::is_iec559);
// The shader packs a fragment's four link bytes into one word, lowest byte first.
static_assert(std::endian::native == std::endian::little);

constexpr std::size_t kGroupSize = 64; // local_size_x of connectivity.comp
// From core/connectivity.cpp's Linker: the grazing limit, |cos| between ray and normal.
constexpr float kMinRayCosine = 0.01f;

enum Binding : GLuint {
    kOffsets = 0,
    kDepths = 1,
    kFragmentTriangles = 2,
    kTriangles = 3,
    kLinks = 4,
    kFragmentPixels = 5,
    kBindingCount = 6,
};

/**
 * A shader storage buffer that only grows. Inputs the shader gathers from live in GPU memory and
 * are uploaded with glNamedBufferSubData; the two streamed in order (the fragments' pixels, which
 * the CPU writes as it checks the offsets, and the links it reads back) are persistently and
 * coherently mapped, so neither needs a copy of its own.
 */
struct Buffer : GlBuffer {
    bool reserve(std::size_t size, GLbitfield mapping) {
        // A little headroom, so a view with a few more fragments does not reallocate.
        return GlBuffer::reserve(size, std::max<std::size_t>(size + size / 8, 64), mapping);
    }
};

/** One compute() call: its input, the sizes of its buffers and its dispatch. */
struct ConnectivityJob {
    const core::DepthStack& stack;
    const core::ConnectivityOptions& options;
    const core::SurfaceGeometry* geometry = nullptr;
    bool surface = false; // the Surface test, with the geometry it reads
    std::size_t fragments = 0, triangles = 0, pixels = 0;
    // One invocation per fragment, in rows of at most maxGroups[0] groups.
    std::size_t groups = 0, groupsX = 0, groupsY = 0;
    std::array<std::size_t, kBindingCount> bytes{}; // per binding
};

} // namespace

const char* connectivityBackendName(ConnectivityBackend backend) {
    switch (backend) {
    case ConnectivityBackend::Cpu:
        return "cpu";
    case ConnectivityBackend::Gpu:
        return "gpu";
    case ConnectivityBackend::Auto:
        break;
    }
    return "auto";
}

std::optional<ConnectivityBackend> parseConnectivityBackend(std::string_view name) {
    const std::string key = core::asciiLower(name);
    for (ConnectivityBackend backend :
         {ConnectivityBackend::Auto, ConnectivityBackend::Cpu, ConnectivityBackend::Gpu})
        if (key == connectivityBackendName(backend))
            return backend;
    return std::nullopt;
}

ConnectivityBackend resolveConnectivityBackend(ConnectivityBackend requested,
                                               bool softwareRenderer) {
    if (requested != ConnectivityBackend::Auto)
        return requested;
    return softwareRenderer ? ConnectivityBackend::Cpu : ConnectivityBackend::Gpu;
}

struct GpuConnectivity::Impl {
    ShaderProgram program;
    GLint size = -1, fragmentCount = -1, rowInvocations = -1, triangleCount = -1, limit = -1,
          contactLimit = -1, creaseCos = -1, smoothCos = -1, minRayCosine2 = -1, fail = -1;
    std::array<GLint, 6> rays{}; // origin0, originDx, originDy, direction0, directionDx, ...Dy
    std::size_t maxBufferBytes = 0;
    GLint maxGroups[2] = {0, 0};
    std::array<Buffer, kBindingCount> buffers;

    void freeBuffers() {
        for (Buffer& buffer : buffers)
            buffer.free();
    }

    core::Status planBuffers(ConnectivityJob& job) const;
    core::Status reserveBuffers(const ConnectivityJob& job);
    core::Status writeFragmentPixels(const ConnectivityJob& job, core::Connectivity& out);
    void uploadInputs(const ConnectivityJob& job);
    void setUniforms(const ConnectivityJob& job);
    core::Status dispatch(const ConnectivityJob& job);
    void readLinks(const ConnectivityJob& job, core::Connectivity& out);
};

/** The dispatch's groups and every buffer's size; an Error where the GL's limits are too small. */
core::Status GpuConnectivity::Impl::planBuffers(ConnectivityJob& job) const {
    const std::size_t fragments = job.fragments, triangles = job.triangles;
    job.groups = (fragments + kGroupSize - 1) / kGroupSize;
    job.groupsX = std::min(job.groups, std::size_t(maxGroups[0]));
    job.groupsY = job.groupsX ? (job.groups + job.groupsX - 1) / job.groupsX : 0;
    if (job.groupsY > std::size_t(maxGroups[1]))
        return core::Error{"gpu connectivity: " + std::to_string(fragments) +
                           " fragments need too many compute groups"};
    job.bytes = {(job.pixels + 1) * sizeof(std::uint32_t),
                 fragments * sizeof(float),
                 fragments * sizeof(std::uint32_t),
                 std::max<std::size_t>(triangles, 1) * sizeof(core::SurfaceTriangle),
                 fragments * sizeof(std::uint32_t),
                 fragments * sizeof(std::uint32_t)};
    for (std::size_t b = 0; b < job.bytes.size(); ++b)
        if (job.bytes[b] > maxBufferBytes)
            return core::Error{
                "gpu connectivity: the view's " +
                std::to_string(b == kTriangles ? triangles : fragments) +
                (b == kTriangles ? " triangles" : " fragments") +
                " exceed this OpenGL's storage block size; " +
                (b == kTriangles ? "use a model with fewer triangles" : "make the view smaller")};
    return {};
}

/** Every buffer at its size: the pixels mapped for writing, the links for reading. */
core::Status GpuConnectivity::Impl::reserveBuffers(const ConnectivityJob& job) {
    for (std::size_t b = 0; b < job.bytes.size(); ++b) {
        const GLbitfield mapping = b == kFragmentPixels ? GL_MAP_WRITE_BIT
                                   : b == kLinks        ? GL_MAP_READ_BIT
                                                        : 0;
        if (!buffers[b].reserve(job.bytes[b], mapping)) {
            freeBuffers();
            return core::Error{"gpu connectivity: out of GPU memory"};
        }
    }
    return {};
}

/**
 * The GPU is idle (glFinish before), so the mapping can be written in place. One pass checks that
 * the offsets ascend within the fragments (so every fragment belongs to one pixel and gets its
 * link word written), finds the deepest pixel and gives each fragment its pixel.
 */
core::Status GpuConnectivity::Impl::writeFragmentPixels(const ConnectivityJob& job,
                                                        core::Connectivity& out) {
    const core::DepthStack& stack = job.stack;
    auto* pixelOf = static_cast<std::uint32_t*>(buffers[kFragmentPixels].data);
    std::uint32_t deepest = 0;
    for (std::size_t p = 0; p < job.pixels; ++p) {
        const std::uint32_t begin = stack.offsets[p], end = stack.offsets[p + 1];
        if (end < begin || end > job.fragments)
            return core::Error{"gpu connectivity: the layer stack's offsets do not ascend"};
        deepest = std::max(deepest, end - begin);
        std::fill(pixelOf + begin, pixelOf + end, std::uint32_t(p));
    }
    out.truncated = deepest > core::kMaxLinkedLayers;
    return {};
}

/** The offsets, depths, fragments' triangles and the triangles' planes. */
void GpuConnectivity::Impl::uploadInputs(const ConnectivityJob& job) {
    const core::DepthStack& stack = job.stack;
    const core::SurfaceGeometry* geometry = job.geometry;
    const auto upload = [&](Binding b, const void* data, std::size_t byteCount) {
        glNamedBufferSubData(buffers[b].id, 0, GLsizeiptr(byteCount), data);
    };
    upload(kOffsets, stack.offsets.data(), job.bytes[kOffsets]);
    upload(kDepths, stack.depth.data(), job.bytes[kDepths]);
    if (job.surface && geometry->hasEntries()) {
        // Only the triangles in view are kept (SurfaceGeometry's entries): each fragment names its
        // triangle's entry, which the same-triangle test compares as it would the ids.
        if (geometry->fragmentEntry.size() == job.fragments) {
            upload(kFragmentTriangles, geometry->fragmentEntry.data(),
                   job.bytes[kFragmentTriangles]);
        } else {
            std::vector<std::uint32_t> entries(job.fragments);
            for (std::size_t f = 0; f < job.fragments; ++f)
                entries[f] = geometry->entryOf(stack.triangle[f]);
            upload(kFragmentTriangles, entries.data(), job.bytes[kFragmentTriangles]);
        }
    } else {
        upload(kFragmentTriangles, stack.triangle.data(), job.bytes[kFragmentTriangles]);
    }
    if (job.triangles)
        upload(kTriangles, geometry->triangles.data(),
               job.triangles * sizeof(core::SurfaceTriangle));
}

/** The sizes, the Linker's limits (with the reference's own float arithmetic) and the rays. */
void GpuConnectivity::Impl::setUniforms(const ConnectivityJob& job) {
    const core::ConnectivityOptions& options = job.options;
    const float scale = options.unitScale > 0.0f ? options.unitScale : 1.0f;
    const float limitValue = options.threshold / scale;
    const float contactLimitValue = limitValue * std::max(options.contactFactor, 0.0f);
    const float creaseCosValue =
        std::cos(glm::radians(std::clamp(options.creaseAngleDegrees, 0.0f, 180.0f)));
    const float smoothCosValue =
        std::cos(glm::radians(std::clamp(options.smoothAngleDegrees, 0.0f, 90.0f)));
    const GLuint id = program.id();
    glProgramUniform2i(id, size, job.stack.width, job.stack.height);
    glProgramUniform1ui(id, fragmentCount, GLuint(job.fragments));
    glProgramUniform1ui(id, rowInvocations, GLuint(job.groupsX * kGroupSize));
    glProgramUniform1ui(id, triangleCount, GLuint(job.triangles));
    glProgramUniform1f(id, limit, limitValue);
    glProgramUniform1f(id, contactLimit, contactLimitValue);
    glProgramUniform1f(id, creaseCos, creaseCosValue);
    glProgramUniform1f(id, smoothCos, smoothCosValue);
    glProgramUniform1f(id, minRayCosine2, kMinRayCosine * kMinRayCosine);
    glProgramUniform1f(id, fail, std::numeric_limits<float>::infinity());
    const core::PixelRays pixelRays = job.surface ? job.geometry->rays : core::PixelRays{};
    const glm::vec3* rayVectors[6] = {&pixelRays.origin0,     &pixelRays.originDx,
                                      &pixelRays.originDy,    &pixelRays.direction0,
                                      &pixelRays.directionDx, &pixelRays.directionDy};
    for (std::size_t i = 0; i < rays.size(); ++i)
        glProgramUniform3fv(id, rays[i], 1, &rayVectors[i]->x);
}

/** The compute pass, with the caller's program put back; an Error if GL reports one. */
core::Status GpuConnectivity::Impl::dispatch(const ConnectivityJob& job) {
    GLint previousProgram = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &previousProgram);
    while (glGetError() != GL_NO_ERROR) {
    }
    program.use();
    for (GLuint b = 0; b < kBindingCount; ++b)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, buffers[b].id);
    glDispatchCompute(GLuint(job.groupsX), GLuint(job.groupsY), 1);
    for (GLuint b = 0; b < kBindingCount; ++b)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, 0);
    glUseProgram(GLuint(previousProgram));
    if (const GLenum error = glGetError(); error != GL_NO_ERROR)
        return core::Error{"gpu connectivity: the compute pass failed (GL error " +
                           std::to_string(error) + ")"};
    return {};
}

/** Waits for the pass and copies the links out of their mapping. */
void GpuConnectivity::Impl::readLinks(const ConnectivityJob& job, core::Connectivity& out) {
    // Shader writes reach the persistent mapping once the fence has signalled.
    glMemoryBarrier(GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);
    GLsync fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    while (glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000'000) ==
           GL_TIMEOUT_EXPIRED) {
    }
    glDeleteSync(fence);
    const auto* links = static_cast<const std::uint8_t*>(buffers[kLinks].data);
    out.links.assign(links, links + job.bytes[kLinks]);
}

GpuConnectivity::GpuConnectivity() : m_impl(std::make_unique<Impl>()) {}

GpuConnectivity::~GpuConnectivity() {
    release();
}

core::Status GpuConnectivity::initialize() {
    Impl& d = *m_impl;
    auto program = ShaderProgram::build({"connectivity.comp"});
    if (!program)
        return core::Error{program.error()};
    d.program = std::move(program).value();
    d.program.locate({{&d.size, "uSize"},
                      {&d.fragmentCount, "uFragmentCount"},
                      {&d.rowInvocations, "uRowInvocations"},
                      {&d.triangleCount, "uTriangleCount"},
                      {&d.limit, "uLimit"},
                      {&d.contactLimit, "uContactLimit"},
                      {&d.creaseCos, "uCreaseCos"},
                      {&d.smoothCos, "uSmoothCos"},
                      {&d.minRayCosine2, "uMinRayCosine2"},
                      {&d.fail, "uFail"},
                      {&d.rays[0], "uOrigin0"},
                      {&d.rays[1], "uOriginDx"},
                      {&d.rays[2], "uOriginDy"},
                      {&d.rays[3], "uDirection0"},
                      {&d.rays[4], "uDirectionDx"},
                      {&d.rays[5], "uDirectionDy"}});

    GLint64 maxBlock = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &d.maxGroups[0]);
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 1, &d.maxGroups[1]);
    // Indices in the shader are 32-bit.
    d.maxBufferBytes = std::size_t(std::clamp<GLint64>(maxBlock, 0, GLint64(0xffffffffu)));
    if (d.maxBufferBytes == 0 || d.maxGroups[0] <= 0 || d.maxGroups[1] <= 0) {
        d.program = ShaderProgram();
        return core::Error{"gpu connectivity: OpenGL reports no shader storage or compute groups"};
    }
    return {};
}

bool GpuConnectivity::initialized() const {
    return m_impl->program.valid();
}

core::Result<core::Connectivity> GpuConnectivity::compute(const core::DepthStack& stack,
                                                          const core::ConnectivityOptions& options,
                                                          const core::SurfaceGeometry* geometry,
                                                          double* ms) {
    Impl& d = *m_impl;
    if (ms)
        *ms = 0.0;
    if (!d.program.valid())
        return core::Error{"gpu connectivity: not initialized"};
    core::Connectivity out;
    out.width = stack.width;
    out.height = stack.height;
    const std::size_t fragments = stack.fragmentCount();
    // The reference's answer to a stack without a pixel grid: every link 0.
    if (stack.width <= 0 || stack.height <= 0 || stack.offsets.size() != stack.pixelCount() + 1) {
        out.links.assign(4 * fragments, 0);
        return out;
    }
    if (stack.triangle.size() != fragments || stack.offsets.front() != 0 ||
        stack.offsets.back() != fragments)
        return core::Error{"gpu connectivity: the layer stack's offsets do not match its "
                           "fragments"};
    if (fragments == 0)
        return out;

    ConnectivityJob job{stack, options, geometry};
    job.surface = options.test == core::ConnectionTest::Surface && geometry;
    job.fragments = fragments;
    job.triangles = job.surface ? geometry->triangles.size() : 0;
    job.pixels = stack.pixelCount();
    if (const core::Status planned = d.planBuffers(job); !planned)
        return planned.takeError();

    glFinish();
    const Clock::time_point start = Clock::now();
    if (const core::Status reserved = d.reserveBuffers(job); !reserved)
        return reserved.takeError();
    if (const core::Status written = d.writeFragmentPixels(job, out); !written)
        return written.takeError();
    d.uploadInputs(job);
    d.setUniforms(job);
    if (const core::Status ran = d.dispatch(job); !ran)
        return ran.takeError();
    d.readLinks(job, out);
    if (ms)
        *ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    return out;
}

void GpuConnectivity::release() {
    if (!m_impl)
        return;
    m_impl->freeBuffers();
    m_impl->program = ShaderProgram();
}

core::Connectivity computeConnectivity(ConnectivityBackend backend, GpuConnectivity* gpu,
                                       const core::DepthStack& stack,
                                       const core::ConnectivityOptions& options,
                                       const core::SurfaceGeometry* geometry,
                                       ConnectivityBackend* used) {
    if (gpu && gpu->initialized() &&
        resolveConnectivityBackend(backend, isSoftwareRenderer()) == ConnectivityBackend::Gpu) {
        if (auto links = gpu->compute(stack, options, geometry)) {
            if (used)
                *used = ConnectivityBackend::Gpu;
            return std::move(links).value();
        }
    }
    if (used)
        *used = ConnectivityBackend::Cpu;
    return core::computeConnectivity(stack, options, geometry);
}

GlConnectivityEngine::GlConnectivityEngine(ConnectivityBackend requested)
    : m_backend(resolveConnectivityBackend(requested, isSoftwareRenderer())) {
    if (m_backend == ConnectivityBackend::Gpu) {
        m_gpu = std::make_unique<GpuConnectivity>();
        if (!m_gpu->initialize()) {
            m_gpu.reset();
            m_backend = ConnectivityBackend::Cpu;
        }
    }
}

GlConnectivityEngine::~GlConnectivityEngine() = default;

core::Connectivity GlConnectivityEngine::compute(const core::DepthStack& stack,
                                                 const core::ConnectivityOptions& options,
                                                 const core::SurfaceGeometry* geometry) {
    return computeConnectivity(m_backend, m_gpu.get(), stack, options, geometry);
}

} // namespace render
