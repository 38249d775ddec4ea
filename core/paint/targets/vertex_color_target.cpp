// SPDX-License-Identifier: GPL-3.0-or-later
// Painting into per-vertex colours (VertexColorTarget): the vertices of a dab's triangles whose
// projection falls into the paintable map, fills, undo blocks of kVertexBlock vertices.
#include <utility>

#include "core/paint/targets/paint_context.h"

namespace core {

namespace {

void vertexRangesFromBlocks(std::vector<TileKey>& keys, std::uint32_t vertexCount,
                            std::vector<VertexRange>& out) {
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 0; i < keys.size();) {
        std::size_t j = i + 1;
        while (j < keys.size() && keys[j].tile == keys[j - 1].tile + 1)
            ++j;
        out.push_back({keys[i].tile * kVertexBlock,
                       std::min((keys[j - 1].tile + 1) * kVertexBlock, vertexCount)});
        i = j;
    }
}

} // namespace

// ---------------------------------------------------------------------------------------------
// VertexColorTarget

VertexColorTarget::VertexColorTarget(std::shared_ptr<const Mesh> mesh,
                                     std::shared_ptr<const MeshTopology> topology,
                                     const PaintTargetOptions& options)
    : PaintTarget(std::move(mesh), std::move(topology), options) {}

VertexColorTarget::~VertexColorTarget() = default;

Result<std::unique_ptr<VertexColorTarget>>
VertexColorTarget::create(std::shared_ptr<const Mesh> mesh,
                          std::shared_ptr<const MeshTopology> topology,
                          const PaintTargetOptions& options) {
    if (const Status paintable = checkMesh(mesh, topology); !paintable)
        return paintable.takeError();
    std::unique_ptr<VertexColorTarget> target(new VertexColorTarget(mesh, topology, options));
    const std::size_t n = mesh->vertexCount();
    // Each vertex takes the factor of the first triangle using it (a vertex shared by materials
    // of different factors cannot keep both looks).
    std::vector<std::uint8_t> assigned(n, 0u);
    target->m_colors.assign(n, glm::vec4(1.0f));
    if (mesh->hasColors())
        for (std::size_t v = 0; v < n; ++v)
            for (int k = 0; k < 4; ++k)
                target->m_colors[v][k] =
                    std::isfinite(mesh->colors[v][k]) ? mesh->colors[v][k] : 1.0f;
    for (std::size_t t = 0; t < mesh->triangleCount(); ++t) {
        const glm::vec4 factor = mesh->materials[mesh->triangleMaterial[t]].baseColorFactor;
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t v = mesh->indices[3 * t + std::size_t(c)];
            if (!assigned[v]) {
                assigned[v] = 1;
                target->m_colors[v] *= factor;
            }
        }
    }
    target->m_original = target->m_colors;
    target->m_vertexDab.assign(n, 0u);
    const std::uint32_t blocks = std::uint32_t((n + kVertexBlock - 1) / kVertexBlock);
    target->setUpStrokeTiles({blocks}, kVertexBlock, kVertexBlock * sizeof(glm::vec4));
    return Result<std::unique_ptr<VertexColorTarget>>(std::move(target));
}

std::optional<glm::vec4> VertexColorTarget::colorAt(std::uint32_t triangle,
                                                    const glm::vec3& weights) const {
    const Mesh& m = mesh();
    glm::vec3 w;
    if (!normalizedWeights(m, triangle, weights, w))
        return std::nullopt;
    glm::vec4 color(0.0f);
    for (int c = 0; c < 3; ++c)
        color += w[c] * m_colors[m.indices[3 * std::size_t(triangle) + std::size_t(c)]];
    return color;
}

std::size_t VertexColorTarget::bytes() const {
    return sizeof(*this) + (m_colors.capacity() + m_original.capacity()) * sizeof(glm::vec4) +
           m_vertexDab.capacity() * sizeof(std::uint32_t) + contextBytes();
}

std::size_t VertexColorTarget::tileBytes(TileKey key) const {
    const std::size_t n = m_colors.size();
    const std::size_t first = std::size_t(key.tile) * kVertexBlock;
    if (key.page != 0 || first >= n)
        return 0;
    return std::min<std::size_t>(kVertexBlock, n - first) * sizeof(glm::vec4);
}

