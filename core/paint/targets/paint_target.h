// SPDX-License-Identifier: GPL-3.0-or-later
// core/paint/targets/: where a dab's paint lands: texture and vertex-colour targets, the
// projection context they share, the flood fill, the target over an automatic UV layout.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec4.hpp>

#include "core/base/result.h"
#include "core/model/mesh.h"
#include "core/model/mesh_topology.h"
#include "core/paint/brush/dab.h"
#include "core/paint/paint_layers/paint_layers.h"
#include "core/paint/paint_layers/undo_tiles.h"

namespace core {

struct DepthLayers;

/** Texture tiles are kTextureTile × kTextureTile texels (edge tiles are smaller). */
inline constexpr int kTextureTile = 64;
/** Vertex colours are stored and undone in blocks of this many vertices. */
inline constexpr std::uint32_t kVertexBlock = 256;

/** A changed rectangle of texels of one texture page. */
struct TexelRect {
    std::uint32_t page = 0;
    int x = 0, y = 0, width = 0, height = 0;
};

/** Changed vertices [begin, end). */
struct VertexRange {
    std::uint32_t begin = 0, end = 0;
};

/**
 * What a dab, undo or redo changed, so a GPU copy can be updated without uploading everything:
 * texel rectangles (whole tiles, merged along tile rows) or vertex ranges (whole blocks, merged).
 */
struct PaintChanges {
    std::vector<TexelRect> texels;
    std::vector<VertexRange> vertices;

    bool empty() const { return texels.empty() && vertices.empty(); }
    void clear() {
        texels.clear();
        vertices.clear();
    }
};

/**
 * One element of a paint target: texel y * width + x of a texture page, or a vertex (page 0) of
 * a vertex colour target.
 */
struct PaintElement {
    std::uint32_t page = 0;
    std::uint32_t index = 0;

    friend bool operator==(const PaintElement&, const PaintElement&) = default;
    friend auto operator<=>(const PaintElement&, const PaintElement&) = default;
};

enum class PaintTargetKind : std::uint8_t { Texture, VertexColors };

/** Where painting goes: the base (layer 0) or the paint layer with that id, or its mask. */
struct PaintSelection {
    std::uint64_t layer = 0;
    bool mask = false;

    friend bool operator==(const PaintSelection&, const PaintSelection&) = default;
};

struct PaintTargetOptions {
    /** Empty: a texture if the mesh has UVs, else vertex colours. */
    std::optional<PaintTargetKind> kind;
    /** Size of a new texture (when the mesh has none to paint), clamped to 512..8192. */
    int resolution = 2048;
    /** Seam padding: painted texels are dilated this far into texels no triangle covers. */
    int padding = 4;
    /** Paint the mesh's own base color textures (false: always bake into a new texture). */
    bool reuseTextures = true;
    /**
     * A texture over an automatic UV layout (makePaintTargetWithLayout()) even when the mesh has
     * UVs: for UVs that overlap where the artist wants to paint the places apart.
     */
    bool automaticUvs = false;
    /**
     * A surface point matches a pixel's fragment when its distance to the fragment's triangle
     * plane is at most relativeTolerance × depth + pixelTolerance × (size of a pixel at that
     * depth). Surfaces hidden behind another are further apart than that.
     */
    float relativeTolerance = 1e-3f;
    float pixelTolerance = 1.5f;
};

/**
 * A paint target that paints into paint layers over a read-only base (a texture target today):
 * the stack, where the next stroke goes (the base, a paint layer or its mask), and the
 * composite's refresh after the stack was changed directly. PaintTarget::paintLayers() gives it.
 */
class PaintLayerTarget {
public:
    /**
     * The paint layers over the base. Change them through the Document (its history); after a
     * change made directly, call refresh() with the tiles it affected.
     */
    virtual PaintLayerStack& paintLayerStack() = 0;
    virtual const PaintLayerStack& paintLayerStack() const = 0;
    /** Where the next stroke or fill paints. A selection of a missing layer paints nothing. */
    virtual const PaintSelection& selection() const = 0;
    virtual void setSelection(PaintSelection selection) = 0;
    /**
     * Recomputes the composite in tiles (plane ignored; duplicates allowed) and returns the
     * texel rectangles that changed, for the GPU copy.
     */
    virtual PaintChanges refresh(std::vector<TileKey> tiles) = 0;
    /** The page (texture set) material m is painted into. */
    virtual std::uint32_t materialPage(std::size_t m) const = 0;

protected:
    ~PaintLayerTarget() = default;
};

/**
 * Where paint goes (docs/architecture.md §3 step 6): the paper's paint_object(object, Mp). A stroke
 * is beginStroke(), paint() per dab, endStroke(), which returns the stroke's undo record. Within a
 * stroke every texel or vertex keeps a coverage a (never above the dab's opacity) that rises by
 * flow × opacity × falloff per dab, and its colour is lerp(value at stroke start, brush colour, a)
 * (the original colour for the eraser), so overlapping dabs never build up beyond the opacity.
 *
 * The target owns the painted data; draw the mesh with drawMaterials() (base colour factors are
 * baked in, so they are all 1). It is a TileStore, so TileUndoRecords restore it; not during a
 * stroke.
 */
class PaintTarget : public TileStore {
public:
    ~PaintTarget() override;
    PaintTarget(const PaintTarget&) = delete;
    PaintTarget& operator=(const PaintTarget&) = delete;

