// SPDX-License-Identifier: GPL-3.0-or-later
// What both paint targets share: the stroke (its start, its tiles, the undo record at its end),
// the checks on the mesh, and makePaintTarget() choosing between them. The targets themselves are
// in texture_target.cpp and vertex_color_target.cpp, their shared dab machinery in
// paint_context.cpp.
#include "core/paint/targets/paint_target.h"

#include <map>
#include <utility>

#include "core/paint/targets/paint_context.h"

namespace core {

// ---------------------------------------------------------------------------------------------
// PaintTarget

PaintTarget::PaintTarget(std::shared_ptr<const Mesh> mesh,
                         std::shared_ptr<const MeshTopology> topology,
                         const PaintTargetOptions& options)
    : m_context(std::make_unique<Context>()) {
    Context& c = *m_context;
    c.mesh = std::move(mesh);
    c.topology = std::move(topology);
    c.options = options;
    c.marks.resize(c.mesh->triangleCount());
    m_drawMaterials = c.mesh->materials;
    for (Material& m : m_drawMaterials)
        m.baseColorFactor = glm::vec4(1.0f);
}

PaintTarget::~PaintTarget() = default;

const Image& PaintTarget::page(std::size_t) const {
    static const Image none;
    return none; // no pages: pageCount() is 0
}

const Image& PaintTarget::metallicRoughnessPage(std::size_t i) const {
    return PaintTarget::page(i);
}

namespace {

/**
 * Appends the textures of painted's maps other than the base colour (indices of source's), with
 * their kept files and origins.
 */
class MapKeeper {
public:
    MapKeeper(const Mesh& source, Mesh& painted) : m_source(source), m_painted(painted) {
        m_painted.textureSources.assign(m_painted.textures.size(), EncodedImage{});
        m_painted.textureOrigins.assign(m_painted.textures.size(), TextureOrigin{});
    }
    /** Appends image (no kept file, origin); returns its index. */
    int add(const Image& image, const EncodedImage* file = nullptr, TextureOrigin origin = {}) {
        m_painted.textures.push_back(image);
        m_painted.textureSources.push_back(file ? *file : EncodedImage{});
        m_painted.textureOrigins.push_back(origin);
        return int(m_painted.textures.size() - 1);
    }
    void keep(MaterialMap& map) {
        if (map.texture < 0)
            return;
        const auto [it, added] = m_kept.emplace(map.texture, -1);
        if (added)
            it->second = add(m_source.textures[std::size_t(map.texture)],
                             m_source.textureSource(map.texture), origin(map.texture, true));
        map.texture = it->second;
    }
    /**
     * Page p, made from the source's texture (-1: none): its origin, and the texture's file
     * where the page is that texture byte for byte.
     */
    void page(std::size_t p, int texture, bool unchanged) {
        m_painted.textureOrigins[p] = origin(texture, unchanged);
        const EncodedImage* file = m_source.textureSource(texture);
        if (file && m_painted.textures[p].width == m_source.textures[std::size_t(texture)].width &&
            m_painted.textures[p].rgba == m_source.textures[std::size_t(texture)].rgba)
            m_painted.textureSources[p] = *file;
    }

private:
    TextureOrigin origin(int texture, bool unchanged) const {
        if (texture < 0 || std::size_t(texture) >= m_source.textureOrigins.size())
            return {-1, unchanged && texture < 0};
        const TextureOrigin& o = m_source.textureOrigins[std::size_t(texture)];
        return {o.image, o.unchanged && unchanged};
    }

