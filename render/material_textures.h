// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <vector>

#include "core/model/mesh.h"
#include "render/paint_texture.h"

namespace render {

/**
 * The textures a mesh's materials sample, on the GPU once: both renderers of a view read the
 * same store (they share its GL context), so a dab's texels are uploaded once. Per mesh texture
 * its base colour texture (sRGB, mipmapped, repeating) and, once set, the metallic-roughness
 * texture that goes with it (linear: G roughness, B metallic). Needs the context it was filled
 * in to be current for every call but the getters.
 */
class MaterialTextures {
public:
    MaterialTextures() = default;
    ~MaterialTextures() { release(); }
    MaterialTextures(const MaterialTextures&) = delete;
    MaterialTextures& operator=(const MaterialTextures&) = delete;

    /**
     * Uploads every texture of a mesh (replacing all, metallic-roughness ones dropped); an empty
     * image gets none.
     */
    void create(const std::vector<core::Image>& textures);
    /**
     * Sets the metallic-roughness texture of mesh texture `texture` (same size); ignored for an
     * unknown texture or an empty image.
     */
    void setMetallicRoughness(std::uint32_t texture, const core::Image& image);
    /**
     * Painting: replaces texels [x, x + width) × [y, y + height) of mesh texture `texture` with
     * those of image (its painted copy, same size), mip levels included; ignored for an unknown
     * texture.
     */
    void updateTexels(std::uint32_t texture, int x, int y, int width, int height,
                      const core::Image& image);
    /** Painting: as updateTexels() for the metallic-roughness texture of `texture`. */
    void updateMetallicRoughness(std::uint32_t texture, int x, int y, int width, int height,
                                 const core::Image& image);

    std::size_t size() const { return m_baseColor.size(); }
    /** Mesh texture `texture`'s base colour texture, nullptr when unknown or empty. */
    const PaintTexture* baseColor(std::size_t texture) const;
    /** Its metallic-roughness texture, nullptr when it has none. */
    const PaintTexture* metallicRoughness(std::size_t texture) const;
    /**
     * Mesh texture `texture` read as plain values (a view of the base colour texture's storage
     * without sRGB decoding: normal and occlusion maps), 0 when unknown or empty. It shows
     * painting's updates too.
     */
    unsigned linearView(std::size_t texture) const;
    /** Frees every texture; the context must be current. */
    void release();
    /** Counts the calls that changed a texture (any of the above but the getters). */
    std::uint64_t revision() const { return m_revision; }

private:
    static unsigned makeLinearView(unsigned texture);

    std::vector<PaintTexture> m_baseColor;
    std::vector<PaintTexture> m_metallicRoughness; // id 0: none
    std::vector<unsigned> m_linearViews;           // 0: none
    std::uint64_t m_revision = 0;
};

} // namespace render