    virtual PaintTargetKind kind() const = 0;
    const Mesh& mesh() const;
    /** mesh(), shared: to keep it for work off the GUI thread. */
    std::shared_ptr<const Mesh> sharedMesh() const;

    /**
     * Makes now what the first stroke would make of the projection context (per vertex and per
     * triangle of the mesh: hundreds of megabytes on a 10M-triangle mesh), e.g. on the thread
     * that made the target, so that the first stroke is as quick as the next.
     */
    void prepareForStrokes();
    /**
     * Starts a stroke with brush (colour, hardness, flow, eraser; radius and opacity come with
     * each dab). A stroke in progress is ended first and its record discarded.
     */
    void beginStroke(const Brush& brush);
    bool inStroke() const;
    /**
     * Paints dab: every texel or vertex whose surface point projects into the dab's paintable
     * map at a pixel whose fragment (of layers.stack) lies on the same surface, weighted by the
     * brush falloff at its exact projected position (dab.center in window pixels, pixel centres at
     * +0.5). layers must be the view the dab was tracked in. Returns what changed (valid until the
     * next call); empty outside a stroke. Map entries outside the stack are ignored.
     */
    virtual const PaintChanges& paint(const DepthLayers& layers, const Dab& dab) = 0;
    /**
     * Paints elements at full weight, as a dab covering them would (flood fill): each gets the
     * stroke's opacity of the brush colour; texture pages pad the seams around painted texels.
     * Elements out of range are ignored. Returns what changed (valid until the next call);
     * empty outside a stroke.
     */
    virtual const PaintChanges& paintElements(std::span<const PaintElement> elements) = 0;
    /**
     * Starts a group of dabs painted as one (a dab and its symmetric copies): within it, an
     * element takes the most any of them gives it, not their sum, so copies that overlap (near a
     * mirror plane) do not paint twice. The group lasts until the next call or the stroke's end.
     */
    void beginDabGroup();
    /** Ends the stroke: the record of the tiles it changed (empty if none, or no stroke). */
    TileUndoRecord endStroke();

    /** What undoing or redoing record changes (the tiles it holds), for updating a GPU copy. */
    PaintChanges changes(const TileUndoRecord& record) const;
    /**
     * The target's current, unlit colour (linear RGBA) at a point of triangle given by weights of
     * its three corners (negative ones are taken as 0, the rest normalised): the texel of its page
     * under the interpolated uv, or the interpolated vertex colour. nullopt for a triangle out of
     * range or weights that are not finite or all zero.
     */
    virtual std::optional<glm::vec4> colorAt(std::uint32_t triangle,
                                             const glm::vec3& weights) const = 0;
    /** The mesh's materials as the painted mesh is to be drawn (see the derived classes). */
    const std::vector<Material>& drawMaterials() const { return m_drawMaterials; }
    /** Memory held by the painted data, originals and scratch, in bytes (approximate). */
    virtual std::size_t bytes() const = 0;

