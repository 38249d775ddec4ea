// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/layer_capture.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <mutex>
#include <string>
#include <thread>

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include "render/gl_buffer.h"
#include "render/mesh_renderer.h"
#include "render/offscreen_target.h"
#include "render/shader_library.h"
#include "render/software_gl.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace render {

namespace {
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

constexpr std::uint32_t kEmpty = 0xffffffffu;
constexpr std::size_t kNodeBytes = 3 * sizeof(std::uint32_t); // depth bits, triangle, next
constexpr int kMaxNodeChunks = 8;                             // capture.frag's NODE_CHUNKS at most
constexpr int kBandRows = 8;                                  // rows per resolve work unit
constexpr std::size_t kAhead = 64;                            // prefetch distance, in pixels

void prefetch(const void* address) {
#if defined(__GNUC__)
    __builtin_prefetch(address);
#else
    (void)address;
#endif
}

/** The end of the run of empty heads from `pixel` on, within [pixel, last). */
std::size_t emptyRunEnd(const std::uint32_t* heads, std::size_t pixel, std::size_t last) {
#if defined(__SSE2__)
    // Eight heads at a time: runs around a model are most of a view's pixels.
    const __m128i empty = _mm_set1_epi32(-1);
    for (; pixel + 8 <= last; pixel += 8) {
        const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(heads + pixel));
        const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(heads + pixel + 4));
        const __m128i both = _mm_and_si128(_mm_cmpeq_epi32(a, empty), _mm_cmpeq_epi32(b, empty));
        if (_mm_movemask_epi8(both) != 0xffff)
            break;
    }
#endif
    while (pixel < last && heads[pixel] == kEmpty)
        ++pixel;
    return pixel;
}

// Float bits to an unsigned key with the same order (negative depths included), and back.
std::uint32_t sortableDepth(std::uint32_t bits) {
    return (bits & 0x80000000u) ? ~bits : bits | 0x80000000u;
}
std::uint32_t depthBits(std::uint32_t key) {
    return (key & 0x80000000u) ? key & 0x7fffffffu : ~key;
}

/**
 * One band of rows after the walk: its fragments sorted per pixel as depth key << 32 | triangle.
 * Aligned so that two threads filling neighbouring bands never share a cache line.
 */
struct alignas(64) Band {
    std::vector<std::uint64_t> keys;
    std::vector<std::uint32_t> perLayer;
};

/** The CPU reads the GPU's lists in place. */
struct MappedBuffer : GlBuffer {
    bool allocate(std::size_t size) {
        return GlBuffer::allocate(size, GL_MAP_READ_BIT | GL_MAP_WRITE_BIT);
    }
};

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

/**
 * Worker threads kept for the capture's lifetime. run() shares bands between them and the
 * calling thread and returns as soon as every band is done, without waiting for a worker the OS
 * has not scheduled yet: on a busy 2-core machine a thread started per capture often began
 * milliseconds late, after the calling thread had done all the work alone.
 */
class BandPool {
public:
    explicit BandPool(int workers) {
        for (int i = 0; i < workers; ++i)
            m_threads.emplace_back([this] { workerLoop(); });
    }
    ~BandPool() {
        {
            const std::lock_guard lock(m_mutex);
            m_stop = true;
        }
        m_wake.notify_all();
        for (std::thread& thread : m_threads)
            thread.join();
    }
    BandPool(const BandPool&) = delete;
    BandPool& operator=(const BandPool&) = delete;

    /** Calls work(b) once for every b in [0, count); false if a call threw (out of memory). */
    bool run(int count, const std::function<void(int)>& work) {
        {
            const std::lock_guard lock(m_mutex);
            m_work = &work;
            m_count = count;
            m_next = m_finished = 0;
            m_failed = false;
            ++m_generation;
        }
        m_wake.notify_all();
        drain();
        std::unique_lock lock(m_mutex);
        m_done.wait(lock, [&] { return m_finished == m_count; });
        m_work = nullptr;
        m_count = m_next = 0; // a worker waking late finds nothing to do
        return !m_failed;
    }

private:
    void drain() {
        std::unique_lock lock(m_mutex);
        while (m_next < m_count) {
            const int band = m_next++;
            const std::function<void(int)>* work = m_work;
            lock.unlock();
            bool failed = false;
            try {
                (*work)(band);
            } catch (const std::exception&) {
                failed = true;
            }
            lock.lock();
            m_failed = m_failed || failed;
            if (++m_finished == m_count)
                m_done.notify_all();
        }
    }
    void workerLoop() {
        std::uint64_t seen = 0;
        for (;;) {
            {
                std::unique_lock lock(m_mutex);
                m_wake.wait(lock, [&] { return m_stop || m_generation != seen; });
                if (m_stop)
                    return;
                seen = m_generation;
            }
            drain();
        }
    }

