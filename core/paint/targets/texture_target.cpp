// SPDX-License-Identifier: GPL-3.0-or-later
// Projection painting into textures (TextureTarget): pages made from the mesh's textures or new,
// seam padding, fills, undo tiles of kTextureTile² texels (the texel loop of a dab is in
// texture_target_dab.cpp).
#include <utility>

#include <glm/common.hpp>
#include <glm/mat4x4.hpp>

#include "core/paint/targets/paint_context.h"
#include "core/paint/targets/texture_tile_layout.h"
#include "core/paint/targets/uv_raster.h"

namespace core {

using uv::scanUv;
using uv::setUpUv;
using uv::UvTriangle;
using uv::wrapIndex;

// ---------------------------------------------------------------------------------------------
// TextureTarget

namespace {

/** Seam padding of one page: which uncovered texels copy which covered one (docs/architecture.md
 * §3). */
void buildPadding(TextureTarget::Page& page, int padding) {
    const int width = page.image.width, height = page.image.height;
    std::vector<std::uint8_t>& coverage = page.coverage;
    std::vector<TextureTarget::PadPair> frontier, next, pairs;
    const auto at = [&](int x, int y) {
        return std::uint32_t(wrapIndex(y, height)) * std::uint32_t(width) +
               std::uint32_t(wrapIndex(x, width));
    };
    static constexpr int kOrthogonal[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    static constexpr int kDiagonal[4][2] = {{1, 1}, {-1, 1}, {1, -1}, {-1, -1}};
    if (padding > 0) {
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const std::uint32_t t = std::uint32_t(y) * std::uint32_t(width) + std::uint32_t(x);
                if (coverage[t] != 1)
                    continue;
                bool border = false;
                for (const auto& d : kOrthogonal)
                    border = border || coverage[at(x + d[0], y + d[1])] == 0;
                for (const auto& d : kDiagonal)
                    border = border || coverage[at(x + d[0], y + d[1])] == 0;
                if (border)
                    frontier.push_back({t, t});
            }
        }
    }
    // Ring by ring, orthogonal neighbours before diagonal ones, so each padded texel copies a
    // near covered texel; the scan order makes the choice deterministic.
    for (int ring = 0; ring < padding && !frontier.empty(); ++ring) {
        next.clear();
        for (const auto* directions : {kOrthogonal, kDiagonal}) {
            for (const TextureTarget::PadPair& f : frontier) {
                const int x = int(f.padded % std::uint32_t(width));
                const int y = int(f.padded / std::uint32_t(width));
                for (int k = 0; k < 4; ++k) {
                    const std::uint32_t n = at(x + directions[k][0], y + directions[k][1]);
                    if (coverage[n] != 0)
                        continue;
                    coverage[n] = 2;
                    pairs.push_back({n, f.source});
                    next.push_back({n, f.source});
                }
            }
        }
        frontier.swap(next);
    }
    // Group by the source texel's tile: a dab pads from the tiles it painted.
    const auto tileOf = [&](std::uint32_t texel) {
        const std::uint32_t x = texel % std::uint32_t(width), y = texel / std::uint32_t(width);
        return (y / kTextureTile) * std::uint32_t(page.tilesX) + x / kTextureTile;
    };
    const std::size_t tiles = std::size_t(page.tilesX) * std::size_t(page.tilesY);
    page.padOffsets.assign(tiles + 1, 0u);
    for (const TextureTarget::PadPair& p : pairs)
        ++page.padOffsets[tileOf(p.source) + 1];
    for (std::size_t i = 0; i < tiles; ++i)
        page.padOffsets[i + 1] += page.padOffsets[i];
    page.padPairs.resize(pairs.size());
    std::vector<std::uint32_t> cursor(page.padOffsets.begin(), page.padOffsets.end() - 1);
    for (const TextureTarget::PadPair& p : pairs)
        page.padPairs[cursor[tileOf(p.source)]++] = p;
}

bool isWhite(const glm::vec4& v) {
    return v == glm::vec4(1.0f);
}

/**
 * A new page for a material of base colour factor: a copy of texture with the factor baked in
 * (texture not nullptr), or resolution² texels of the factor.
 */
TextureTarget::Page makePage(const glm::vec4& factor, const Image* texture, int textureIndex,
                             int resolution) {
    const SrgbTables& srgb = SrgbTables::get();
    TextureTarget::Page page;
    page.factor = factor;
    if (texture != nullptr) {
        page.source = textureIndex;
        page.image = *texture;
        if (!isWhite(page.factor)) {
            for (std::size_t i = 0; i < page.image.rgba.size(); i += 4) {
                std::uint8_t* px = &page.image.rgba[i];
                for (int k = 0; k < 3; ++k)
                    px[k] = srgb.encode(srgb.decode[px[k]] * page.factor[k]);
                px[3] = encodeUnorm(float(px[3]) / 255.0f * page.factor[3]);
            }
        }
    } else {
        page.image.width = page.image.height = resolution;
        page.image.rgba.resize(std::size_t(resolution) * std::size_t(resolution) * 4);
        const std::uint8_t fill[4] = {srgb.encode(page.factor.r), srgb.encode(page.factor.g),
                                      srgb.encode(page.factor.b), encodeUnorm(page.factor.a)};
        for (std::size_t i = 0; i < page.image.rgba.size(); i += 4)
            std::memcpy(&page.image.rgba[i], fill, 4);
    }
    page.tilesX = (page.image.width + kTextureTile - 1) / kTextureTile;
    page.tilesY = (page.image.height + kTextureTile - 1) / kTextureTile;
    page.coverage.assign(std::size_t(page.image.width) * std::size_t(page.image.height), 0u);
    return page;
}

/**
 * The base colour texture of material m that a target made with options paints into, or nullptr
 * (a new page). Texel indices are 32-bit and a dab keeps texel coordinates in 16 bits: a texture
 * beyond 16384² or 65535 texels on a side is baked into a new page instead.
 */
const Image* paintableTexture(const Mesh& mesh, std::size_t m, const PaintTargetOptions& options) {
    const int texture = mesh.materials[m].baseColorTexture;
    const Image* image = texture >= 0 && std::size_t(texture) < mesh.textures.size()
                             ? &mesh.textures[std::size_t(texture)]
                             : nullptr;
    const bool paintable =
        options.reuseTextures && image != nullptr && !image->empty() &&
        std::int64_t(image->width) * image->height <= std::int64_t(16384) * 16384 &&
        image->width <= 65535 && image->height <= 65535;
    return paintable ? image : nullptr;
}

/**
 * The pages: one per (texture, factor) of textured materials, one shared new page for the rest;
 * materialPage and drawMaterials' textures say each material's.
 */
void makePages(const Mesh& mesh, const PaintTargetOptions& options,
               std::vector<TextureTarget::Page>& pages, std::vector<std::uint32_t>& materialPage,
               std::vector<Material>& drawMaterials) {
    materialPage.assign(mesh.materials.size(), 0u);
    std::uint32_t newPage = kNone;
    const int resolution = std::clamp(options.resolution, 512, 8192);
    for (std::size_t m = 0; m < mesh.materials.size(); ++m) {
        const Material& material = mesh.materials[m];
        const int texture = material.baseColorTexture;
        const Image* image = paintableTexture(mesh, m, options);
        const bool textured = image != nullptr;
        std::uint32_t index = kNone;
        if (textured) {
            for (std::size_t p = 0; p < pages.size(); ++p)
                if (pages[p].source == texture && pages[p].factor == material.baseColorFactor)
                    index = std::uint32_t(p);
        } else {
            index = newPage;
        }
        if (index == kNone) {
            index = std::uint32_t(pages.size());
            if (!textured)
                newPage = index;
            pages.push_back(makePage(material.baseColorFactor, textured ? image : nullptr, texture,
                                     resolution));
        }
        materialPage[m] = index;
        drawMaterials[m].baseColorTexture = int(index);
    }
}

/**
 * The coverage of every page, baking factor × vertex colours (× texture) into the texels of new
 * and baked pages; a page that is its texture byte for byte only records coverage.
 */
void coverPages(const Mesh& mesh, const std::vector<std::uint32_t>& materialPage, bool bakeColors,
                std::vector<TextureTarget::Page>& pages) {
    const SrgbTables& srgb = SrgbTables::get();
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const Material& material = mesh.materials[mesh.triangleMaterial[t]];
        TextureTarget::Page& page = pages[materialPage[mesh.triangleMaterial[t]]];
        const int width = page.image.width, height = page.image.height;
        glm::vec2 uv[3];
        glm::vec4 colors[3];
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t v = mesh.indices[3 * t + std::size_t(c)];
            uv[c] = mesh.uvs[v];
            colors[c] = bakeColors ? mesh.colors[v] : glm::vec4(1.0f);
        }
        UvTriangle r;
        if (!setUpUv(uv, width, height, r))
            continue;
        // Triangles spread over many repeats of the texture would take forever to visit.
        if (double(r.maxX - r.minX + 1) * double(r.maxY - r.minY + 1) >
            4.0 * double(width) * double(height))
            continue;
        // A textured page bakes from the mesh's texture, not from the page, so a texel that
        // overlapping charts visit twice is not multiplied twice.
        const bool bake = bakeColors || page.source < 0;
        const std::uint8_t* source =
            page.source >= 0 ? mesh.textures[std::size_t(page.source)].rgba.data() : nullptr;
        const glm::vec4 factor = page.source < 0 ? material.baseColorFactor : page.factor;
        const double invArea = 1.0 / double(r.area);
        scanUv(r, r.minX, r.maxX, r.minY, r.maxY,
               [&](int x, int y, std::int64_t e0, std::int64_t e1, std::int64_t e2) {
                   const std::size_t texel =
                       std::size_t(wrapIndex(y, height)) * std::size_t(width) +
                       std::size_t(wrapIndex(x, width));
                   page.coverage[texel] = 1;
                   if (!bake)
                       return;
                   const float l0 = float(double(e0) * invArea), l1 = float(double(e1) * invArea),
                               l2 = float(double(e2) * invArea);
                   const glm::vec4 color =
                       factor * (l0 * colors[r.corner[0]] + l1 * colors[r.corner[1]] +
                                 l2 * colors[r.corner[2]]);
                   std::uint8_t* px = &page.image.rgba[texel * 4];
                   if (source) {
                       const std::uint8_t* in = source + texel * 4;
                       for (int k = 0; k < 3; ++k)
                           px[k] = srgb.encode(srgb.decode[in[k]] * color[k]);
                       px[3] = encodeUnorm(float(in[3]) / 255.0f * color[3]);
                   } else {
                       for (int k = 0; k < 3; ++k)
                           px[k] = srgb.encode(color[k]);
                       px[3] = encodeUnorm(color[3]);
                   }
               });
    }
}