    /** The paint layers this target paints into, or nullptr (vertex colours have none yet). */
    virtual PaintLayerTarget* paintLayers() { return nullptr; }
    virtual const PaintLayerTarget* paintLayers() const { return nullptr; }
    /**
     * The texture pages the target paints (none for vertex colours): page i as shown (sRGB RGBA8,
     * the paint layers flattened over the base) and its glTF metallic-roughness texture (linear,
     * G roughness, B metallic). i must be below pageCount().
     */
    virtual std::size_t pageCount() const { return 0; }
    virtual const Image& page(std::size_t i) const;
    virtual const Image& metallicRoughnessPage(std::size_t i) const;
    /** The painted vertex colours (linear RGBA, one per vertex); empty for a texture target. */
    virtual std::span<const glm::vec4> vertexColors() const { return {}; }
    /**
     * Whether page i's roughness or metallic differ from the base's, which the materials'
     * metallic-roughness maps and factors give (or a reopened project's saved base).
     */
    virtual bool metallicRoughnessPainted(std::size_t) const { return false; }
    /**
     * Page i's texture in mesh() (-1 for a page made anew) and whether the page shows still what
     * it showed when the target was made.
     */
    virtual int pageTexture(std::size_t) const { return -1; }
    virtual bool pageUnchanged(std::size_t) const { return false; }
    /**
     * The mesh as painted: drawMaterials() with the pages as its first textures (and its other
     * maps' textures after them, kept files and all; a page's roughness and metallic, where
     * painted, as its materials' metallic-roughness map with factors 1), or its colours.
     */
    Mesh paintedMesh() const;
    /**
     * What paintedMesh() changes of mesh(), without a copy of its geometry: the materials,
     * textures (with their kept files and origins) and vertex colours; the rest left empty.
     */
    Mesh paintedLook() const;

protected:
    struct Context; // the shared dab and stroke machinery, defined in paint_target.cpp

    /** Called by beginStroke() once the brush is set: the target picks the stroke's plane. */
    virtual void strokeStarted() {}
    /** Called by endStroke() when the stroke's record is made. */
    virtual void strokeEnded() {}

    PaintTarget(std::shared_ptr<const Mesh> mesh, std::shared_ptr<const MeshTopology> topology,
                const PaintTargetOptions& options);
    /** Sets the tile layout the stroke state keeps: tiles per page, elements and bytes a tile. */
    void setUpStrokeTiles(const std::vector<std::uint32_t>& tilesPerPage,
                          std::size_t elementsPerTile, std::size_t bytesPerTile);
    /**
     * The checks both targets' create() make (a valid mesh); topology is computed when it is
     * missing or belongs to another mesh.
     */
    static Status checkMesh(const std::shared_ptr<const Mesh>& mesh,
                            std::shared_ptr<const MeshTopology>& topology);
    /** Memory held by the shared dab and stroke state, in bytes (approximate). */
    std::size_t contextBytes() const;
    /** Adds what the tiles keys (sorted here) cover to out: texel rectangles or vertex ranges. */
    virtual void addChanges(std::vector<TileKey>& keys, PaintChanges& out) const = 0;
    /** The changes of the tiles the current dab or elements touched (valid until the next call). */
    const PaintChanges& touchedChanges();

    std::unique_ptr<Context> m_context;
    std::vector<Material> m_drawMaterials;
};

/**
 * Projection painting into base colour textures ("pages", sRGB RGBA8, rows top first, uv (0,0)
 * the top-left texel corner; UVs outside 0..1 repeat). Pages:
 * - each base colour texture the materials use becomes a page, byte for byte, when its
 *   materials' factor is white and the mesh has no vertex colours; otherwise (factor or vertex
 *   colours to fold in) a copy with them baked in, one per distinct factor, so the look does not
 *   change and painted colours show as painted;
 * - all materials without a texture share one new page of options.resolution, filled per texel
 *   from the base colour factor × vertex colours. Their UV layouts are assumed not to overlap
 *   (where they do, painting one paints the other, as in any texture painter).
 * drawMaterials()[m].baseColorTexture is the index of material m's page, factors are 1, and
 * vertex colours are not to be applied (they are baked in).
 */
class TextureTarget final : public PaintTarget, public PaintLayerTarget {
public:
    /**
     * A target for mesh (topology = buildMeshTopology(*mesh), or nullptr to compute it here).
     * An Error if the mesh is invalid, has no UVs or no triangles.
     */
    static Result<std::unique_ptr<TextureTarget>>
    create(std::shared_ptr<const Mesh> mesh, std::shared_ptr<const MeshTopology> topology,
           const PaintTargetOptions& options = {});
    ~TextureTarget() override;
    /**
     * Per material of mesh, the size of the page create() paints it into: its base colour
     * texture's (options.reuseTextures), else options.resolution² (clamped to 512..8192).
     */
    static std::vector<PageSize> materialPageSizes(const Mesh& mesh,
                                                   const PaintTargetOptions& options);

