// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <glm/vec4.hpp>

#include "core/base/result.h"
#include "core/depth/depth_layers.h"
#include "core/depth/depth_stack.h"
#include "core/model/camera.h"
#include "core/model/mesh.h"
#include "render/material_channel.h"
#include "render/material_textures.h"

namespace render {

/** What draw_layers shows. */
enum class DepthLayerDisplay {
    Composite,    // the visible fragment of each pixel, shaded (the normal painting view)
    SingleLayer,  // layer k alone, shaded; pixels without a k-th fragment show the background
    Segmentation, // the visible fragment coloured by its region (the paper's Figure 2)
};

// MaterialChannel (render/material_channel.h): which channel Composite and SingleLayer show.

struct CompositeOptions {
    DepthLayerDisplay display = DepthLayerDisplay::Composite;
    MaterialChannel channel = MaterialChannel::Material;
    std::uint32_t layer = 1; // for SingleLayer (1-based)
    /**
     * Overlay region boundaries (the paper's Figure 3 contour lines): darkens the visible
     * fragment where, towards a neighbour pixel that has any fragment, it has no same-layer link
     * either way, i.e. where its region ends.
     */
    bool boundaries = false;
    /**
     * A region drawn highlighted (hover in the region graph), or core::kNone: tinted where it
     * is visible, striped where another region covers it.
     */
    std::uint32_t highlightRegion = core::kNone;
    /**
     * Below 1: transparency (the paper's exploded view). Where the visible fragment is not on
     * layer 1 (a popped-up or revealed region), it is drawn with this opacity over the next
     * fragment in the order, so its surroundings stay visible. Layer 1 is always opaque.
     */
    float popUpOpacity = 1.0f;
    /** Segmentation: shade region colours lightly by the normal; false gives flat regionColor(). */
    bool shadeSegmentation = true;
    glm::vec4 background{0.22f, 0.23f, 0.25f, 1.0f}; // sRGB-encoded, as MeshRenderer
};

/** A mesh as the compositor uploads it, made off the GL thread (DepthCompositor::prepareMesh). */
struct CompositorMesh;

/**
 * draw_layers (docs/architecture.md §3 step 4): draws the view from the captured per-pixel fragment
 * lists instead of the geometry, so the picture updates (paint, region order, display mode) without
 * capturing again. The visible fragment of a pixel is the one whose region has the lowest rank
 * in the region order, skipping hidden regions; the default order ranks regions by id (so
 * layer 1 is visible everywhere). Each fragment is shaded like MeshRenderer shades the surface
 * where the pixel's ray meets the fragment's triangle (normal, uv, vertex colour interpolated).
 *
 * The work is split by how often its inputs change, since llvmpipe shades every pixel of a
 * pass whatever branches it takes: fragment shading once per capture or mesh (a compute pass
 * over all fragments), picking the visible fragments once per region order, picked layer or
 * boundary setting, and composing (texture, region colours, overlays) on every draw. Only
 * 16 × 16 tiles holding fragments are drawn; the rest is cleared. GPU memory: 8 bytes a pixel,
 * 36 a fragment, up to 40 a vertex, 16 a triangle, plus copies of the base color and
 * metallic-roughness textures.
 * Needs a current GL context for every call, the one it was initialized in.
 */
class DepthCompositor {
public:
    DepthCompositor();
    ~DepthCompositor();
    DepthCompositor(const DepthCompositor&) = delete;
    DepthCompositor& operator=(const DepthCompositor&) = delete;