/** The seam padding of every page; each page as it is now becomes its original. */
void padPages(int padding, bool bakeColors, std::vector<TextureTarget::Page>& pages) {
    for (TextureTarget::Page& page : pages) {
        buildPadding(page, padding);
        // A page made here gets its padding texels from the charts, so filtering at chart
        // borders shows the surface's colour; a texture kept byte for byte stays as it was.
        const bool baked = page.source < 0 || bakeColors; // baked texel by texel
        if (baked)
            for (const TextureTarget::PadPair& p : page.padPairs)
                std::memcpy(&page.image.rgba[std::size_t(p.padded) * 4],
                            &page.image.rgba[std::size_t(p.source) * 4], 4);
        page.original = page.image;
    }
}

/**
 * The paint layer stack whose base is the pages' texels (which move there), with roughness and
 * metallic starting from the materials' metallic-roughness maps and factors.
 */
std::unique_ptr<PaintLayerStack> baseOfPages(const Mesh& mesh,
                                             const std::vector<std::uint32_t>& materialPage,
                                             std::vector<TextureTarget::Page>& pages) {
    std::vector<PageSize> sizes;
    std::vector<std::vector<std::uint8_t>> baseColor, baseMr;
    for (std::size_t p = 0; p < pages.size(); ++p) {
        TextureTarget::Page& page = pages[p];
        sizes.push_back({page.image.width, page.image.height});
        baseMr.push_back(startingMetallicRoughness(mesh, materialPage, std::uint32_t(p),
                                                   page.image.width, page.image.height)
                             .rgba);
        baseColor.push_back(std::move(page.image.rgba));
        page.image.rgba.clear();
    }
    return std::make_unique<PaintLayerStack>(std::move(sizes), std::move(baseColor),
                                             std::move(baseMr));
}

} // namespace

