// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/depth_capture.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <mutex>
#include <new>
#include <string>
#include <thread>

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include "render/gl_buffer.h"
#include "render/mesh_renderer.h"
#include "render/offscreen_target.h"
#include "render/shader_library.h"
#include "render/software_gl.h"

namespace render {

namespace {
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

constexpr std::uint32_t kNone = 0xffffffffu;                  // node indices stay below it
constexpr std::size_t kNodeBytes = 3 * sizeof(std::uint32_t); // depth bits, triangle, pixel
constexpr int kMaxNodeChunks = 8;                             // capture.frag's NODE_CHUNKS at most
constexpr std::size_t kMaxNodeRanges = 8;                     // capture.frag's uRangeStart[8]
constexpr std::size_t kCounterStride = 16; // words between the ranges' counters: a cache line
// The resolve sorts the nodes by band of 2^kBandShift pixels (about 8 rows of a 1920-pixel view),
// then each band by pixel: a band's counts and fragments stay in a core's cache.
constexpr unsigned kBandShift = 14;
constexpr std::size_t kBandPixels = std::size_t(1) << kBandShift;
// The passes over the list take it in slices of at least kSliceNodes nodes, at most kMaxSlices.
constexpr std::size_t kSliceNodes = std::size_t(1) << 16;
constexpr int kMaxSlices = 32;

// Float bits to an unsigned key with the same order (negative depths included), and back.
std::uint32_t sortableDepth(std::uint32_t bits) {
    return (bits & 0x80000000u) ? ~bits : bits | 0x80000000u;
}
std::uint32_t depthBits(std::uint32_t key) {
    return (key & 0x80000000u) ? key & 0x7fffffffu : ~key;
}

/**
 * What one band's resolve found: [k] pixels with more than k fragments. Aligned so that two
 * threads filling neighbouring bands never share a cache line.
 */
struct alignas(64) Band {
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
    GLint widthLocation = -1, heightLocation = -1, chunkShiftLocation = -1;
    GLint rangeMaskLocation = -1, rangeStartLocation = -1, rangeCapacityLocation = -1;
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
                      {&p.chunkShiftLocation, "uChunkShift"},
                      {&p.rangeMaskLocation, "uRangeMask"},
                      {&p.rangeStartLocation, "uRangeStart"},
                      {&p.rangeCapacityLocation, "uRangeCapacity"}});
    return p;
}

struct DepthCapture::Impl {
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
    MappedBuffer counter;
    std::vector<MappedBuffer> nodes;
    std::vector<const std::uint32_t*> nodeData; // each chunk's mapping
    std::size_t capacity = 0;                   // nodes that fit in `nodes`
    std::size_t requestedCapacity = 0;          // from setNodeCapacity, applied at the next capture
    // The nodes' ranges, each with its own counter (capture.frag): a power of two of them, one
    // on a hardware GPU. `written` is what the last draw counted, perhaps more than fits.
    struct NodeRange {
        std::size_t first = 0, capacity = 0, written = 0;
    };
    std::vector<NodeRange> ranges{1};
    std::size_t plannedCapacity = 0; // the capacity the ranges were planned for
    bool software = false;           // a software rasterizer (see drawPieces())
    int totalRecaptures = 0;
    std::unique_ptr<BandPool> pool;
    // The resolve's working memory, kept between captures.
    std::vector<Band> bands;
    std::vector<std::uint32_t> sliceCounts; // [slice * bands + band]: nodes, then cursors
    std::vector<std::uint16_t> pixelInBand; // each fragment's pixel within its band