    std::mutex m_mutex;
    std::condition_variable m_wake, m_done;
    const std::function<void(int)>* m_work = nullptr;
    int m_count = 0, m_next = 0, m_finished = 0;
    bool m_failed = false, m_stop = false;
    std::uint64_t m_generation = 0;
    std::vector<std::thread> m_threads;
};
} // namespace

/** capture.vert + capture.frag for a number of node chunks, and its uniforms. */
struct CaptureProgram {
    ShaderProgram program;
    GLint viewLocation = -1, projLocation = -1;
    GLint widthLocation = -1, heightLocation = -1, capacityLocation = -1, chunkShiftLocation = -1;
};

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
                      {&p.capacityLocation, "uCapacity"},
                      {&p.chunkShiftLocation, "uChunkShift"}});
    return p;
}

struct LayerCapture::Impl {
    std::map<int, CaptureProgram> programs; // by node chunks; 1 built by initialize()
    // The mesh as a triangle soup: 3 positions a triangle, in triangle order.
    GLuint vertexArray = 0, positions = 0;
    std::size_t soupVertices = 0;
    GLuint framebuffer = 0; // no attachments, only a default size
    int framebufferWidth = 0, framebufferHeight = 0;
    GLint maxFramebufferWidth = 0, maxFramebufferHeight = 0;
    std::size_t maxBufferBytes = 0;
    std::size_t blockCap = 0; // setStorageBlockCap(): 0 for none
    int maxChunks = 1;        // node chunks the GL's storage bindings allow
    unsigned chunkShift = 0;  // a chunk holds 2^chunkShift nodes

    // The nodes are split into chunks of 2^chunkShift nodes (the last one shorter), each its own
    // storage block: one block caps a buffer, not the list. A list that fits one chunk is one
    // buffer as large as it needs.
    MappedBuffer counter, heads;
    std::vector<MappedBuffer> nodes;
    std::vector<const std::uint32_t*> nodeData; // each chunk's mapping
    std::size_t capacity = 0;                   // nodes that fit in `nodes`
    std::size_t requestedCapacity = 0;          // from setNodeCapacity, applied at the next capture
    bool headsEmpty = false;                    // every head is kEmpty (the resolve resets them)
    bool software = false;                      // a software rasterizer (see drawPieces())
    int totalRecaptures = 0;
    std::unique_ptr<BandPool> pool;
    std::vector<Band> bands;

    std::size_t chunkNodes() const { return std::size_t(1) << chunkShift; }
    std::size_t maxNodes() const {
        return std::min<std::size_t>(chunkNodes() * std::size_t(maxChunks), kEmpty - 1);
    }
    void freeNodes() {
        for (MappedBuffer& chunk : nodes)
            chunk.free();
        nodes.clear();
        nodeData.clear();
        capacity = 0;
    }
    void releaseMesh() {
        if (vertexArray)
            glDeleteVertexArrays(1, &vertexArray);
        if (positions)
            glDeleteBuffers(1, &positions);
        vertexArray = positions = 0;
        soupVertices = 0;
    }
    core::Status ensureNodes(std::size_t wanted);
    /** The chunk size: the largest power of two of nodes within a (possibly capped) block. */
    void planChunks() {
        const std::size_t block = blockCap ? std::min(blockCap, maxBufferBytes) : maxBufferBytes;
        chunkShift = 0;
        while ((std::size_t(2) << chunkShift) * kNodeBytes <= block && chunkShift < 31)
            ++chunkShift;
    }
    /** The program for the current number of node chunks, built on first use. */
    core::Status ensureProgram() {
        const int chunks = int(nodes.size());
        if (programs.count(chunks))
            return {};
        auto built = buildCaptureProgram(chunks);
        if (!built)
            return core::Error{built.error()};
        programs.emplace(chunks, std::move(built).value());
        return {};
    }
    void draw(const core::View& view, const Options& options);
    core::Result<core::LayerStack> resolve(const core::View& view, std::size_t written,
                                           Timings* timings);
};