TextureTarget::TextureTarget(std::shared_ptr<const Mesh> mesh,
                             std::shared_ptr<const MeshTopology> topology,
                             const PaintTargetOptions& options)
    : PaintTarget(std::move(mesh), std::move(topology), options) {}

TextureTarget::~TextureTarget() = default;

std::vector<PageSize> TextureTarget::materialPageSizes(const Mesh& mesh,
                                                       const PaintTargetOptions& options) {
    const int resolution = std::clamp(options.resolution, 512, 8192);
    std::vector<PageSize> sizes;
    for (std::size_t m = 0; m < mesh.materials.size(); ++m) {
        const Image* image = paintableTexture(mesh, m, options);
        sizes.push_back(image ? PageSize{image->width, image->height}
                              : PageSize{resolution, resolution});
    }
    return sizes;
}

Result<std::unique_ptr<TextureTarget>>
TextureTarget::create(std::shared_ptr<const Mesh> mesh,
                      std::shared_ptr<const MeshTopology> topology,
                      const PaintTargetOptions& options) {
    if (const Status paintable = checkMesh(mesh, topology); !paintable)
        return paintable.takeError();
    if (!mesh->hasUvs())
        return Error{"the mesh has no texture coordinates to paint a texture with",
                     ErrorKind::BadInput};
    std::unique_ptr<TextureTarget> target(new TextureTarget(mesh, topology, options));
    target->m_padding = std::clamp(options.padding, 0, kTextureTile);

    // Vertex colours other than white have to be baked in; white ones change nothing.
    const bool bakeColors =
        mesh->hasColors() && std::any_of(mesh->colors.begin(), mesh->colors.end(),
                                         [](const glm::vec4& c) { return !isWhite(c); });
    std::vector<Page>& pages = target->m_pages;
    makePages(*mesh, options, pages, target->m_materialPage, target->m_drawMaterials);
    coverPages(*mesh, target->m_materialPage, bakeColors, pages);
    padPages(target->m_padding, bakeColors, pages);
    target->m_stack = baseOfPages(*mesh, target->m_materialPage, pages);

    std::vector<std::uint32_t> tilesPerPage;
    for (const Page& page : pages)
        tilesPerPage.push_back(std::uint32_t(page.tilesX * page.tilesY));
    target->setUpStrokeTiles(tilesPerPage, std::size_t(kTextureTile) * kTextureTile,
                             std::size_t(kTextureTile) * kTextureTile * kPaintLayerTexelBytes);
    return Result<std::unique_ptr<TextureTarget>>(std::move(target));
}