    const Mesh& m_source;
    Mesh& m_painted;
    std::map<int, int> m_kept; // source texture -> painted texture
};

} // namespace

Mesh PaintTarget::paintedLook() const {
    const Mesh& source = mesh();
    Mesh look;
    look.materials = drawMaterials();
    if (pageCount() == 0) {
        look.textures = source.textures;
        look.textureSources = source.textureSources;
        look.textureOrigins = source.textureOrigins;
        look.colors = source.colors;
    } else {
        for (std::size_t i = 0; i < pageCount(); ++i)
            look.textures.push_back(page(i));
        MapKeeper keeper(source, look); // the colours are baked into the pages
        for (std::size_t i = 0; i < pageCount(); ++i)
            keeper.page(i, pageTexture(i), pageUnchanged(i));
        std::map<std::size_t, int> painting; // page -> its painted metallic-roughness
        for (Material& m : look.materials) {
            keeper.keep(m.normal);
            keeper.keep(m.occlusion);
            keeper.keep(m.emissive);
            const auto p = std::size_t(m.baseColorTexture);
            if (m.baseColorTexture < 0 || p >= pageCount() || !metallicRoughnessPainted(p)) {
                keeper.keep(m.metallicRoughness);
                continue;
            }
            const auto [it, added] = painting.emplace(p, -1);
            if (added)
                it->second = keeper.add(metallicRoughnessPage(p));
            m.metallicRoughness = MaterialMap{it->second, glm::mat3(1.0f)};
            m.metallicFactor = m.roughnessFactor = 1.0f;
        }
    }
    if (const std::span<const glm::vec4> colors = vertexColors(); !colors.empty())
        look.colors.assign(colors.begin(), colors.end());
    return look;
}

Mesh PaintTarget::paintedMesh() const {
    Mesh painted = mesh();
    Mesh look = paintedLook();
    painted.materials = std::move(look.materials);
    painted.textures = std::move(look.textures);
    painted.textureSources = std::move(look.textureSources);
    painted.textureOrigins = std::move(look.textureOrigins);
    painted.colors = std::move(look.colors);
    return painted;
}

const Mesh& PaintTarget::mesh() const {
    return *m_context->mesh;
}

std::shared_ptr<const Mesh> PaintTarget::sharedMesh() const {
    return m_context->mesh;
}

Status PaintTarget::checkMesh(const std::shared_ptr<const Mesh>& mesh,
                              std::shared_ptr<const MeshTopology>& topology) {
    if (!mesh)
        return Error{"no mesh to paint"};
    if (const Status valid = mesh->validate(); !valid)
        return Error{"cannot paint the mesh: " + valid.error(), ErrorKind::BadInput};
    if (!topology || topology->triangleCount() != mesh->triangleCount())
        topology = std::make_shared<const MeshTopology>(buildMeshTopology(*mesh));
    return {};
}

std::size_t PaintTarget::contextBytes() const {
    const Context& c = *m_context;
    std::size_t views = c.current.bytes();
    for (const ViewState& kept : c.keptViews)
        views += kept.bytes();
    return views + c.marks.capacity() * sizeof(TriangleMark) +
           (c.window.capacity() + c.windowSums.capacity()) * sizeof(std::uint32_t) +
           c.triangleCover.capacity() * sizeof(float) +
           c.coveredTriangles.capacity() * sizeof(std::uint32_t) +
           c.slots.size() * (c.elementsPerTile * sizeof(float) + c.bytesPerTile);
}

PaintChanges PaintTarget::changes(const TileUndoRecord& record) const {
    PaintChanges result;
    std::vector<TileKey> keys;
    for (std::size_t i = 0; i < record.tileCount(); ++i)
        if (tileBytes(record.tile(i)) > 0)
            keys.push_back(record.tile(i));
    addChanges(keys, result);
    return result;
}

const PaintChanges& PaintTarget::touchedChanges() {
    Context& c = *m_context;
    c.keys.clear();
    for (const std::uint32_t slot : c.touched)
        c.keys.push_back(c.slots[slot].key);
    addChanges(c.keys, c.changes);
    return c.changes;
}

void PaintTarget::setUpStrokeTiles(const std::vector<std::uint32_t>& tilesPerPage,
                                   std::size_t elementsPerTile, std::size_t bytesPerTile) {
    Context& c = *m_context;
    c.tileSlot.clear();
    for (const std::uint32_t tiles : tilesPerPage)
        c.tileSlot.emplace_back(tiles, -1);
    c.elementsPerTile = elementsPerTile;
    c.bytesPerTile = bytesPerTile;
    c.slots.clear();
    c.slotsUsed = 0;
    c.scratch.resize(bytesPerTile);
}

void PaintTarget::prepareForStrokes() {
    m_context->prepareView();
}

void PaintTarget::beginStroke(const Brush& brush) {
    Context& c = *m_context;
    if (c.inStroke)
        endStroke();
    c.inStroke = true;
    c.group = 0;
    c.brush = brush;
    c.strokePlane = 0;
    const SrgbTables& t = SrgbTables::get();
    for (int k = 0; k < 4; ++k) {
        c.colorLinear[k] =
            std::clamp(std::isfinite(brush.color[k]) ? brush.color[k] : 0.0f, 0.0f, 1.0f);
        c.colorBytes[std::size_t(k)] =
            k < 3 ? t.encode(c.colorLinear[k]) : encodeUnorm(c.colorLinear[k]);
    }
    strokeStarted();
}

void PaintTarget::beginDabGroup() {
    Context& c = *m_context;
    if (++c.groupSerial == 0) {
        for (StrokeTile& s : c.slots)
            s.group = 0;
        c.groupSerial = 1;
    }
    c.group = c.groupSerial;
}

bool PaintTarget::inStroke() const {
    return m_context->inStroke;
}

TileUndoRecord PaintTarget::endStroke() {
    Context& c = *m_context;
    TileUndoRecord record;
    if (!c.inStroke)
        return record;
    c.inStroke = false;
    std::size_t changed = 0;
    for (std::size_t i = 0; i < c.slotsUsed; ++i) {
        StrokeTile& s = c.slots[i];
        const std::size_t size = tileBytes(s.key);
        readTile(s.key, std::span<std::uint8_t>(c.scratch.data(), size));
        // A tile the stroke only looked at (coverage stayed 0) or painted back is not kept.
        if (std::memcmp(c.scratch.data(), s.before.data(), size) != 0) {
            std::swap(c.slots[changed], s);
            ++changed;
        }
    }
    std::size_t total = 0;
    for (std::size_t i = 0; i < changed; ++i)
        total += tileBytes(c.slots[i].key);
    record.reserve(changed, total);
    for (std::size_t i = 0; i < changed; ++i) {
        const StrokeTile& s = c.slots[i];
        record.addTile(s.key, std::span<const std::uint8_t>(s.before.data(), tileBytes(s.key)));
    }
    for (std::size_t i = 0; i < c.slotsUsed; ++i)
        c.tileSlot[c.slots[i].key.page][c.slots[i].key.tile] = -1;
    c.slotsUsed = 0;
    strokeEnded();
    // Keep the pool for the next stroke, but not what one huge stroke needed.
    constexpr std::size_t kKeptSlots = 512;
    if (c.slots.size() > kKeptSlots)
        c.slots.resize(kKeptSlots);
    return record;
}

// ---------------------------------------------------------------------------------------------

Result<std::unique_ptr<PaintTarget>> makePaintTarget(std::shared_ptr<const Mesh> mesh,
                                                     std::shared_ptr<const MeshTopology> topology,
                                                     const PaintTargetOptions& options) {
    const bool texture =
        options.kind ? *options.kind == PaintTargetKind::Texture : (mesh && mesh->hasUvs());
    if (texture) {
        auto target = TextureTarget::create(std::move(mesh), std::move(topology), options);
        if (!target)
            return target.takeError();
        return Result<std::unique_ptr<PaintTarget>>(std::move(target).value());
    }
    auto target = VertexColorTarget::create(std::move(mesh), std::move(topology), options);
    if (!target)
        return target.takeError();
    return Result<std::unique_ptr<PaintTarget>>(std::move(target).value());
}

} // namespace core