    PaintTargetKind kind() const override { return PaintTargetKind::Texture; }
    const PaintChanges& paint(const DepthLayers& layers, const Dab& dab) override;
    const PaintChanges& paintElements(std::span<const PaintElement> elements) override;
    std::optional<glm::vec4> colorAt(std::uint32_t triangle,
                                     const glm::vec3& weights) const override;
    std::size_t bytes() const override;

    PaintLayerTarget* paintLayers() override { return this; }
    const PaintLayerTarget* paintLayers() const override { return this; }
    std::size_t pageCount() const override { return m_pages.size(); }
    const Image& page(std::size_t i) const override;
    const Image& metallicRoughnessPage(std::size_t i) const override;
    bool metallicRoughnessPainted(std::size_t i) const override;
    int pageTexture(std::size_t i) const override { return m_pages[i].source; }
    bool pageUnchanged(std::size_t i) const override;
    /** The base's texels of page i (RGBA8): painting with no paint layer selected goes here. */
    const std::vector<std::uint8_t>& basePixels(std::size_t i) const;
    /** Page i as created (what the eraser restores on the base). */
    const Image& originalPage(std::size_t i) const { return m_pages[i].original; }

    PaintLayerStack& paintLayerStack() override { return *m_stack; }
    const PaintLayerStack& paintLayerStack() const override { return *m_stack; }
    const PaintSelection& selection() const override { return m_selection; }
    void setSelection(PaintSelection selection) override { m_selection = selection; }
    /** The TileKey::plane of a paint layer's channels (mask false) or of its mask. */
    static std::uint64_t planeKey(std::uint64_t layer, bool mask) {
        return layer == 0 ? 0 : layer * 2 + (mask ? 1 : 0);
    }
    PaintChanges refresh(std::vector<TileKey> tiles) override;
    /**
     * The colour of the current paint layer (its base colour over nothing, linear RGBA with
     * the layer's coverage as alpha; the base's colour when the base is selected), as colorAt().
     */
    std::optional<glm::vec4> layerColorAt(std::uint32_t triangle, const glm::vec3& weights) const;
    /** The mesh texture page i was made from, or -1 for a new page. */
    int pageSource(std::size_t i) const { return m_pages[i].source; }
    /** Per texel of page i: 0 outside every triangle, 1 covered, 2 seam padding. */
    const std::vector<std::uint8_t>& coverage(std::size_t i) const { return m_pages[i].coverage; }
    /** The page triangle t is painted on. */
    std::uint32_t trianglePage(std::size_t t) const;
    /** The page material m is painted on (m below the mesh's material count). */
    std::uint32_t materialPage(std::size_t m) const override { return m_materialPage[m]; }
    int padding() const { return m_padding; }

    std::size_t tileBytes(TileKey key) const override;
    bool readTile(TileKey key, std::span<std::uint8_t> out) const override;
    bool writeTile(TileKey key, std::span<const std::uint8_t> bytes) override;

    struct PadPair {
        std::uint32_t padded = 0; // texel index y * width + x of an uncovered texel
        std::uint32_t source = 0; // the covered texel it copies
    };
    struct Page {
        Image image; // the page's size; its texels are the layer stack's base once created
        Image original;
        std::vector<std::uint8_t> coverage;
        int source = -1;
        glm::vec4 factor{1.0f};
        int tilesX = 0, tilesY = 0;
        std::vector<std::uint32_t> padOffsets; // per tile of the source texel, into padPairs
        std::vector<PadPair> padPairs;
    };

private:
    TextureTarget(std::shared_ptr<const Mesh> mesh, std::shared_ptr<const MeshTopology> topology,
                  const PaintTargetOptions& options);
    /** Pads the seams around the tiles the current dab touched (see PaintTargetOptions). */
    void padTouched();
    /**
     * Raises the stroke's coverage of texel (x, y) of page pageIndex to cover (never lowers it)
     * and blends the texel to it: the flood fill's and the seam padding's texel.
     */
    void coverTexel(std::uint32_t pageIndex, int x, int y, float cover);
    void addChanges(std::vector<TileKey>& keys, PaintChanges& out) const override;
    void strokeStarted() override;
    void strokeEnded() override;
    /** Writes texel (x, y) of page pageIndex for the stroke at coverage cover (see paint()). */
    void writeTexel(std::uint32_t pageIndex, int x, int y, const std::uint8_t* before,
                    std::size_t local, std::size_t tileTexels, float cover);
    /** Recomputes the composite of the tiles the current dab touched. */
    void refreshTouched();
    /** The layer index and whether the mask is meant for a plane key; nullopt if missing. */
    std::optional<std::size_t> layerOfPlane(std::uint64_t plane) const;
    /** The texel (x, y, in the page's pixels) of triangle's page at weights, or false. */
    bool texelAt(std::uint32_t triangle, const glm::vec3& weights, int& x, int& y) const;