core::Status LayerCapture::Impl::ensureNodes(std::size_t wanted) {
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

void LayerCapture::Impl::draw(const core::View& view, const Options& options) {
    if (!headsEmpty) {
        const GLuint empty = kEmpty;
        glClearNamedBufferData(heads.id, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &empty);
    }
    headsEmpty = false;
    const GLuint zero = 0;
    glClearNamedBufferData(counter.id, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);

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
    glUniform1ui(p.capacityLocation, GLuint(capacity));
    glUniform1ui(p.chunkShiftLocation, GLuint(chunkShift));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, counter.id);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, heads.id);
    for (std::size_t c = 0; c < nodes.size(); ++c)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(2 + c), nodes[c].id);
    glBindVertexArray(vertexArray);
    const std::size_t triangles = soupVertices / 3;
    const int pieces = drawPieces(software, triangles, std::size_t(view.width) * view.height);
    drawInPieces(0, triangles, pieces, [](std::size_t first, std::size_t count) {
        glDrawArrays(GL_TRIANGLES, GLint(3 * first), GLsizei(3 * count));
    });
    for (GLuint binding = 0; binding < GLuint(2 + nodes.size()); ++binding)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);

    // Shader writes reach the persistent mappings once the fence has signalled.
    glMemoryBarrier(GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);
    GLsync fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    while (glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000'000) ==
           GL_TIMEOUT_EXPIRED) {
    }
    glDeleteSync(fence);
}

core::Result<core::LayerStack> LayerCapture::Impl::resolve(const core::View& view,
                                                           std::size_t written, Timings* timings) {
    const int width = view.width, height = view.height;
    const int bandCount = (height + kBandRows - 1) / kBandRows;
    if (int(bands.size()) < bandCount)
        bands.resize(std::size_t(bandCount));
    auto* headWords = static_cast<std::uint32_t*>(heads.data);
    const std::uint32_t* const* chunkWords = nodeData.data();
    const unsigned shift = chunkShift;
    const std::uint32_t mask = std::uint32_t(chunkNodes() - 1);
    const auto nodeWords = [&](std::uint32_t node) {
        return chunkWords[node >> shift] + std::size_t(node & mask) * 3;
    };
    const auto nodeLimit = std::uint32_t(written);

    core::LayerStack stack;
    stack.width = width;
    stack.height = height;
    stack.offsets.resize(std::size_t(width) * height + 1);

    // Pass 1, per band: walk each pixel's list, sort it into the band's buffer, and store the
    // offset of its first fragment within the band. Heads are reset on the way, which spares
    // the next capture its clear.
    const std::function<void(int)> walkBand = [&](int b) {
        Band& band = bands[std::size_t(b)];
        band.keys.clear();
        band.perLayer.clear();
        const std::size_t first = std::size_t(b) * kBandRows * width;
        const std::size_t last =
            std::min(std::size_t(b + 1) * kBandRows, std::size_t(height)) * std::size_t(width);
        for (std::size_t pixel = first; pixel < last; ++pixel) {
            // A run of empty pixels: each starts (and ends) at the band's fragments so far.
            if (headWords[pixel] == kEmpty) {
                const std::size_t end = emptyRunEnd(headWords, pixel, last);
                std::fill(stack.offsets.begin() + std::ptrdiff_t(pixel),
                          stack.offsets.begin() + std::ptrdiff_t(end),
                          std::uint32_t(band.keys.size()));
                pixel = end - 1;
                continue;
            }
            // The walk waits on cache misses: nodes lie in rasterization order, not pixel
            // order. Prefetch the first two nodes of pixels ahead.
            if (pixel + 2 * kAhead < last)
                if (const std::uint32_t h = headWords[pixel + 2 * kAhead]; h < nodeLimit)
                    prefetch(nodeWords(h));
            if (pixel + kAhead < last)
                if (const std::uint32_t h = headWords[pixel + kAhead]; h < nodeLimit)
                    if (const std::uint32_t next = nodeWords(h)[2]; next < nodeLimit)
                        prefetch(nodeWords(next));
            const std::size_t begin = band.keys.size();
            stack.offsets[pixel] = std::uint32_t(begin);
            std::uint32_t node = headWords[pixel];
            headWords[pixel] = kEmpty;
            // Bounded by the nodes written, so a corrupt list cannot loop forever.
            for (std::uint32_t steps = 0; node < nodeLimit && steps < nodeLimit; ++steps) {
                const std::uint32_t* n = nodeWords(node);
                band.keys.push_back(std::uint64_t(sortableDepth(n[0])) << 32 | n[1]);
                node = n[2];
            }
            const auto begins = band.keys.begin() + std::ptrdiff_t(begin);
            const std::size_t count = band.keys.size() - begin;
            if (count <= 16) {
                for (auto i = begins + 1; i < band.keys.end(); ++i)
                    for (auto j = i; j != begins && *j < *(j - 1); --j)
                        std::iter_swap(j, j - 1);
            } else {
                std::sort(begins, band.keys.end());
            }
            if (band.perLayer.size() < count)
                band.perLayer.resize(count, 0);
            for (std::size_t k = 0; k < count; ++k)
                ++band.perLayer[k];
        }
    };

    // Pass 2, per band: offsets made global, fragments decoded into their place.
    std::vector<std::size_t> bandStart(std::size_t(bandCount) + 1, 0);
    const std::function<void(int)> writeBand = [&](int b) {
        const Band& band = bands[std::size_t(b)];
        const std::size_t start = bandStart[std::size_t(b)];
        const std::size_t first = std::size_t(b) * kBandRows * width;
        const std::size_t last =
            std::min(std::size_t(b + 1) * kBandRows, std::size_t(height)) * std::size_t(width);
        if (start > 0)
            for (std::size_t pixel = first; pixel < last; ++pixel)
                stack.offsets[pixel] += std::uint32_t(start);
        for (std::size_t k = 0; k < band.keys.size(); ++k) {
            const std::uint32_t bits = depthBits(std::uint32_t(band.keys[k] >> 32));
            std::memcpy(&stack.depth[start + k], &bits, sizeof(float));
            stack.triangle[start + k] = std::uint32_t(band.keys[k]);
        }
    };

    const core::Error outOfMemory{"layer capture: out of memory for the layer stack"};
    if (!pool->run(bandCount, walkBand))
        return outOfMemory;
    std::vector<std::uint32_t> perLayer;
    for (int b = 0; b < bandCount; ++b) {
        const Band& band = bands[std::size_t(b)];
        bandStart[std::size_t(b) + 1] = bandStart[std::size_t(b)] + band.keys.size();
        if (perLayer.size() < band.perLayer.size())
            perLayer.resize(band.perLayer.size(), 0);
        for (std::size_t k = 0; k < band.perLayer.size(); ++k)
            perLayer[k] += band.perLayer[k];
    }
    const std::size_t total = bandStart[std::size_t(bandCount)];
    stack.depth.resize(total);
    stack.triangle.resize(total);
    if (!pool->run(bandCount, writeBand))
        return outOfMemory;
    stack.offsets.back() = std::uint32_t(total);
    if (timings) {
        timings->fragments = total;
        timings->fragmentsPerLayer = std::move(perLayer);
    }
    return stack;
}