std::uint32_t TextureTarget::trianglePage(std::size_t t) const {
    return m_materialPage[mesh().triangleMaterial[t]];
}

bool TextureTarget::texelAt(std::uint32_t triangle, const glm::vec3& weights, int& x,
                            int& y) const {
    const Mesh& m = mesh();
    glm::vec3 w;
    if (!normalizedWeights(m, triangle, weights, w))
        return false;
    glm::vec2 uv(0.0f);
    for (int c = 0; c < 3; ++c)
        uv += w[c] * m.uvs[m.indices[3 * std::size_t(triangle) + std::size_t(c)]];
    const Image& image = m_pages[trianglePage(triangle)].image;
    if (image.empty())
        return false;
    // The texel whose square holds the point (UVs repeat, as when painting).
    const double u = double(uv.x) - std::floor(double(uv.x));
    const double v = double(uv.y) - std::floor(double(uv.y));
    x = std::clamp(int(u * image.width), 0, image.width - 1);
    y = std::clamp(int(v * image.height), 0, image.height - 1);
    return true;
}

std::optional<glm::vec4> TextureTarget::colorAt(std::uint32_t triangle,
                                                const glm::vec3& weights) const {
    int x = 0, y = 0;
    if (!texelAt(triangle, weights, x, y))
        return std::nullopt;
    const Image& image = page(trianglePage(triangle));
    const std::uint8_t* texel =
        &image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
    return glm::vec4(srgbToLinear(texel[0]), srgbToLinear(texel[1]), srgbToLinear(texel[2]),
                     float(texel[3]) / 255.0f);
}

