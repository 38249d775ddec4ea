// SPDX-License-Identifier: GPL-3.0-or-later
// Internal to the capture's .cpp files (it includes the GL header): the GL objects and working
// memory of DepthCapture, shared by the GPU capture (depth_capture.cpp) and the CPU resolve that
// sorts its fragment list into a stack (depth_capture_resolve.cpp).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include <epoxy/gl.h>

#include "core/base/result.h"
#include "core/depth/depth_stack.h"
#include "core/model/camera.h"
#include "render/band_pool.h"
#include "render/depth_capture.h"
#include "render/gl_buffer.h"
#include "render/shader_library.h"

namespace render {

/** capture.vert + capture.frag for a number of node chunks, and its uniforms. */
struct CaptureProgram {
    ShaderProgram program;
    GLint viewLocation = -1, projLocation = -1;
    GLint widthLocation = -1, heightLocation = -1, chunkShiftLocation = -1;
    GLint rangeMaskLocation = -1, rangeStartLocation = -1, rangeCapacityLocation = -1;
};

/** Builds capture.vert + capture.frag for a number of node chunks; an Error if it fails. */
core::Result<CaptureProgram> buildCaptureProgram(int chunks);

struct DepthCapture::Impl {
    static constexpr std::uint32_t kNone = 0xffffffffu; // node indices stay below it
    static constexpr std::size_t kNodeBytes =
        3 * sizeof(std::uint32_t); // depth bits, triangle, pixel

    /** The CPU reads the GPU's lists in place. */
    struct MappedBuffer : GlBuffer {
        bool allocate(std::size_t size) {
            return GlBuffer::allocate(size, GL_MAP_READ_BIT | GL_MAP_WRITE_BIT);
        }
    };
    /**
     * What one band's resolve found: [k] pixels with more than k fragments. Aligned so that two
     * threads filling neighbouring bands never share a cache line.
     */
    struct alignas(64) Band {
        std::vector<std::uint32_t> perLayer;
    };
    /** One resolve's passes and their scratch (depth_capture_resolve.cpp). */
    struct Resolve;

    std::map<int, CaptureProgram> programs; // by node chunks; 1 built by initialize()
    // The mesh as a triangle soup: 3 positions a triangle, in triangle order.
    GLuint vertexArray = 0, positions = 0;
    std::size_t soupVertices = 0;
    std::size_t pendingVertices = 0; // the soup mapped between beginMesh() and finishMesh()
    bool pendingFilled = false;      // and written whole by the fill
    // The shown back faces (DepthCaptureOptions::shownBackFaces) as the vertex array's element
    // buffer: triangle t as soup vertices 3t, 3t + 2, 3t + 1, so its back faces the viewer and
    // the culling that drops the other back faces keeps it; its id is still gl_VertexID / 3.
    GLuint backFaceElements = 0;
    std::vector<std::uint32_t> backFaces;
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
        if (pendingVertices)
            glUnmapNamedBuffer(positions);
        pendingVertices = 0;
        if (vertexArray)
            glDeleteVertexArrays(1, &vertexArray);
        if (positions)
            glDeleteBuffers(1, &positions);
        if (backFaceElements)
            glDeleteBuffers(1, &backFaceElements);
        vertexArray = positions = backFaceElements = 0;
        soupVertices = 0;
        backFaces.clear();
    }
    /** The element buffer of the shown back faces made for triangles, if it is not already. */
    void useBackFaces(std::span<const std::uint32_t> triangles);
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
    /** Sizes the framebuffer, the counters and the nodes for a view; builds their program. */
    core::Status prepareDraw(const core::View& view);
    /** Appends the view's fragments to the nodes, growing them until all fit: the recaptures. */
    core::Result<int> drawUntilFits(const core::View& view, const Options& options);
    void draw(const core::View& view, const Options& options);
    /** Sorts the list the last draw wrote into the view's stack (depth_capture_resolve.cpp). */
    core::Result<core::DepthStack> resolve(const core::View& view, Timings* timings);
};

} // namespace render