LayerCapture::LayerCapture() : m_impl(std::make_unique<Impl>()) {}

LayerCapture::~LayerCapture() {
    release();
}

core::Status LayerCapture::initialize() {
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
    // Counter and heads take two blocks; the rest can hold node chunks.
    d.maxChunks = std::clamp(std::min(fragmentBlocks, bindings) - 2, 1, kMaxNodeChunks);
    glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &d.maxFramebufferWidth);
    glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &d.maxFramebufferHeight);
    // Node indices are 32-bit with 0xffffffff as "none"; offsets are 32-bit too.
    d.maxBufferBytes =
        std::size_t(std::clamp<GLint64>(maxBlock, 0, GLint64(kEmpty - 1) * GLint64(kNodeBytes)));
    if (d.maxBufferBytes < kNodeBytes || d.maxFramebufferWidth <= 0 || d.maxFramebufferHeight <= 0)
        return core::Error{"layer capture: OpenGL reports no shader storage or framebuffer size"};
    d.planChunks();
    if (!d.framebuffer)
        glCreateFramebuffers(1, &d.framebuffer);
    if (!d.pool) {
        const int cores = int(std::thread::hardware_concurrency());
        d.pool = std::make_unique<BandPool>(std::clamp(cores - 1, 0, 15));
    }
    return {};
}