std::optional<glm::vec4> TextureTarget::layerColorAt(std::uint32_t triangle,
                                                     const glm::vec3& weights) const {
    int x = 0, y = 0;
    if (!texelAt(triangle, weights, x, y))
        return std::nullopt;
    const std::uint32_t p = trianglePage(triangle);
    const std::optional<std::size_t> index = m_stack->indexOf(m_selection.layer);
    if (m_selection.layer == 0 || !index) {
        const std::uint8_t* texel = &m_stack->baseColor(
            p)[(std::size_t(y) * std::size_t(m_pages[p].image.width) + std::size_t(x)) * 4];
        return glm::vec4(srgbToLinear(texel[0]), srgbToLinear(texel[1]), srgbToLinear(texel[2]),
                         float(texel[3]) / 255.0f);
    }
    const PaintLayer& layer = m_stack->layer(*index);
    if (layer.settings.kind == PaintLayerKind::Fill) {
        if (!layer.settings.fill.baseColor)
            return glm::vec4(0.0f);
        const glm::vec3 c = *layer.settings.fill.baseColor;
        const SrgbTables& srgb = SrgbTables::get();
        return glm::vec4(srgb.decode[encodeUnorm(c.r)], srgb.decode[encodeUnorm(c.g)],
                         srgb.decode[encodeUnorm(c.b)], 1.0f);
    }
    const TiledPlane* plane = layer.channels[0].get();
    if (plane == nullptr)
        return glm::vec4(0.0f);
    const std::uint8_t* texel = plane->texel(p, x, y);
    return glm::vec4(srgbToLinear(texel[0]), srgbToLinear(texel[1]), srgbToLinear(texel[2]),
                     float(texel[3]) / 255.0f);
}

const Image& TextureTarget::page(std::size_t i) const {
    return m_stack->compositeImage(std::uint32_t(i));
}

bool TextureTarget::pageUnchanged(std::size_t i) const {
    return page(i).rgba == m_pages[i].original.rgba;
}

bool TextureTarget::metallicRoughnessPainted(std::size_t i) const {
    // The base's roughness and metallic are never painted (paint layers hold them), so the
    // composite differs from the base exactly where a paint layer changes them.
    const Image& composite = metallicRoughnessPage(i);
    return !composite.empty() && composite.rgba != m_stack->baseMetallicRoughness(std::uint32_t(i));
}

const Image& TextureTarget::metallicRoughnessPage(std::size_t i) const {
    return m_stack->compositeMetallicRoughnessImage(std::uint32_t(i));
}

const std::vector<std::uint8_t>& TextureTarget::basePixels(std::size_t i) const {
    return m_stack->baseColor(std::uint32_t(i));
}