    enum class StrokeMode : std::uint8_t { Base, Channels, Mask, Nothing };

    std::vector<Page> m_pages;
    std::vector<std::uint32_t> m_materialPage;
    int m_padding = 4;
    std::unique_ptr<PaintLayerStack> m_stack;
    PaintSelection m_selection;
    // The stroke's plane (strokeStarted()).
    StrokeMode m_mode = StrokeMode::Base;
    bool m_lock = false;
    std::array<TiledPlane*, kPaintChannels> m_planes{};
    TiledPlane* m_mask = nullptr;
    std::array<float, 5> m_values{};            // sRGB base colour, roughness, metallic (0..1)
    std::array<std::int16_t, 5> m_emptyBytes{}; // their emptyTexelByte()
    std::uint8_t m_maskValue = 255;
};

/**
 * Painting into per-vertex colours (linear RGBA), for meshes without UVs or on request. Starts
 * from the mesh's vertex colours (white without) times the base colour factor of the vertex's
 * first triangle's material; drawMaterials() have factor 1 and keep their textures, so a
 * textured mesh shows texture × painted colour.
 */
class VertexColorTarget final : public PaintTarget {
public:
    /** A target for mesh (topology as for TextureTarget); an Error if invalid or empty. */
    static Result<std::unique_ptr<VertexColorTarget>>
    create(std::shared_ptr<const Mesh> mesh, std::shared_ptr<const MeshTopology> topology,
           const PaintTargetOptions& options = {});
    ~VertexColorTarget() override;

    PaintTargetKind kind() const override { return PaintTargetKind::VertexColors; }
    const PaintChanges& paint(const DepthLayers& layers, const Dab& dab) override;
    const PaintChanges& paintElements(std::span<const PaintElement> elements) override;
    std::optional<glm::vec4> colorAt(std::uint32_t triangle,
                                     const glm::vec3& weights) const override;
    std::size_t bytes() const override;

    std::span<const glm::vec4> vertexColors() const override { return m_colors; }
    const std::vector<glm::vec4>& colors() const { return m_colors; }
    const std::vector<glm::vec4>& originalColors() const { return m_original; }

    std::size_t tileBytes(TileKey key) const override;
    bool readTile(TileKey key, std::span<std::uint8_t> out) const override;
    bool writeTile(TileKey key, std::span<const std::uint8_t> bytes) override;

private:
    VertexColorTarget(std::shared_ptr<const Mesh> mesh,
                      std::shared_ptr<const MeshTopology> topology,
                      const PaintTargetOptions& options);
    void addChanges(std::vector<TileKey>& keys, PaintChanges& out) const override;
    /** Sets vertex v to lerp(before, the brush colour or its original, cover). */
    void blendVertex(std::uint32_t v, const std::uint8_t* before, float cover);

    std::vector<glm::vec4> m_colors;
    std::vector<glm::vec4> m_original;
    std::vector<std::uint32_t> m_vertexDab; // per vertex: the last dab that looked at it
};

/**
 * The target options.kind asks for (by default a texture if the mesh has UVs, else vertex
 * colours); an Error as the targets' create() does, or for a texture on a mesh without UVs.
 */
Result<std::unique_ptr<PaintTarget>> makePaintTarget(std::shared_ptr<const Mesh> mesh,
                                                     std::shared_ptr<const MeshTopology> topology,
                                                     const PaintTargetOptions& options = {});

} // namespace core