bool VertexColorTarget::readTile(TileKey key, std::span<std::uint8_t> out) const {
    const std::size_t size = tileBytes(key);
    if (size == 0 || out.size() != size)
        return false;
    std::memcpy(out.data(), &m_colors[std::size_t(key.tile) * kVertexBlock], size);
    return true;
}

bool VertexColorTarget::writeTile(TileKey key, std::span<const std::uint8_t> bytes) {
    const std::size_t size = tileBytes(key);
    if (size == 0 || bytes.size() != size)
        return false;
    std::memcpy(&m_colors[std::size_t(key.tile) * kVertexBlock], bytes.data(), size);
    return true;
}

void VertexColorTarget::addChanges(std::vector<TileKey>& keys, PaintChanges& out) const {
    vertexRangesFromBlocks(keys, std::uint32_t(m_colors.size()), out.vertices);
}

void VertexColorTarget::blendVertex(std::uint32_t v, const std::uint8_t* before, float cover) {
    glm::vec4 from;
    std::memcpy(&from, before, sizeof(glm::vec4));
    const glm::vec4 target = m_context->brush.eraser ? m_original[v] : m_context->colorLinear;
    if (cover >= 1.0f) {
        m_colors[v] = target;
        return;
    }
    // Colour mixes on sRGB-encoded values, as on texture targets (blendTexel()); alpha linear.
    for (int k = 0; k < 3; ++k) {
        const float a = encodeSrgb(from[k]);
        m_colors[v][k] = srgbToLinear(a + (encodeSrgb(target[k]) - a) * cover);
    }
    m_colors[v].a = from.a + (target.a - from.a) * cover;
}

const PaintChanges& VertexColorTarget::paintElements(std::span<const PaintElement> elements) {
    Context& c = *m_context;
    const float cover = c.beginElements();
    if (!(cover > 0.0f))
        return c.changes;
    for (const PaintElement& e : elements) {
        const std::uint32_t v = e.index;
        if (e.page != 0 || v >= m_colors.size())
            continue;
        const std::int32_t slot = c.slotFor(*this, 0, v / kVertexBlock);
        StrokeTile& st = c.slots[std::size_t(slot)];
        const std::size_t local = v % kVertexBlock;
        if (!(cover > st.alpha[local]))
            continue;
        st.alpha[local] = cover;
        c.touch(slot);
        blendVertex(v, &st.before[local * sizeof(glm::vec4)], cover);
    }
    return touchedChanges();
}

const PaintChanges& VertexColorTarget::paint(const DepthLayers& layers, const Dab& dab) {
    Context& c = *m_context;
    c.changes.clear();
    if (!c.inStroke || !c.beginDab(layers, dab))
        return c.changes;
    for (std::size_t si = 0; si < c.setups.size(); ++si) {
        const TriangleSetup& s = c.setups[si];
        for (const std::uint32_t v : s.vertex) {
            if (m_vertexDab[v] == c.dab)
                continue;
            m_vertexDab[v] = c.dab;
            const ProjectedVertex& p = c.vertices[v];
            const float px = p.sx / p.w, py = p.sy / p.w;
            const std::uint32_t mapped = c.mapAt(px, py);
            if (mapped == kNone)
                continue;
            // The vertex is a corner of the fragment's triangle, or lies on its plane.
            const std::array<std::uint32_t, 3>& corners = c.setups[mapped].vertex;
            const bool corner = corners[0] == v || corners[1] == v || corners[2] == v;
            if (!corner && !c.onMapSurface(std::uint32_t(si), p.view, mapped))
                continue;
            const glm::vec2 offset = glm::vec2(px, py) - c.center;
            const float weight = c.tip.weight(offset, glm::length(offset));
            if (!(weight > 0.0f))
                continue;
            const std::int32_t slot = c.slotFor(*this, 0, v / kVertexBlock);
            StrokeTile& st = c.slots[std::size_t(slot)];
            const std::size_t local = v % kVertexBlock;
            const float old = st.alpha[local];
            const float cover = std::max(
                old, std::min(c.dabOpacity, c.coverBase(slot)[local] + c.flowOpacity * weight));
            if (!(cover > old))
                continue;
            st.alpha[local] = cover;
            c.touch(slot);
            blendVertex(v, &st.before[local * sizeof(glm::vec4)], cover);
        }
    }
    return touchedChanges();
}

} // namespace core