    /** Compiles the shaders (other feature variants on first use); an Error if they fail. */
    core::Status initialize();
    /**
     * Uploads what shading needs: vertices, triangles, materials and their textures. A mesh
     * whose arrays exceed one storage block is split into parts of consecutive triangles, each
     * within a block. Returns an Error (and keeps no mesh) if GL memory runs out. Buffers are
     * reused while the data fits.
     */
    core::Status setMesh(const core::Mesh& mesh,
                         std::shared_ptr<MaterialTextures> textures = nullptr);
    /**
     * As setMesh() above, the geometry from geometry, the materials, textures and vertex
     * colours from look (a PaintTarget::paintedLook(), which spares a copy of the geometry).
     */
    core::Status setMesh(const core::Mesh& geometry, const core::Mesh& look,
                         std::shared_ptr<MaterialTextures> textures);
    /**
     * The CPU's share of setMesh(): the triangles packed and split for storage blocks of
     * blockBytes (storageBlockBytes()), the normals encoded. Needs no GL: any thread may run
     * it while the compositor draws, so the upload that follows only copies.
     */
    static core::Result<std::shared_ptr<const CompositorMesh>>
    prepareMesh(const core::Mesh& geometry, const core::Mesh& look, std::size_t blockBytes);
    /** The storage block size prepareMesh() splits the mesh for. */
    std::size_t storageBlockBytes() const;
    /**
     * setMesh() of a mesh prepareMesh() made from geometry and look (with the block size of
     * storageBlockBytes(), else it is prepared again here): the GL share alone.
     */
    core::Status setMesh(const CompositorMesh& prepared, const core::Mesh& geometry,
                         const core::Mesh& look, std::shared_ptr<MaterialTextures> textures);
    /**
     * The textures the materials sample (with a mesh renderer of the same context, the store
     * both read). Textures are sampled when composing, so painting them (MaterialTextures::
     * updateTexels()) runs nothing else again; a base colour texture with a metallic-roughness
     * texture is lit as metallic-roughness.
     */
    MaterialTextures& textures();
    /**
     * Painting: replaces the colours of vertices [first, first + colors.size()) (clamped to the
     * mesh; ignored if setMesh() had no vertex colours). Fragments are shaded with them, so the
     * next draw shades every fragment again.
     */
    void updateVertexColors(std::uint32_t first, std::span<const glm::vec4> colors);
    /**
     * Uploads one build's fragments, links and regions; resets the region order. Returns an
     * Error (and keeps no layers) if the stack is inconsistent or exceeds the GL's limits.
     * Buffers are reused while the data fits, so a rebuild does not reallocate.
     */
    core::Status setDepthLayers(const core::DepthLayers& layers);
    /**
     * Re-uploads links and regions after resegmentDepthLayers() (same capture) and resets the
     * region order, since region ids change. An Error if there are no layers or sizes do not match.
     */
    core::Status updateSegmentation(const core::DepthLayers& layers);
    bool hasDepthLayers() const;
    /**
     * The region order: rank[r] is region r's place front to back (lower is in front), or
     * core::kNone for a hidden region. Size = region count; returns false (and keeps the old
     * order) otherwise.
     */
    bool setRegionRanks(const std::vector<std::uint32_t>& rank);
    /**
     * Draws into the currently bound framebuffer at the layers' view size (viewport at the
     * origin), replacing every pixel of it; without layers it only clears to the background.
     * The first draw after setMesh() or setDepthLayers() also shades every fragment, and the first
     * after a new region order, display layer or boundaries setting also picks the visible
     * fragments again. One pass per base color texture of the mesh. Leaves depth test,
     * blending, face culling and stencil test disabled.
     */
    void draw(const CompositeOptions& options);
    /**
     * What the last draw showed: per pixel of the layers' view (rows top first) the index of the
     * fragment drawn (on top, with transparency), core::kNone for background; empty before a
     * draw of these layers and order. Reads back from the GPU: for tests and tools.
     */
    std::vector<std::uint32_t> readVisible() const;
    /**
     * Plans the mesh's parts as if a storage block held at most `bytes` (0: the GL's limit), so
     * tests run small scenes through the split path. Takes effect at the next setMesh().
     */
    void setStorageBlockCap(std::size_t bytes);
    /** How many parts the mesh was split into (1 when it fits one block; 0 without a mesh). */
    std::size_t meshPartCount() const;
    /** Frees every GL object; the context must be current. Called by the destructor too. */
    void release();

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

/**
 * The colour the Segmentation display gives region id (sRGB, alpha 1): distinct neighbouring
 * hues, the same in the GUI's panels. A CPU function so widgets and tests agree with the shader.
 */
glm::vec4 regionColor(std::uint32_t region);

} // namespace render
