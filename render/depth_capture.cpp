// SPDX-License-Identifier: GPL-3.0-or-later
// The GPU side of the capture: its program, buffers and draw, which append every fragment of a
// view to a list (the CPU resolve that sorts the list is in depth_capture_resolve.cpp).
#include "render/depth_capture.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <limits>
#include <string>
#include <thread>
#include <utility>

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include "render/depth_capture_impl.h"
#include "render/mesh_renderer.h"
#include "render/offscreen_target.h"
#include "render/software_gl.h"

namespace render {

namespace {
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

constexpr int kMaxNodeChunks = 8;          // capture.frag's NODE_CHUNKS at most
constexpr std::size_t kMaxNodeRanges = 8;  // capture.frag's uRangeStart[8]
constexpr std::size_t kCounterStride = 16; // words between the ranges' counters: a cache line

/** Saves the GL state the capture changes and puts it back. */
class StateGuard {
public:
    StateGuard() {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &m_framebuffer);
        glGetIntegerv(GL_VIEWPORT, m_viewport);
        glGetIntegerv(GL_CURRENT_PROGRAM, &m_program);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &m_vertexArray);
        glGetIntegerv(GL_CULL_FACE_MODE, &m_cullMode);
        glGetIntegerv(GL_FRONT_FACE, &m_frontFace);
        m_depthTest = glIsEnabled(GL_DEPTH_TEST);
        m_cullFace = glIsEnabled(GL_CULL_FACE);
        m_scissor = glIsEnabled(GL_SCISSOR_TEST);
    }
    ~StateGuard() {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(m_framebuffer));
        glViewport(m_viewport[0], m_viewport[1], m_viewport[2], m_viewport[3]);
        glUseProgram(GLuint(m_program));
        glBindVertexArray(GLuint(m_vertexArray));
        glCullFace(GLenum(m_cullMode));
        glFrontFace(GLenum(m_frontFace));
        setEnabled(GL_DEPTH_TEST, m_depthTest);
        setEnabled(GL_CULL_FACE, m_cullFace);
        setEnabled(GL_SCISSOR_TEST, m_scissor);
    }
    StateGuard(const StateGuard&) = delete;
    StateGuard& operator=(const StateGuard&) = delete;

    static void setEnabled(GLenum cap, bool on) {
        if (on)
            glEnable(cap);
        else
            glDisable(cap);
    }

private:
    GLint m_framebuffer = 0, m_viewport[4] = {}, m_program = 0, m_vertexArray = 0;
    GLint m_cullMode = GL_BACK, m_frontFace = GL_CCW;
    bool m_depthTest = false, m_cullFace = false, m_scissor = false;
};
} // namespace

core::Result<CaptureProgram> buildCaptureProgram(int chunks) {
    std::vector<std::string> defines;
    if (chunks > 1)
        defines.push_back("NODE_CHUNKS " + std::to_string(chunks));
    auto built = ShaderProgram::build({"capture.vert", "capture.frag"}, defines);
    if (!built)
        return core::Error{built.error()};
    CaptureProgram p{std::move(built).value()};
    p.program.locate({{&p.viewLocation, "uView"},
                      {&p.projLocation, "uProj"},
                      {&p.widthLocation, "uWidth"},
                      {&p.heightLocation, "uHeight"},
                      {&p.chunkShiftLocation, "uChunkShift"},
                      {&p.rangeMaskLocation, "uRangeMask"},
                      {&p.rangeStartLocation, "uRangeStart"},
                      {&p.rangeCapacityLocation, "uRangeCapacity"}});
    return p;
}

core::Status DepthCapture::Impl::ensureNodes(std::size_t wanted) {
    if (wanted > maxNodes())
        return core::Error{"layer capture: the view has " + std::to_string(wanted) +
                           " fragments, more than this OpenGL holds (" +
                           std::to_string(maxNodes()) + "); make the view smaller"};
    if (wanted <= capacity && !nodes.empty())
        return {};
    freeNodes();
    const std::size_t chunks = (wanted + chunkNodes() - 1) / chunkNodes();
    nodes.resize(std::max<std::size_t>(chunks, 1));
    for (std::size_t c = 0; c < nodes.size(); ++c) {
        const std::size_t count = std::min(chunkNodes(), wanted - c * chunkNodes());
        if (!nodes[c].allocate(std::max<std::size_t>(count, 1) * kNodeBytes)) {
            freeNodes();
            return core::Error{"layer capture: out of GPU memory for " + std::to_string(wanted) +
                               " fragments; make the view smaller"};
        }
        nodeData.push_back(static_cast<const std::uint32_t*>(nodes[c].data));
    }
    capacity = wanted;
    return {};
}

