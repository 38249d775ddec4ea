// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>

#include <glm/vec4.hpp>

#include "core/base/result.h"
#include "core/model/camera.h"
#include "core/model/mesh.h"
#include "render/material_channel.h"
#include "render/material_textures.h"

namespace render {

struct DrawOptions {
    glm::vec4 background{0.22f, 0.23f, 0.25f, 1.0f}; // sRGB-encoded RGBA, as written
    bool clear = true;
    bool cullBackFaces = false; // true: back faces are culled but for setMesh's shownBackFaces
    bool standIn = false;       // draw the stand-in (setStandIn) instead of the mesh, if set
    /** What is shown, as the compositor shows it (render/material_channel.h). */
    MaterialChannel channel = MaterialChannel::Material;

    bool operator==(const DrawOptions&) const = default;
};

/**
 * Draws a core::Mesh shaded as the compositor shades the depth layers: base color factor × base
 * color texture (sRGB) × vertex colors with a headlight, lit as a metallic-roughness material
 * where its texture has one (MaterialTextures::setMetallicRoughness()), or one channel alone
 * (DrawOptions::channel). The stand-in is drawn the same way. Needs a current GL context for every
 * call, the one it was initialized in.
 */
class MeshRenderer {
public:
    MeshRenderer();
    ~MeshRenderer();
    MeshRenderer(const MeshRenderer&) = delete;
    MeshRenderer& operator=(const MeshRenderer&) = delete;

    /** Compiles the shaders; returns an Error if they fail to build. */
    core::Status initialize();
    /**
     * Uploads the mesh (replacing any previous one). With textures, the materials sample that
     * store, which whoever shares it has filled from the mesh's textures (a DepthCompositor of
     * the same context may read it too); without, the renderer makes its own. The triangles of
     * shownBackFaces (ascending; core::MeshTopology::shownBackFaces) show their back faces when
     * back faces are culled, as the depth-layer capture does; so does the stand-in where those
     * triangles' materials lie.
     */
    void setMesh(const core::Mesh& mesh, std::shared_ptr<MaterialTextures> textures = nullptr,
                 std::span<const std::uint32_t> shownBackFaces = {});
    /**
     * As setMesh() above, the geometry (positions, normals, uvs, triangles and their material
     * numbers) from geometry, the materials, textures and vertex colours from look (a
     * PaintTarget::paintedLook(), which spares a copy of the geometry).
     */
    void setMesh(const core::Mesh& geometry, const core::Mesh& look,
                 std::shared_ptr<MaterialTextures> textures,
                 std::span<const std::uint32_t> shownBackFaces);
    /**
     * setMesh() above in three steps, so that its long part can run on another thread:
     * beginMesh() replaces the mesh and makes its buffers, mapped; the fill it returns (empty
     * when there is no GL memory for them: no mesh then) writes geometry's vertices and indices
     * through the mappings, on any thread, once, while geometry lives; finishMesh() unmaps them
     * and the mesh is drawn from then on (none if the fill did not return: out of memory).
     * Meanwhile hasMesh() is false and draw() draws nothing; the fill must have returned (or
     * thrown) before any other call that changes the mesh.
     */
    std::function<void()> beginMesh(const core::Mesh& geometry, const core::Mesh& look,
                                    std::shared_ptr<MaterialTextures> textures,
                                    std::span<const std::uint32_t> shownBackFaces);
    void finishMesh();
    bool hasMesh() const;
    /**
     * Sets the simplified triangles drawn with DrawOptions::standIn: indices into the mesh's
     * vertices (its attributes, textures and colour updates are shared), a material per
     * triangle. Ignored (the stand-in cleared) if an index or material is out of range; a new
     * mesh clears it.
     */
    void setStandIn(std::span<const std::uint32_t> indices,
                    std::span<const std::uint32_t> triangleMaterial);
    void clearStandIn();
    bool hasStandIn() const;
    /** Triangles of the last draw() (0 when it drew nothing). */
    std::size_t lastDrawnTriangles() const;
    /**
     * The textures the materials sample (MaterialTextures: painting updates them there); a
     * material whose base colour texture has a metallic-roughness texture is lit as
     * metallic-roughness. Empty before the first mesh.
     */
    MaterialTextures& textures();
    /** Replaces the colours of vertices [first, first + colors.size()) (clamped to the mesh). */
    void updateVertexColors(std::uint32_t first, std::span<const glm::vec4> colors);
    /** Draws into the currently bound framebuffer, with view.width × view.height as viewport. */
    void draw(const core::View& view, const DrawOptions& options = {});
    /** Triangles draw() draws with options (the stand-in's or the mesh's). */
    std::size_t frameTriangles(const DrawOptions& options) const;
    /**
     * Draws what draw() draws in slices: the triangles [from, from + count) of the frame's
     * frameTriangles(options), in draw()'s order (the clear with the first slice), so the
     * slices of a frame drawn one after the other give draw()'s pixels. Returns where the next
     * slice starts (frameTriangles(options) once the frame is whole).
     */
    std::size_t drawSlice(const core::View& view, const DrawOptions& options, std::size_t from,
                          std::size_t count);
    /**
     * Counts the changes to what draw() shows besides its arguments: a new mesh or stand-in,
     * vertex colours (textures count their own: MaterialTextures::revision()).
     */
    std::uint64_t revision() const;
    /** Frees every GL object; the context must be current. Called by the destructor too. */
    void release();

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace render