void TextureTarget::strokeStarted() {
    Context& c = *m_context;
    c.clearTriangleCover();
    const Brush& brush = c.brush;
    m_mode = StrokeMode::Base;
    m_planes = {};
    m_mask = nullptr;
    c.strokePlane = 0;
    // The composite changes in the base colour on the base, in every channel through a mask,
    // and in the painted channels on a layer.
    m_stack->beginStroke(0, 1u);
    if (m_selection.layer == 0) {
        if (!brush.paintBaseColor && !brush.eraser)
            m_mode = StrokeMode::Nothing;
        return;
    }
    const std::optional<std::size_t> index = m_stack->indexOf(m_selection.layer);
    if (!index) {
        m_mode = StrokeMode::Nothing;
        return;
    }
    const PaintLayer& layer = m_stack->layer(*index);
    c.strokePlane = planeKey(m_selection.layer, m_selection.mask);
    if (m_selection.mask) {
        m_mode = StrokeMode::Mask;
        m_mask = &m_stack->maskPlane(*index);
        m_stack->beginStroke(m_selection.layer, 7u);
        // A mask takes the brush colour's lightness: white shows, black hides.
        const glm::vec4 lin = c.colorLinear;
        m_maskValue = SrgbTables::get().encode(0.2126f * lin.r + 0.7152f * lin.g + 0.0722f * lin.b);
        return;
    }
    if (layer.settings.kind == PaintLayerKind::Fill) {
        m_mode = StrokeMode::Nothing; // uniform values: only its mask can be painted
        return;
    }
    m_mode = StrokeMode::Channels;
    m_lock = layer.settings.lockTransparency;
    const bool on[kPaintChannels] = {brush.paintBaseColor, brush.paintRoughness,
                                     brush.paintMetallic};
    for (std::size_t ch = 0; ch < kPaintChannels; ++ch) {
        // The eraser clears whatever the layer holds; paint goes into the brush's channels.
        if (brush.eraser ? layer.channels[ch] != nullptr : on[ch])
            m_planes[ch] = m_stack->channelPlane(*index, PaintChannel(ch));
    }
    if (std::all_of(m_planes.begin(), m_planes.end(), [](TiledPlane* p) { return !p; }))
        m_mode = StrokeMode::Nothing;
    unsigned channels = 0;
    for (std::size_t ch = 0; ch < kPaintChannels; ++ch)
        if (m_planes[ch] != nullptr)
            channels |= 1u << ch;
    m_stack->beginStroke(m_selection.layer, channels);
    for (int k = 0; k < 3; ++k)
        m_values[std::size_t(k)] = float(c.colorBytes[std::size_t(k)]) / 255.0f;
    m_values[3] = std::clamp(std::isfinite(brush.roughness) ? brush.roughness : 0.0f, 0.0f, 1.0f);
    m_values[4] = std::clamp(std::isfinite(brush.metallic) ? brush.metallic : 0.0f, 0.0f, 1.0f);
    for (std::size_t k = 0; k < m_values.size(); ++k)
        m_emptyBytes[k] = emptyTexelByte(m_values[k]);
}

void TextureTarget::strokeEnded() {
    m_stack->endStroke();
}

void TextureTarget::writeTexel(std::uint32_t pageIndex, int x, int y, const std::uint8_t* before,
                               std::size_t local, std::size_t tileTexels, float cover) {
    Context& c = *m_context;
    const bool eraser = c.brush.eraser;
    switch (m_mode) {
    case StrokeMode::Base: {
        const std::size_t at =
            (std::size_t(y) * std::size_t(m_pages[pageIndex].image.width) + std::size_t(x)) * 4;
        blendTexel(&m_stack->baseColor(pageIndex)[at], before + local * 4,
                   eraser ? &m_pages[pageIndex].original.rgba[at] : c.colorBytes.data(), cover);
        return;
    }
    case StrokeMode::Channels:
        for (std::size_t ch = 0; ch < kPaintChannels; ++ch) {
            TiledPlane* plane = m_planes[ch];
            if (plane == nullptr)
                continue;
            const int n = ch == 0 ? 3 : 1;
            const std::uint8_t* start =
                before + channelOffset(ch, tileTexels) + local * std::size_t(n + 1);
            std::uint8_t* texel = plane->writableTexel(pageIndex, x, y);
            if (eraser)
                eraseTexel(texel, start, n, cover);
            else
                paintTexel(texel, start, n, &m_values[ch == 0 ? 0 : ch + 2], cover, m_lock,
                           &m_emptyBytes[ch == 0 ? 0 : ch + 2]);
        }
        return;
    case StrokeMode::Mask: {
        const float from = float(before[local]);
        const float to = eraser ? 255.0f : float(m_maskValue);
        *m_mask->writableTexel(pageIndex, x, y) =
            std::uint8_t(std::lround(from + (to - from) * std::clamp(cover, 0.0f, 1.0f)));
        return;
    }
    case StrokeMode::Nothing:
        return;
    }
}