void DepthCapture::Impl::draw(const core::View& view, const Options& options) {
    const GLuint zero = 0;
    glClearNamedBufferData(counter.id, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    GLuint rangeStart[kMaxNodeRanges] = {}, rangeCapacity[kMaxNodeRanges] = {};
    for (std::size_t r = 0; r < ranges.size(); ++r) {
        rangeStart[r] = GLuint(ranges[r].first);
        rangeCapacity[r] = GLuint(ranges[r].capacity);
    }

    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, view.width, view.height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_SCISSOR_TEST);
    StateGuard::setEnabled(GL_CULL_FACE, options.cullBackFaces);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    const CaptureProgram& p = programs.at(int(nodes.size()));
    p.program.use();
    glUniformMatrix4fv(p.viewLocation, 1, GL_FALSE, glm::value_ptr(view.view));
    glUniformMatrix4fv(p.projLocation, 1, GL_FALSE, glm::value_ptr(view.proj));
    glUniform1i(p.widthLocation, view.width);
    glUniform1i(p.heightLocation, view.height);
    glUniform1ui(p.rangeMaskLocation, GLuint(ranges.size() - 1));
    glUniform1uiv(p.rangeStartLocation, GLsizei(kMaxNodeRanges), rangeStart);
    glUniform1uiv(p.rangeCapacityLocation, GLsizei(kMaxNodeRanges), rangeCapacity);
    glUniform1ui(p.chunkShiftLocation, GLuint(chunkShift));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, counter.id);
    for (std::size_t c = 0; c < nodes.size(); ++c)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(1 + c), nodes[c].id);
    glBindVertexArray(vertexArray);
    const std::size_t triangles = soupVertices / 3;
    const int pieces = drawPieces(software, triangles, std::size_t(view.width) * view.height);
    drawInPieces(0, triangles, pieces, [](std::size_t first, std::size_t count) {
        glDrawArrays(GL_TRIANGLES, GLint(3 * first), GLsizei(3 * count));
    });
    if (options.cullBackFaces && !backFaces.empty())
        drawInPieces(0, backFaces.size(), pieces, [](std::size_t first, std::size_t count) {
            glDrawElements(GL_TRIANGLES, GLsizei(3 * count), GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(3 * first * sizeof(std::uint32_t)));
        });
    for (GLuint binding = 0; binding < GLuint(1 + nodes.size()); ++binding)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);

    // Shader writes reach the persistent mappings once the fence has signalled.
    glMemoryBarrier(GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);
    GLsync fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    while (glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000'000) ==
           GL_TIMEOUT_EXPIRED) {
    }
    glDeleteSync(fence);
}

core::Status DepthCapture::Impl::prepareDraw(const core::View& view) {
    if (view.width != framebufferWidth || view.height != framebufferHeight) {
        glNamedFramebufferParameteri(framebuffer, GL_FRAMEBUFFER_DEFAULT_WIDTH, view.width);
        glNamedFramebufferParameteri(framebuffer, GL_FRAMEBUFFER_DEFAULT_HEIGHT, view.height);
        framebufferWidth = view.width;
        framebufferHeight = view.height;
    }
    const std::size_t counterBytes = ranges.size() * kCounterStride * sizeof(std::uint32_t);
    if (counter.bytes != counterBytes && !counter.allocate(counterBytes))
        return core::Error{"layer capture: out of GPU memory"};
    if (requestedCapacity) {
        capacity = 0; // reallocates to the requested size, smaller or larger
        const core::Status status = ensureNodes(requestedCapacity);
        requestedCapacity = 0;
        if (!status)
            return status;
    } else if (nodes.empty()) {
        // A first guess of two fragments a pixel; a deeper view grows it once.
        const std::size_t pixels = std::size_t(view.width) * std::size_t(view.height);
        if (const core::Status status = ensureNodes(std::min(pixels * 2, maxNodes())); !status)
            return status;
    }
    if (const core::Status status = ensureProgram(); !status)
        return status;
    if (plannedCapacity != capacity)
        planRanges(false);
    return {};
}

core::Result<int> DepthCapture::Impl::drawUntilFits(const core::View& view,
                                                    const Options& options) {
    int recaptures = 0;
    const StateGuard guard;
    for (;;) {
        draw(view, options);
        const auto* counts = static_cast<const volatile std::uint32_t*>(counter.data);
        std::size_t written = 0;
        bool fits = true;
        for (std::size_t r = 0; r < ranges.size(); ++r) {
            NodeRange& range = ranges[r];
            range.written = counts[r * kCounterStride];
            written += range.written;
            fits = fits && range.written <= range.capacity;
        }
        if (fits)
            return recaptures;
        // Lists cut at a range's capacity are incomplete: grow with some headroom if the
        // whole list does not fit, split the nodes as this draw needs them and draw again.
        const std::size_t grown = std::min(maxNodes(), written + written / 8);
        if (const core::Status status = ensureNodes(std::max(grown, written)); !status)
            return core::Error{status.error()};
        if (const core::Status status = ensureProgram(); !status)
            return core::Error{status.error()};
        planRanges(true);
        ++recaptures;
        ++totalRecaptures;
    }
}