    std::size_t chunkNodes() const { return std::size_t(1) << chunkShift; }
    std::size_t maxNodes() const {
        return std::min<std::size_t>(chunkNodes() * std::size_t(maxChunks), kNone - 1);
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
    void setRanges(std::size_t count) {
        ranges.assign(count, {});
        plannedCapacity = 0;
    }
    /**
     * Splits the capacity between the ranges: each gets what the last draw wrote into it (with
     * `fromLastDraw`) and an even share of the rest.
     */
    void planRanges(bool fromLastDraw) {
        std::size_t need = 0;
        for (const NodeRange& range : ranges)
            need += fromLastDraw ? range.written : 0;
        const std::size_t share = (capacity - std::min(need, capacity)) / ranges.size();
        std::size_t first = 0;
        for (NodeRange& range : ranges) {
            range.first = first;
            range.capacity = (fromLastDraw ? range.written : 0) + share;
            first += range.capacity;
        }
        ranges.back().capacity += capacity - std::min(first, capacity);
        plannedCapacity = capacity;
    }
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
    core::Result<core::DepthStack> resolve(const core::View& view, Timings* timings);
};

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

core::Result<core::DepthStack> DepthCapture::Impl::resolve(const core::View& view,
                                                           Timings* timings) {
    std::size_t written = 0; // the ranges' nodes as one list
    for (const NodeRange& range : ranges)
        written += range.written;
    const std::size_t pixels = std::size_t(view.width) * std::size_t(view.height);
    const std::size_t bandCount = (pixels + kBandPixels - 1) >> kBandShift;
    const int slices = int(std::clamp<std::size_t>(written / kSliceNodes, 1, kMaxSlices));
    const unsigned shift = chunkShift;
    const std::size_t mask = chunkNodes() - 1;
    const std::uint32_t* const* chunkWords = nodeData.data();
    // Calls visit(words) for the nodes [first, last) of that list in order, chunk by chunk.
    const auto forNodes = [&](std::size_t first, std::size_t last, auto&& visit) {
        std::size_t rangeBegins = 0;
        for (const NodeRange& range : ranges) {
            std::size_t node = range.first + std::max(first, rangeBegins) - rangeBegins;
            const std::size_t end =
                range.first + std::min(last, rangeBegins + range.written) - rangeBegins;
            rangeBegins += range.written;
            while (node < end) {
                const std::size_t chunkEnd = std::min(end, ((node >> shift) + 1) << shift);
                const std::uint32_t* words = chunkWords[node >> shift] + (node & mask) * 3;
                for (; node < chunkEnd; ++node, words += 3)
                    visit(words);
            }
        }
    };
    const auto sliceFirst = [&](int s) { return written * std::size_t(s) / std::size_t(slices); };

    core::DepthStack stack;
    stack.width = view.width;
    stack.height = view.height;

    // Pass 1, per slice of the list: its nodes in each band. A node naming no pixel of the view
    // (only a corrupt list has one) is left out here and below.
    const std::function<void(int)> countSlice = [&](int s) {
        std::uint32_t* counts = sliceCounts.data() + std::size_t(s) * bandCount;
        forNodes(sliceFirst(s), sliceFirst(s + 1), [&](const std::uint32_t* words) {
            if (words[2] < pixels)
                ++counts[words[2] >> kBandShift];
        });
    };
    // Where each band's fragments begin, and each slice's within the band: the counts become
    // cursors.
    std::vector<std::size_t> bandBegin;
    const auto placeSlices = [&] {
        std::size_t total = 0;
        for (std::size_t b = 0; b < bandCount; ++b) {
            bandBegin[b] = total;
            for (int s = 0; s < slices; ++s) {
                std::uint32_t& count = sliceCounts[std::size_t(s) * bandCount + b];
                const std::uint32_t nodesHere = count;
                count = std::uint32_t(total);
                total += nodesHere;
            }
        }
        bandBegin[bandCount] = total;
        return total;
    };
    // Pass 2, per slice: the nodes into their band's range of the stack, unsorted, with their
    // pixel within the band.
    const std::function<void(int)> scatterSlice = [&](int s) {
        std::uint32_t* cursors = sliceCounts.data() + std::size_t(s) * bandCount;
        float* depth = stack.depth.data();
        std::uint32_t* triangle = stack.triangle.data();
        std::uint16_t* pixelOf = pixelInBand.data();
        forNodes(sliceFirst(s), sliceFirst(s + 1), [&](const std::uint32_t* words) {
            const std::uint32_t pixel = words[2];
            if (pixel >= pixels)
                return;
            const std::uint32_t at = cursors[pixel >> kBandShift]++;
            std::memcpy(&depth[at], &words[0], sizeof(float));
            triangle[at] = words[1];
            pixelOf[at] = std::uint16_t(pixel & (kBandPixels - 1));
        });
    };
    // Pass 3, per band: a counting sort by pixel, then each pixel's fragments front to back
    // (ties by triangle id), written back in place; the band's offsets.
    const std::function<void(int)> sortBand = [&](int b) {
        Band& band = bands[std::size_t(b)];
        band.perLayer.clear();
        const std::size_t first = bandBegin[std::size_t(b)], last = bandBegin[std::size_t(b) + 1];
        const std::size_t firstPixel = std::size_t(b) << kBandShift;
        const std::size_t bandPixels = std::min(kBandPixels, pixels - firstPixel);
        std::uint32_t* offsets = stack.offsets.data() + firstPixel;
        if (first == last) {
            std::fill(offsets, offsets + bandPixels, std::uint32_t(first));
            return;
        }
        thread_local std::vector<std::uint32_t> ends;
        thread_local std::vector<std::uint16_t> occupied; // the pixels with fragments
        thread_local std::vector<std::uint64_t> keys;
        ends.assign(bandPixels, 0);
        occupied.resize(bandPixels);
        const std::uint16_t* pixelOf = pixelInBand.data() + first;
        const std::size_t count = last - first;
        for (std::size_t k = 0; k < count; ++k)
            ++ends[pixelOf[k]];
        std::uint32_t at = 0;
        std::size_t used = 0;
        for (std::size_t i = 0; i < bandPixels; ++i) {
            // Eight empty pixels at a time: around a model most of a view's pixels are empty.
            if (std::uint64_t w[4]; i + 8 <= bandPixels) {
                std::memcpy(w, &ends[i], sizeof w);
                if ((w[0] | w[1] | w[2] | w[3]) == 0) {
                    std::fill_n(offsets + i, 8, std::uint32_t(first) + at);
                    i += 7;
                    continue;
                }
            }
            const std::uint32_t n = ends[i];
            offsets[i] = std::uint32_t(first) + at;
            ends[i] = at; // the pixel's next free place
            occupied[used] = std::uint16_t(i);
            used += n != 0;
            at += n;
        }
        keys.resize(count);
        const float* depth = stack.depth.data() + first;
        const std::uint32_t* triangle = stack.triangle.data() + first;
        for (std::size_t k = 0; k < count; ++k) {
            std::uint32_t bits;
            std::memcpy(&bits, &depth[k], sizeof bits);
            keys[ends[pixelOf[k]]++] = std::uint64_t(sortableDepth(bits)) << 32 | triangle[k];
        }
        std::uint64_t* const key = keys.data();
        for (std::size_t u = 0; u < used; ++u) {
            const std::size_t i = occupied[u];
            const std::size_t begin = offsets[i] - first, end = ends[i], n = end - begin;
            if (n > 16) {
                std::sort(key + begin, key + end);
            } else {
                for (std::size_t j = begin + 1; j < end; ++j) {
                    const std::uint64_t k = key[j];
                    std::size_t to = j;
                    for (; to > begin && key[to - 1] > k; --to)
                        key[to] = key[to - 1];
                    key[to] = k;
                }
            }
            if (band.perLayer.size() < n)
                band.perLayer.resize(n, 0);
            for (std::size_t k = 0; k < n; ++k)
                ++band.perLayer[k];
        }
        float* outDepth = stack.depth.data() + first;
        std::uint32_t* outTriangle = stack.triangle.data() + first;
        for (std::size_t k = 0; k < count; ++k) {
            const std::uint32_t bits = depthBits(std::uint32_t(key[k] >> 32));
            std::memcpy(&outDepth[k], &bits, sizeof(float));
            outTriangle[k] = std::uint32_t(key[k]);
        }
    };

    const core::Error outOfMemory{"layer capture: out of memory for the layer stack"};
    // Every allocation is in here: running out of memory is an error, not an abort.
    try {
        stack.offsets.resize(pixels + 1);
        if (bands.size() < bandCount)
            bands.resize(bandCount);
        sliceCounts.assign(std::size_t(slices) * bandCount, 0);
        bandBegin.assign(bandCount + 1, 0);
        if (!pool->run(slices, countSlice))
            return outOfMemory;
        const std::size_t total = placeSlices();
        stack.depth.resize(total);
        stack.triangle.resize(total);
        pixelInBand.resize(total);
        if (!pool->run(slices, scatterSlice) || !pool->run(int(bandCount), sortBand))
            return outOfMemory;
        stack.offsets.back() = std::uint32_t(total);
        if (timings) {
            std::vector<std::uint32_t> perLayer;
            for (std::size_t b = 0; b < bandCount; ++b) {
                const Band& band = bands[b];
                if (perLayer.size() < band.perLayer.size())
                    perLayer.resize(band.perLayer.size(), 0);
                for (std::size_t k = 0; k < band.perLayer.size(); ++k)
                    perLayer[k] += band.perLayer[k];
            }
            timings->fragments = total;
            timings->fragmentsPerLayer = std::move(perLayer);
        }
    } catch (const std::bad_alloc&) {
        return outOfMemory;
    }
    return stack;
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
    d.maxBufferBytes =
        std::size_t(std::clamp<GLint64>(maxBlock, 0, GLint64(kNone - 1) * GLint64(kNodeBytes)));
    if (d.maxBufferBytes < kNodeBytes || d.maxFramebufferWidth <= 0 || d.maxFramebufferHeight <= 0)
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
    if (view.width != d.framebufferWidth || view.height != d.framebufferHeight) {
        glNamedFramebufferParameteri(d.framebuffer, GL_FRAMEBUFFER_DEFAULT_WIDTH, view.width);
        glNamedFramebufferParameteri(d.framebuffer, GL_FRAMEBUFFER_DEFAULT_HEIGHT, view.height);
        d.framebufferWidth = view.width;
        d.framebufferHeight = view.height;
    }
    const std::size_t counterBytes = d.ranges.size() * kCounterStride * sizeof(std::uint32_t);
    if (d.counter.bytes != counterBytes && !d.counter.allocate(counterBytes))
        return core::Error{"layer capture: out of GPU memory"};
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
    if (d.plannedCapacity != d.capacity)
        d.planRanges(false);
    int recaptures = 0;
    {
        const StateGuard guard;
        for (;;) {
            d.draw(view, options);
            const auto* counts = static_cast<const volatile std::uint32_t*>(d.counter.data);
            std::size_t written = 0;
            bool fits = true;
            for (std::size_t r = 0; r < d.ranges.size(); ++r) {
                Impl::NodeRange& range = d.ranges[r];
                range.written = counts[r * kCounterStride];
                written += range.written;
                fits = fits && range.written <= range.capacity;
            }
            if (fits)
                break;
            // Lists cut at a range's capacity are incomplete: grow with some headroom if the
            // whole list does not fit, split the nodes as this draw needs them and draw again.
            const std::size_t grown = std::min(d.maxNodes(), written + written / 8);
            if (const core::Status status = d.ensureNodes(std::max(grown, written)); !status)
                return core::Error{status.error()};
            if (const core::Status status = d.ensureProgram(); !status)
                return core::Error{status.error()};
            d.planRanges(true);
            ++recaptures;
            ++d.totalRecaptures;
        }
    }
    const double gpuMs = msSince(start);

    const Clock::time_point resolveStart = Clock::now();
    core::Result<core::DepthStack> stack = d.resolve(view, timings);
    if (!stack)
        return stack;
    if (timings) {
        timings->gpuMs = gpuMs;
        timings->resolveMs = msSince(resolveStart);
        timings->recaptures = recaptures;
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
