// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "core/base/result.h"
#include "core/depth/depth_stack.h"
#include "core/model/camera.h"
#include "core/model/mesh.h"

namespace render {

class MeshRenderer;
class OffscreenTarget;
struct DrawOptions;

/** Options of DepthCapture::capture(). */
struct DepthCaptureOptions {
    bool cullBackFaces = true; // false: two-sided, back faces are captured too
    /** Ascending triangles whose back faces are captured anyway (MeshTopology::shownBackFaces). */
    std::span<const std::uint32_t> shownBackFaces = {};
};

/** What one capture cost and found. */
struct DepthCaptureTimings {
    double gpuMs = 0.0;     // clears, draws (every attempt) and the wait for the GPU
    double resolveMs = 0.0; // sorting the list into the stack on the CPU
    int recaptures = 0;     // extra draws because the node buffer was too small
    std::size_t fragments = 0;
    std::vector<std::uint32_t> fragmentsPerLayer; // [k - 1]: fragments on layer k
};

/**
 * Captures every fragment of a view as a core::DepthStack (docs/architecture.md §3 step 2) in one
 * geometry pass: a fragment shader appends each fragment with its pixel to a list in GL buffers,
 * then CPU threads sort the list straight from the mapped buffers by band of pixels, each band by
 * pixel and each pixel front to back (ties by triangle id, so the result is deterministic). If a
 * view has more fragments than the node buffer holds, the buffers grow and the view is drawn
 * again; the capacity is kept for later captures. GPU memory: 36 bytes a triangle, 12 a
 * fragment; CPU memory beside the stack: 2 bytes a fragment. capture() blocks until the list
 * is sorted. Needs a current GL 4.5 context for every call, the one it was initialized in.
 */
class DepthCapture {
public:
    // Outside the class only so they can be default arguments of its members.
    using Options = DepthCaptureOptions;
    using Timings = DepthCaptureTimings;

    DepthCapture();
    ~DepthCapture();
    DepthCapture(const DepthCapture&) = delete;
    DepthCapture& operator=(const DepthCapture&) = delete;

    /** Compiles the shaders and reads the GL's limits; an Error if either fails. */
    core::Status initialize();
    /**
     * Uploads the mesh (replacing any previous one); triangle ids are its triangle indices.
     * An empty mesh, or one of more than 715 million triangles, leaves the capture without one.
     */
    void setMesh(const core::Mesh& mesh);
    /**
     * setMesh() in three steps, as MeshRenderer::beginMesh(): beginMesh() replaces the mesh and
     * maps a buffer for it; the fill it returns (empty: no mesh) writes the mesh's soup through
     * the mapping on any thread, once, while mesh lives; finishMesh() unmaps it, and the mesh is
     * captured from then on. Meanwhile hasMesh() is false.
     */
    std::function<void()> beginMesh(const core::Mesh& mesh);
    void finishMesh();
    bool hasMesh() const;

    /**
     * Captures the view at view.width × view.height. Without a mesh the stack has no fragments.
     * Returns an Error (and captures nothing) if initialize() has not succeeded, if the size
     * exceeds the GL's framebuffer limits, or if GL or CPU memory runs out. The fragments are
     * not capped by one storage block: they are split into chunks of a block each (up to 8,
     * as the GL's storage bindings allow: 67 million fragments on llvmpipe).
     */
    core::Result<core::DepthStack> capture(const core::View& view, const Options& options = {},
                                           Timings* timings = nullptr);

    /** Fragments the node buffer holds (0 before the first capture). */
    std::size_t nodeCapacity() const;
    /** Resizes the node buffer at the next capture (tests force growth with a tiny one). */
    void setNodeCapacity(std::size_t nodes);
    /**
     * Plans the node chunks as if a storage block held at most `bytes` (0: the GL's limit), so
     * tests run small views through the split path. Frees the node buffers.
     */
    void setStorageBlockCap(std::size_t bytes);
    /**
     * Splits the nodes into `count` ranges (rounded down to a power of two, 1 to 8), each with
     * its own counter: a fragment at x takes a node of range (x / 64) mod count. On a software
     * rasterizer initialize() chooses one a core, so that its threads, each on a 64-pixel tile,
     * seldom count on one cache line; elsewhere one. Tests choose others; the stack is the same.
     */
    void setNodeRanges(std::size_t count);
    std::size_t nodeRanges() const;
    /** How many buffers the fragment (node) list is split into (0 before the first capture). */
    std::size_t nodeChunks() const;
    /** Recaptures forced by a full node buffer over this object's lifetime. */
    int totalRecaptures() const;

    /** Frees every GL object; the context must be current. Called by the destructor too. */
    void release();

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

/**
 * The capture's baseline (docs/architecture.md §5): milliseconds of one plain z-buffer pass of the
 * renderer's mesh into the target, from an idle GPU to the pass's end (glFinish on both sides).
 * The target should have the view's size.
 */
double timePlainPass(MeshRenderer& renderer, const OffscreenTarget& target, const core::View& view,
                     const DrawOptions& options);

} // namespace render