DepthCapture::DepthCapture() : m_impl(std::make_unique<Impl>()) {}

DepthCapture::~DepthCapture() {
    release();
}

core::Status DepthCapture::initialize() {
    Impl& d = *m_impl;
    d.software = isSoftwareRenderer();
    auto program = buildCaptureProgram(1);
    if (!program)
        return core::Error{program.error()};
    d.programs.clear();
    d.programs.emplace(1, std::move(program).value());

    GLint64 maxBlock = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
    GLint fragmentBlocks = 0, bindings = 0;
    glGetIntegerv(GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS, &fragmentBlocks);
    glGetIntegerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, &bindings);
    // The counter takes one block; the rest can hold node chunks.
    d.maxChunks = std::clamp(std::min(fragmentBlocks, bindings) - 1, 1, kMaxNodeChunks);
    glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &d.maxFramebufferWidth);
    glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &d.maxFramebufferHeight);
    // Node indices are 32-bit with 0xffffffff as "none"; offsets are 32-bit too.
    d.maxBufferBytes = std::size_t(
        std::clamp<GLint64>(maxBlock, 0, GLint64(Impl::kNone - 1) * GLint64(Impl::kNodeBytes)));
    if (d.maxBufferBytes < Impl::kNodeBytes || d.maxFramebufferWidth <= 0 ||
        d.maxFramebufferHeight <= 0)
        return core::Error{"layer capture: OpenGL reports no shader storage or framebuffer size"};
    d.planChunks();
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    // A node range for each rasterizer thread llvmpipe may run (one a core).
    d.setRanges(d.software ? std::min<std::size_t>(std::bit_ceil(cores), kMaxNodeRanges) : 1);
    if (!d.framebuffer)
        glCreateFramebuffers(1, &d.framebuffer);
    if (!d.pool)
        d.pool = std::make_unique<BandPool>(std::clamp(int(cores) - 1, 0, 15));
    return {};
}

void DepthCapture::setMesh(const core::Mesh& mesh) {
    if (const std::function<void()> fill = beginMesh(mesh)) {
        fill();
        finishMesh();
    }
}

std::function<void()> DepthCapture::beginMesh(const core::Mesh& mesh) {
    Impl& d = *m_impl;
    d.releaseMesh();
    const std::size_t triangles = mesh.triangleCount();
    if (triangles == 0 || triangles > std::size_t(std::numeric_limits<GLsizei>::max() / 3))
        return {};
    // Written straight into the buffer: no copy of the soup is kept or made on the CPU.
    const std::size_t corners = triangles * 3;
    const auto bytes = GLsizeiptr(corners * sizeof(glm::vec3));
    glCreateBuffers(1, &d.positions);
    glNamedBufferStorage(d.positions, bytes, nullptr, GL_MAP_WRITE_BIT);
    auto* soup = static_cast<glm::vec3*>(glMapNamedBufferRange(
        d.positions, 0, bytes, GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT));
    if (!soup) {
        d.releaseMesh();
        return {};
    }
    d.pendingVertices = corners;
    d.pendingFilled = false;
    return [&mesh, soup, corners, filled = &d.pendingFilled] {
        for (std::size_t i = 0; i < corners; ++i) {
            const std::uint32_t v = mesh.indices[i];
            soup[i] = v < mesh.positions.size() ? mesh.positions[v] : glm::vec3(0.0f);
        }
        *filled = true;
    };
}