void TextureTarget::padTouched() {
    Context& c = *m_context;
    // Seam padding: uncovered texels next to charts take the coverage of the texel they copy,
    // blended over their own stroke-start value, so the eraser restores them exactly too.
    const std::size_t paintedTiles = c.touched.size(); // padding adds to the list
    for (std::size_t i = 0; i < paintedTiles; ++i) {
        const TileKey key = c.slots[c.touched[i]].key;
        Page& page = m_pages[key.page];
        const int width = page.image.width;
        const std::uint32_t begin = page.padOffsets[key.tile], end = page.padOffsets[key.tile + 1];
        if (begin == end)
            continue;
        const std::size_t sourceSlot = c.touched[i];
        const int sourceTileX = int(key.tile % std::uint32_t(page.tilesX)) * kTextureTile;
        const int sourceTileY = int(key.tile / std::uint32_t(page.tilesX)) * kTextureTile;
        const int sourceWidth = std::min(kTextureTile, width - sourceTileX);
        for (std::uint32_t j = begin; j < end; ++j) {
            const PadPair pair = page.padPairs[j];
            const int sx = int(pair.source % std::uint32_t(width)) - sourceTileX;
            const int sy = int(pair.source / std::uint32_t(width)) - sourceTileY;
            const float sourceCover =
                c.slots[sourceSlot]
                    .alpha[std::size_t(sy) * std::size_t(sourceWidth) + std::size_t(sx)];
            if (!(sourceCover > 0.0f))
                continue;
            coverTexel(key.page, int(pair.padded % std::uint32_t(width)),
                       int(pair.padded / std::uint32_t(width)), sourceCover);
        }
    }
}

void TextureTarget::coverTexel(std::uint32_t pageIndex, int x, int y, float cover) {
    Context& c = *m_context;
    Page& page = m_pages[pageIndex];
    const int width = page.image.width;
    const std::uint32_t tile = std::uint32_t(y / kTextureTile) * std::uint32_t(page.tilesX) +
                               std::uint32_t(x / kTextureTile);
    const std::int32_t slot = c.slotFor(*this, pageIndex, tile);
    StrokeTile& st = c.slots[std::size_t(slot)];
    const int tileWidth = std::min(kTextureTile, width - (x / kTextureTile) * kTextureTile);
    const std::size_t local =
        std::size_t(y % kTextureTile) * std::size_t(tileWidth) + std::size_t(x % kTextureTile);
    if (!(cover > st.alpha[local]))
        return;
    st.alpha[local] = cover;
    c.touch(slot);
    Context::wrote(st, x % kTextureTile, y % kTextureTile);
    const int tileHeight =
        std::min(kTextureTile, page.image.height - (y / kTextureTile) * kTextureTile);
    writeTexel(pageIndex, x, y, st.before.data(), local,
               std::size_t(tileWidth) * std::size_t(tileHeight), cover);
}

const PaintChanges& TextureTarget::paintElements(std::span<const PaintElement> elements) {
    Context& c = *m_context;
    const float cover = c.beginElements();
    if (!(cover > 0.0f) || m_mode == StrokeMode::Nothing)
        return c.changes;
    for (const PaintElement& e : elements) {
        if (e.page >= m_pages.size())
            continue;
        Page& page = m_pages[e.page];
        const int width = page.image.width;
        if (std::size_t(e.index) >= std::size_t(width) * std::size_t(page.image.height))
            continue;
        coverTexel(e.page, int(e.index % std::uint32_t(width)), int(e.index / std::uint32_t(width)),
                   cover);
    }
    padTouched();
    refreshTouched();
    return touchedChanges();
}

} // namespace core