void LayerCapture::setMesh(const core::Mesh& mesh) {
    Impl& d = *m_impl;
    d.releaseMesh();
    const std::size_t triangles = mesh.triangleCount();
    if (triangles == 0 || triangles > std::size_t(std::numeric_limits<GLsizei>::max() / 3))
        return;
    std::vector<glm::vec3> soup(triangles * 3);
    for (std::size_t i = 0; i < soup.size(); ++i) {
        const std::uint32_t v = mesh.indices[i];
        soup[i] = v < mesh.positions.size() ? mesh.positions[v] : glm::vec3(0.0f);
    }
    glCreateBuffers(1, &d.positions);
    glNamedBufferStorage(d.positions, GLsizeiptr(soup.size() * sizeof(glm::vec3)), soup.data(), 0);
    glCreateVertexArrays(1, &d.vertexArray);
    glVertexArrayVertexBuffer(d.vertexArray, 0, d.positions, 0, sizeof(glm::vec3));
    glEnableVertexArrayAttrib(d.vertexArray, 0);
    glVertexArrayAttribFormat(d.vertexArray, 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(d.vertexArray, 0, 0);
    d.soupVertices = soup.size();
}

bool LayerCapture::hasMesh() const {
    return m_impl->soupVertices > 0;
}

core::Result<core::LayerStack> LayerCapture::capture(const core::View& view, const Options& options,
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
        core::LayerStack empty;
        empty.width = view.width;
        empty.height = view.height;
        empty.offsets.assign(pixels + 1, 0);
        return empty;
    }

    const Clock::time_point start = Clock::now();
    if (view.width != d.framebufferWidth || view.height != d.framebufferHeight) {
        glNamedFramebufferParameteri(d.framebuffer, GL_FRAMEBUFFER_DEFAULT_WIDTH, view.width);
        glNamedFramebufferParameteri(d.framebuffer, GL_FRAMEBUFFER_DEFAULT_HEIGHT, view.height);
        d.framebufferWidth = view.width;
        d.framebufferHeight = view.height;
    }
    if (!d.counter.id && !d.counter.allocate(sizeof(std::uint32_t)))
        return core::Error{"layer capture: out of GPU memory"};
    if (d.heads.bytes < pixels * sizeof(std::uint32_t)) {
        if (pixels * sizeof(std::uint32_t) > d.maxBufferBytes)
            return core::Error{"layer capture: " + std::to_string(pixels) +
                               " pixels exceed this OpenGL's buffer size"};
        d.headsEmpty = false;
        if (!d.heads.allocate(pixels * sizeof(std::uint32_t)))
            return core::Error{"layer capture: out of GPU memory for the list heads"};
    }
    if (d.requestedCapacity) {
        d.capacity = 0; // reallocates to the requested size, smaller or larger
        const core::Status status = d.ensureNodes(d.requestedCapacity);
        d.requestedCapacity = 0;
        if (!status)
            return core::Error{status.error()};
    } else if (d.nodes.empty()) {
        // A first guess of two fragments a pixel; a deeper view grows it once.
        if (const core::Status status = d.ensureNodes(std::min(pixels * 2, d.maxNodes())); !status)
            return core::Error{status.error()};
    }

    if (const core::Status status = d.ensureProgram(); !status)
        return core::Error{status.error()};
    int recaptures = 0;
    std::size_t written = 0;
    {
        const StateGuard guard;
        for (;;) {
            d.draw(view, options);
            written = *static_cast<const volatile std::uint32_t*>(d.counter.data);
            if (written <= d.capacity)
                break;
            // Lists cut at the capacity are incomplete: grow with some headroom and draw again.
            const std::size_t grown = std::min(d.maxNodes(), written + written / 8);
            if (const core::Status status = d.ensureNodes(std::max(grown, written)); !status)
                return core::Error{status.error()};
            if (const core::Status status = d.ensureProgram(); !status)
                return core::Error{status.error()};
            ++recaptures;
            ++d.totalRecaptures;
        }
    }
    const double gpuMs = msSince(start);

    const Clock::time_point resolveStart = Clock::now();
    core::Result<core::LayerStack> stack = d.resolve(view, written, timings);
    if (!stack) {
        d.headsEmpty = false;
        return stack;
    }
    d.headsEmpty = true;
    if (timings) {
        timings->gpuMs = gpuMs;
        timings->resolveMs = msSince(resolveStart);
        timings->recaptures = recaptures;
    }
    return stack;
}

std::size_t LayerCapture::nodeCapacity() const {
    return m_impl->capacity;
}

void LayerCapture::setNodeCapacity(std::size_t nodes) {
    m_impl->requestedCapacity = std::max<std::size_t>(nodes, 1);
}

void LayerCapture::setStorageBlockCap(std::size_t bytes) {
    Impl& d = *m_impl;
    d.blockCap = bytes;
    d.freeNodes();
    d.planChunks();
}

std::size_t LayerCapture::nodeChunks() const {
    return m_impl->nodes.size();
}

int LayerCapture::totalRecaptures() const {
    return m_impl->totalRecaptures;
}

void LayerCapture::release() {
    if (!m_impl)
        return;
    Impl& d = *m_impl;
    d.counter.free();
    d.heads.free();
    d.freeNodes();
    d.headsEmpty = false;
    d.releaseMesh();
    if (d.framebuffer)
        glDeleteFramebuffers(1, &d.framebuffer);
    d.framebuffer = 0;
    d.framebufferWidth = d.framebufferHeight = 0;
    d.programs.clear();
    d.pool.reset();
    d.bands.clear();
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