void DepthCapture::finishMesh() {
    Impl& d = *m_impl;
    if (!d.pendingVertices)
        return;
    const std::size_t corners = std::exchange(d.pendingVertices, 0);
    if (glUnmapNamedBuffer(d.positions) != GL_TRUE || !d.pendingFilled) {
        d.releaseMesh(); // the soup was lost, or never written whole
        return;
    }
    glCreateVertexArrays(1, &d.vertexArray);
    glVertexArrayVertexBuffer(d.vertexArray, 0, d.positions, 0, sizeof(glm::vec3));
    glEnableVertexArrayAttrib(d.vertexArray, 0);
    glVertexArrayAttribFormat(d.vertexArray, 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(d.vertexArray, 0, 0);
    d.soupVertices = corners;
}

void DepthCapture::Impl::useBackFaces(std::span<const std::uint32_t> triangles) {
    if (std::equal(triangles.begin(), triangles.end(), backFaces.begin(), backFaces.end()))
        return;
    if (backFaceElements)
        glDeleteBuffers(1, &backFaceElements);
    backFaceElements = 0;
    backFaces.clear();
    std::vector<std::uint32_t> elements;
    elements.reserve(triangles.size() * 3);
    for (const std::uint32_t t : triangles)
        if (t < soupVertices / 3) {
            backFaces.push_back(t);
            elements.insert(elements.end(), {3 * t, 3 * t + 2, 3 * t + 1});
        }
    if (elements.empty())
        return;
    glCreateBuffers(1, &backFaceElements);
    glNamedBufferStorage(backFaceElements, GLsizeiptr(elements.size() * sizeof(std::uint32_t)),
                         elements.data(), 0);
    glVertexArrayElementBuffer(vertexArray, backFaceElements);
}

bool DepthCapture::hasMesh() const {
    return m_impl->soupVertices > 0;
}

core::Result<core::DepthStack> DepthCapture::capture(const core::View& view, const Options& options,
                                                     Timings* timings) {
    Impl& d = *m_impl;
    if (timings)
        *timings = Timings{};
    if (d.programs.empty() || !d.framebuffer || !d.pool)
        return core::Error{"layer capture: not initialized"};
    if (view.width < 1 || view.height < 1 || view.width > d.maxFramebufferWidth ||
        view.height > d.maxFramebufferHeight)
        return core::Error{"layer capture: size " + std::to_string(view.width) + "x" +
                           std::to_string(view.height) + " is not supported (maximum " +
                           std::to_string(d.maxFramebufferWidth) + "x" +
                           std::to_string(d.maxFramebufferHeight) + ")"};
    const std::size_t pixels = std::size_t(view.width) * std::size_t(view.height);
    if (d.soupVertices == 0) {
        core::DepthStack empty;
        empty.width = view.width;
        empty.height = view.height;
        empty.offsets.assign(pixels + 1, 0);
        return empty;
    }

    const Clock::time_point start = Clock::now();
    if (const core::Status status = d.prepareDraw(view); !status)
        return core::Error{status.error()};
    d.useBackFaces(options.shownBackFaces);
    const core::Result<int> recaptures = d.drawUntilFits(view, options);
    if (!recaptures)
        return core::Error{recaptures.error()};
    const double gpuMs = msSince(start);

    const Clock::time_point resolveStart = Clock::now();
    core::Result<core::DepthStack> stack = d.resolve(view, timings);
    if (!stack)
        return stack;
    if (timings) {
        timings->gpuMs = gpuMs;
        timings->resolveMs = msSince(resolveStart);
        timings->recaptures = *recaptures;
    }
    return stack;
}

std::size_t DepthCapture::nodeCapacity() const {
    return m_impl->capacity;
}

void DepthCapture::setNodeCapacity(std::size_t nodes) {
    m_impl->requestedCapacity = std::max<std::size_t>(nodes, 1);
}

void DepthCapture::setStorageBlockCap(std::size_t bytes) {
    Impl& d = *m_impl;
    d.blockCap = bytes;
    d.freeNodes();
    d.planChunks();
}

void DepthCapture::setNodeRanges(std::size_t count) {
    m_impl->setRanges(std::clamp<std::size_t>(std::bit_floor(std::max<std::size_t>(count, 1)), 1,
                                              kMaxNodeRanges));
}

std::size_t DepthCapture::nodeRanges() const {
    return m_impl->ranges.size();
}

std::size_t DepthCapture::nodeChunks() const {
    return m_impl->nodes.size();
}

int DepthCapture::totalRecaptures() const {
    return m_impl->totalRecaptures;
}

void DepthCapture::release() {
    if (!m_impl)
        return;
    Impl& d = *m_impl;
    d.counter.free();
    d.freeNodes();
    d.releaseMesh();
    if (d.framebuffer)
        glDeleteFramebuffers(1, &d.framebuffer);
    d.framebuffer = 0;
    d.framebufferWidth = d.framebufferHeight = 0;
    d.programs.clear();
    d.pool.reset();
    d.bands.clear();
    d.sliceCounts.clear();
    d.pixelInBand = {};
}

double timePlainPass(MeshRenderer& renderer, const OffscreenTarget& target, const core::View& view,
                     const DrawOptions& options) {
    target.bind();
    glFinish();
    const Clock::time_point start = Clock::now();
    renderer.draw(view, options);
    glFinish();
    return msSince(start);
}

} // namespace render
