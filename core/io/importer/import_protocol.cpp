// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/importer/import_protocol.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <new>
#include <vector>

#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <sys/uio.h>
#include <unistd.h>

#include "core/io/json_nesting.h"

namespace core::importer {

static_assert(sizeof(FrameHeader) == 16 && sizeof(MeshHeader) == 72 &&
              sizeof(MaterialHeader) == 224 && sizeof(ImageHeader) == 8 &&
              sizeof(TextureSourceHeader) == 8 && sizeof(SourceSceneHeader) == 56 &&
              sizeof(SourcePrimitive) == 32);
static_assert(sizeof(glm::vec2) == 8 && sizeof(glm::vec3) == 12 && sizeof(glm::vec4) == 16,
              "the arrays travel as their bytes");

namespace {

constexpr std::uint64_t kMaxTextBytes = 64u << 10;
constexpr std::size_t kMaxWarnings = 1000;
constexpr std::uint64_t kMaxMaterials = 1u << 20;
constexpr std::uint64_t kMaxTextures = 1u << 16;
constexpr std::size_t kMaxLine = 2000;
constexpr std::uint32_t kMaxMimeType = 64;

MaterialMap* mapsOf(Material& m, std::size_t k) {
    MaterialMap* maps[] = {&m.metallicRoughness, &m.normal, &m.occlusion, &m.emissive};
    return maps[k];
}

MaterialHeader materialHeader(const Material& m) {
    MaterialHeader h{};
    for (int k = 0; k < 4; ++k)
        h.baseColorFactor[k] = m.baseColorFactor[k];
    h.baseColorTexture = m.baseColorTexture;
    h.metallicFactor = m.metallicFactor;
    h.roughnessFactor = m.roughnessFactor;
    h.normalScale = m.normalScale;
    h.occlusionStrength = m.occlusionStrength;
    for (int k = 0; k < 3; ++k)
        h.emissiveFactor[k] = m.emissiveFactor[k];
    h.emissiveStrength = m.emissiveStrength;
    h.alphaCutoff = m.alphaCutoff;
    Material copy = m;
    for (std::size_t k = 0; k < 4; ++k) {
        const MaterialMap& map = *mapsOf(copy, k);
        h.maps[k].texture = map.texture;
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r)
                h.maps[k].uvTransform[c * 3 + r] = map.uvTransform[c][r];
    }
    h.alphaMode = static_cast<std::uint8_t>(m.alphaMode);
    h.doubleSided = m.doubleSided ? 1 : 0;
    h.nameLength = static_cast<std::uint32_t>(m.name.size());
    return h;
}

template <typename T> std::size_t bytesOf(const std::vector<T>& v) {
    return v.size() * sizeof(T);
}

/** a * b, or the maximum on overflow (a cap check then fails). */
std::uint64_t mul(std::uint64_t a, std::uint64_t b) {
    if (a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a)
        return std::numeric_limits<std::uint64_t>::max();
    return a * b;
}

std::uint64_t add(std::uint64_t a, std::uint64_t b) {
    return b > std::numeric_limits<std::uint64_t>::max() - a
               ? std::numeric_limits<std::uint64_t>::max()
               : a + b;
}

} // namespace

std::string cleanText(std::string text) {
    for (char& c : text)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            c = ' ';
    if (text.size() > kMaxLine) {
        text.resize(kMaxLine);
        // Not in the middle of a UTF-8 sequence.
        while (!text.empty() && (static_cast<unsigned char>(text.back()) & 0xC0) == 0x80)
            text.pop_back();
        if (!text.empty() && static_cast<unsigned char>(text.back()) >= 0xC0)
            text.pop_back();
        text += "...";
    }
    while (!text.empty() && text.back() == ' ')
        text.pop_back();
    return text;
}

std::uint64_t maxOutputBytes(const LoadLimits& limits) {
    // Positions, normals, colours and UVs per vertex; indices and a material per triangle;
    // textures worth eight of the largest images, and their kept files; text and materials.
    std::uint64_t bytes = mul(limits.maxVertices, 12 + 12 + 16 + 8);
    bytes = add(bytes, mul(limits.maxTriangles, 12 + 4));
    bytes = add(bytes, mul(limits.maxImagePixels, 4 * 8 + 4 * 2));
    // The scene kept to write back: the file's buffers and images, its JSON, the runs.
    bytes = add(bytes, mul(limits.maxFileBytes, 2));
    bytes = add(bytes, mul(limits.maxTriangles, sizeof(SourcePrimitive)));
    bytes = add(bytes, mul(limits.maxVertices, sizeof(std::uint32_t)));
    return add(bytes, 64u << 20);
}

// ---------------------------------------------------------------------------------------------
// Writing (the importer process)

bool FrameWriter::writeAll(const void* data, std::size_t size) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    // The pipe holds references to the pages until they are read (see lendUntilExit()); small
    // payloads are not worth the pinning. A refusal (not a pipe) falls back to write().
    constexpr std::size_t kLendFrom = 64u << 10;
    while (m_lend && size >= kLendFrom) {
        iovec part{const_cast<std::uint8_t*>(p), std::min<std::size_t>(size, 1u << 30)};
        const ssize_t n = ::vmsplice(m_fd, &part, 1, 0);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            m_lend = false;
            break;
        }
        p += n;
        size -= static_cast<std::size_t>(n);
    }
    while (size > 0) {
        const ssize_t n = ::write(m_fd, p, std::min<std::size_t>(size, 1u << 30));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        p += n;
        size -= static_cast<std::size_t>(n);
    }
    return true;
}

bool FrameWriter::frame(Tag tag, const void* a, std::size_t aSize, const void* b,
                        std::size_t bSize) {
    if (!m_ok)
        return false;
    const FrameHeader header{kMagic, static_cast<std::uint32_t>(tag), aSize + bSize};
    m_ok = writeAll(&header, sizeof header) && (aSize == 0 || writeAll(a, aSize)) &&
           (bSize == 0 || writeAll(b, bSize));
    return m_ok;
}

bool FrameWriter::progress(double fraction) {
    return frame(Tag::Progress, &fraction, sizeof fraction);
}

bool FrameWriter::text(Tag tag, const std::string& text) {
    return frame(tag, text.data(), std::min<std::size_t>(text.size(), kMaxTextBytes));
}

bool FrameWriter::image(const Image& image) {
    const ImageHeader header{static_cast<std::uint32_t>(image.width),
                             static_cast<std::uint32_t>(image.height)};
    return frame(Tag::Image, &header, sizeof header, image.rgba.data(), image.rgba.size());
}

bool FrameWriter::mesh(const Mesh& mesh) {
    for (const std::string& warning : mesh.warnings)
        text(Tag::Warning, warning);
    const MeshHeader header{mesh.positions.size(),        mesh.indices.size(),
                            mesh.normals.size(),          mesh.uvs.size(),
                            mesh.colors.size(),           mesh.tangents.size(),
                            mesh.triangleMaterial.size(), mesh.materials.size(),
                            mesh.textures.size()};
    frame(Tag::MeshBegin, &header, sizeof header);
    frame(Tag::Positions, mesh.positions.data(), bytesOf(mesh.positions));
    if (!mesh.normals.empty())
        frame(Tag::Normals, mesh.normals.data(), bytesOf(mesh.normals));
    if (!mesh.uvs.empty())
        frame(Tag::Uvs, mesh.uvs.data(), bytesOf(mesh.uvs));
    if (!mesh.colors.empty())
        frame(Tag::Colors, mesh.colors.data(), bytesOf(mesh.colors));
    if (!mesh.tangents.empty())
        frame(Tag::Tangents, mesh.tangents.data(), bytesOf(mesh.tangents));
    frame(Tag::Indices, mesh.indices.data(), bytesOf(mesh.indices));
    if (!mesh.triangleMaterial.empty())
        frame(Tag::TriangleMaterials, mesh.triangleMaterial.data(), bytesOf(mesh.triangleMaterial));
    for (const Material& m : mesh.materials) {
        const MaterialHeader mh = materialHeader(m);
        frame(Tag::Material, &mh, sizeof mh, m.name.data(), m.name.size());
    }
    for (const Image& image : mesh.textures) {
        const ImageHeader ih{static_cast<std::uint32_t>(image.width),
                             static_cast<std::uint32_t>(image.height)};
        frame(Tag::Texture, &ih, sizeof ih, image.rgba.data(), image.rgba.size());
    }
    for (std::size_t t = 0; t < mesh.textureSources.size() && t < mesh.textures.size(); ++t) {
        const EncodedImage& source = mesh.textureSources[t];
        if (source.empty() || source.mimeType.size() > kMaxMimeType)
            continue;
        const TextureSourceHeader sh{static_cast<std::uint32_t>(t),
                                     static_cast<std::uint32_t>(source.mimeType.size())};
        std::vector<std::uint8_t> head(sizeof sh + source.mimeType.size());
        std::memcpy(head.data(), &sh, sizeof sh);
        std::memcpy(head.data() + sizeof sh, source.mimeType.data(), source.mimeType.size());
        frame(Tag::TextureSource, head.data(), head.size(), source.bytes.data(),
              source.bytes.size());
    }
    if (!mesh.textureOrigins.empty()) {
        std::vector<std::int32_t> images;
        for (const TextureOrigin& o : mesh.textureOrigins)
            images.push_back(o.image);
        frame(Tag::TextureOrigins, images.data(), images.size() * sizeof(std::int32_t));
    }
    if (!mesh.objects.empty())
        objects(mesh.objects);
    if (mesh.source)
        sourceScene(*mesh.source);
    return frame(Tag::MeshEnd, nullptr, 0);
}

bool FrameWriter::objects(const std::vector<MeshObject>& objects) {
    std::vector<std::uint8_t>& payload = m_held.emplace_back();
    for (const MeshObject& object : objects) {
        const std::uint32_t head[2] = {object.firstTriangle,
                                       static_cast<std::uint32_t>(object.name.size())};
        const auto* bytes = reinterpret_cast<const std::uint8_t*>(head);
        payload.insert(payload.end(), bytes, bytes + sizeof head);
        payload.insert(payload.end(), object.name.begin(), object.name.end());
    }
    return frame(Tag::Objects, payload.data(), payload.size());
}

bool FrameWriter::sourceScene(const SourceScene& scene) {
    const std::string json = scene.json.is_null() ? std::string() : scene.json.dump();
    const SourceSceneHeader h{json.size(),
                              scene.bin.size(),
                              scene.primitives.size(),
                              scene.usedVertices.size(),
                              scene.uvHash,
                              scene.colorHash,
                              static_cast<std::uint32_t>(scene.notKept.size()),
                              0};
    std::vector<std::uint8_t>& head = m_held.emplace_back(sizeof h);
    std::memcpy(head.data(), &h, sizeof h);
    const auto put = [&head](const void* data, std::size_t size) {
        const auto* bytes = static_cast<const std::uint8_t*>(data);
        head.insert(head.end(), bytes, bytes + size);
    };
    put(json.data(), json.size());
    put(scene.notKept.data(), scene.notKept.size());
    put(scene.primitives.data(), scene.primitives.size() * sizeof(SourcePrimitive));
    put(scene.usedVertices.data(), scene.usedVertices.size() * sizeof(std::uint32_t));
    return frame(Tag::SourceScene, head.data(), head.size(), scene.bin.data(), scene.bin.size());
}

// ---------------------------------------------------------------------------------------------
// Reading (the application)

namespace {

class Reader {
public:
    Reader(FrameSource& source, const LoadLimits& limits, const ProgressFn& progress)
        : m_source(source), m_limits(limits), m_progress(progress),
          m_budget(maxOutputBytes(limits)) {}

    Received run() {
        try {
            while (!m_done && m_received.malformed.empty() && !m_received.cancelled) {
                FrameHeader header{};
                if (!m_source.read(&header, sizeof header))
                    break;
                if (header.magic != kMagic) {
                    m_received.malformed = "it wrote something that is not a frame";
                    break;
                }
                if (header.length > m_budget) {
                    m_received.malformed = "it sent more data than the limits allow";
                    break;
                }
                m_budget -= header.length;
                if (!frame(static_cast<Tag>(header.tag), header.length))
                    break;
            }
        } catch (const std::bad_alloc&) {
            m_received.malformed = "not enough memory for what it sent";
        }
        if (!m_done) {
            m_received.mesh.reset();
            m_received.image.reset();
        }
        return std::move(m_received);
    }

private:
    bool fail(std::string what) {
        m_received.malformed = std::move(what);
        return false;
    }

    template <typename T>
    bool readArray(std::vector<T>& out, std::uint64_t count, std::uint64_t length, bool& seen) {
        if (seen)
            return fail("it sent an array twice");
        if (length != mul(count, sizeof(T)))
            return fail("an array's length does not match the counts it announced");
        seen = true;
        out.resize(static_cast<std::size_t>(count));
        return count == 0 || m_source.read(out.data(), static_cast<std::size_t>(length));
    }

    bool array(Tag tag, std::uint64_t length) {
        if (!m_mesh)
            return fail("it sent an array outside a mesh");
        Mesh& m = *m_mesh;
        switch (tag) {
        case Tag::Positions:
            return readArray(m.positions, m_header.vertices, length, m_seen[0]);
        case Tag::Normals:
            return readArray(m.normals, m_header.normals, length, m_seen[1]);
        case Tag::Uvs:
            return readArray(m.uvs, m_header.uvs, length, m_seen[2]);
        case Tag::Colors:
            return readArray(m.colors, m_header.colors, length, m_seen[3]);
        case Tag::Indices:
            return readArray(m.indices, m_header.indices, length, m_seen[4]);
        case Tag::Tangents:
            return readArray(m.tangents, m_header.tangents, length, m_seen[6]);
        default:
            return readArray(m.triangleMaterial, m_header.triangleMaterials, length, m_seen[5]);
        }
    }

    bool readText(std::uint64_t length, std::string& out) {
        if (length > kMaxTextBytes)
            return fail("it sent a message that is too long");
        out.resize(static_cast<std::size_t>(length));
        return length == 0 || m_source.read(out.data(), out.size());
    }

    bool readImage(std::uint64_t length, Image& out) {
        ImageHeader header{};
        if (length < sizeof header || !m_source.read(&header, sizeof header))
            return length < sizeof header ? fail("it sent a truncated image") : false;
        const std::uint64_t pixels = std::uint64_t(header.width) * header.height;
        if (header.width == 0 || header.height == 0 || header.width > 65536 ||
            header.height > 65536 || pixels > m_limits.maxImagePixels)
            return fail("it sent an image of an impossible size");
        if (length - sizeof header != pixels * 4)
            return fail("an image's length does not match its size");
        out.width = static_cast<int>(header.width);
        out.height = static_cast<int>(header.height);
        out.rgba.resize(static_cast<std::size_t>(pixels * 4));
        return m_source.read(out.rgba.data(), out.rgba.size());
    }

    /** One frame of length bytes after its header, handled by its kind; false stops reading. */
    bool frame(Tag tag, std::uint64_t length) {
        switch (tag) {
        case Tag::Progress:
            return progressFrame(length);
        case Tag::Warning:
            return warningFrame(length);
        case Tag::Error:
            return errorFrame(length);
        case Tag::Image:
            return imageFrame(length);
        case Tag::MeshBegin:
            return meshBegin(length);
        case Tag::Positions:
        case Tag::Normals:
        case Tag::Uvs:
        case Tag::Colors:
        case Tag::Tangents:
        case Tag::Indices:
        case Tag::TriangleMaterials:
            return array(tag, length);
        case Tag::Material:
            return materialFrame(length);
        case Tag::Texture:
            return textureFrame(length);
        case Tag::TextureSource:
            return textureSourceFrame(length);
        case Tag::TextureOrigins:
            return textureOriginsFrame(length);
        case Tag::Objects:
            return objectsFrame(length);
        case Tag::SourceScene:
            return sourceSceneFrame(length);
        case Tag::MeshEnd:
            return meshEnd(length);
        }
        return fail("it sent a frame of an unknown kind");
    }

    bool progressFrame(std::uint64_t length) {
        double fraction = 0.0;
        if (length != sizeof fraction)
            return fail("it sent a malformed progress report");
        if (!m_source.read(&fraction, sizeof fraction))
            return false;
        if (!std::isfinite(fraction))
            return fail("it sent a malformed progress report");
        if (!reportProgress(m_progress, std::clamp(fraction, 0.0, 1.0))) {
            m_received.cancelled = true;
            return false;
        }
        return true;
    }

    bool warningFrame(std::uint64_t length) {
        std::string text;
        if (!readText(length, text))
            return false;
        if (m_received.warnings.size() < kMaxWarnings)
            m_received.warnings.push_back(cleanText(std::move(text)));
        return true;
    }

    bool errorFrame(std::uint64_t length) {
        std::string text;
        if (!readText(length, text))
            return false;
        m_received.error = cleanText(std::move(text));
        m_done = true;
        return true;
    }

    bool imageFrame(std::uint64_t length) {
        if (m_mesh)
            return fail("it sent an image inside a mesh");
        Image image;
        if (!readImage(length, image))
            return false;
        m_received.image = std::move(image);
        m_done = true;
        return true;
    }

    /** The mesh header: its counts, checked against the limits, before any array. */
    bool meshBegin(std::uint64_t length) {
        MeshHeader h{};
        if (m_mesh)
            return fail("it started a second mesh");
        if (length != sizeof h)
            return fail("it sent a malformed mesh header");
        if (!m_source.read(&h, sizeof h))
            return false;
        const bool perVertex = (h.normals == 0 || h.normals == h.vertices) &&
                               (h.uvs == 0 || h.uvs == h.vertices) &&
                               (h.colors == 0 || h.colors == h.vertices) &&
                               (h.tangents == 0 || h.tangents == h.vertices);
        if (h.vertices > m_limits.maxVertices || h.indices % 3 != 0 ||
            h.indices / 3 > m_limits.maxTriangles || !perVertex ||
            (h.triangleMaterials != 0 && h.triangleMaterials != h.indices / 3) ||
            h.materials > kMaxMaterials || h.textures > kMaxTextures)
            return fail("it announced a mesh beyond the limits");
        m_header = h;
        m_mesh.emplace();
        m_mesh->materials.reserve(static_cast<std::size_t>(h.materials));
        return true;
    }

    bool materialFrame(std::uint64_t length) {
        MaterialHeader h{};
        if (!m_mesh || m_mesh->materials.size() >= m_header.materials)
            return fail("it sent more materials than it announced");
        if (length < sizeof h || length - sizeof h > kMaxTextBytes)
            return fail("it sent a malformed material");
        if (!m_source.read(&h, sizeof h))
            return false;
        if (h.nameLength != length - sizeof h)
            return fail("it sent a malformed material");
        Material m;
        if (!readMaterial(h, m))
            return false;
        m.name.resize(h.nameLength);
        if (h.nameLength > 0 && !m_source.read(m.name.data(), m.name.size()))
            return false;
        m_mesh->materials.push_back(std::move(m));
        return true;
    }

    /** The fields of h; texture indices below 0 are none (Mesh::validate() checks the rest). */
    bool readMaterial(const MaterialHeader& h, Material& m) {
        m.baseColorFactor = glm::vec4(h.baseColorFactor[0], h.baseColorFactor[1],
                                      h.baseColorFactor[2], h.baseColorFactor[3]);
        for (int k = 0; k < 4; ++k)
            if (!std::isfinite(m.baseColorFactor[k]))
                return fail("it sent a material colour that is not a number");
        m.baseColorTexture = h.baseColorTexture < 0 ? -1 : h.baseColorTexture;
        m.metallicFactor = h.metallicFactor;
        m.roughnessFactor = h.roughnessFactor;
        m.normalScale = h.normalScale;
        m.occlusionStrength = h.occlusionStrength;
        m.emissiveFactor = glm::vec3(h.emissiveFactor[0], h.emissiveFactor[1], h.emissiveFactor[2]);
        m.emissiveStrength = h.emissiveStrength;
        m.alphaCutoff = h.alphaCutoff;
        bool finite = std::isfinite(m.metallicFactor) && std::isfinite(m.roughnessFactor) &&
                      std::isfinite(m.normalScale) && std::isfinite(m.occlusionStrength) &&
                      std::isfinite(m.emissiveStrength) && std::isfinite(m.alphaCutoff);
        for (int k = 0; k < 3; ++k)
            finite = finite && std::isfinite(m.emissiveFactor[k]);
        for (std::size_t k = 0; k < 4; ++k) {
            MaterialMap& map = *mapsOf(m, k);
            map.texture = h.maps[k].texture < 0 ? -1 : h.maps[k].texture;
            for (int c = 0; c < 3; ++c)
                for (int r = 0; r < 3; ++r) {
                    map.uvTransform[c][r] = h.maps[k].uvTransform[c * 3 + r];
                    finite = finite && std::isfinite(map.uvTransform[c][r]);
                }
        }
        if (!finite)
            return fail("it sent a material factor that is not a number");
        if (h.alphaMode > static_cast<std::uint8_t>(AlphaMode::Blend) || h.doubleSided > 1)
            return fail("it sent a malformed material");
        m.alphaMode = static_cast<AlphaMode>(h.alphaMode);
        m.doubleSided = h.doubleSided != 0;
        return true;
    }

    bool textureSourceFrame(std::uint64_t length) {
        TextureSourceHeader h{};
        if (!m_mesh || length < sizeof h)
            return fail("it sent a malformed texture file");
        if (!m_source.read(&h, sizeof h))
            return false;
        if (h.texture >= m_mesh->textures.size() || h.mimeTypeLength > kMaxMimeType ||
            length - sizeof h <= h.mimeTypeLength)
            return fail("it sent a malformed texture file");
        m_mesh->textureSources.resize(m_mesh->textures.size());
        EncodedImage& out = m_mesh->textureSources[h.texture];
        if (!out.empty())
            return fail("it sent a texture's file twice");
        out.mimeType.resize(h.mimeTypeLength);
        out.bytes.resize(static_cast<std::size_t>(length - sizeof h - h.mimeTypeLength));
        return (h.mimeTypeLength == 0 || m_source.read(out.mimeType.data(), out.mimeType.size())) &&
               m_source.read(out.bytes.data(), out.bytes.size());
    }

    bool textureOriginsFrame(std::uint64_t length) {
        if (!m_mesh || !m_mesh->textureOrigins.empty() ||
            length != mul(m_header.textures, sizeof(std::int32_t)))
            return fail("it sent malformed texture origins");
        std::vector<std::int32_t> images(static_cast<std::size_t>(m_header.textures));
        if (!images.empty() && !m_source.read(images.data(), static_cast<std::size_t>(length)))
            return false;
        for (std::int32_t image : images)
            m_mesh->textureOrigins.push_back(TextureOrigin{image < 0 ? -1 : image, true});
        return true;
    }

    /** The named objects: in triangle order from triangle 0, names of at most kMaxNameBytes. */
    bool objectsFrame(std::uint64_t length) {
        constexpr std::uint64_t kMaxNameBytes = 1024;
        const std::uint64_t triangles = m_header.indices / 3;
        if (!m_mesh || !m_mesh->objects.empty() || length == 0 ||
            length > mul(triangles, 8 + kMaxNameBytes))
            return fail("it sent malformed objects");
        std::vector<std::uint8_t> payload(static_cast<std::size_t>(length));
        if (!m_source.read(payload.data(), payload.size()))
            return false;
        std::vector<MeshObject> objects;
        for (std::size_t at = 0; at < payload.size();) {
            std::uint32_t head[2];
            if (payload.size() - at < sizeof head)
                return fail("it sent malformed objects");
            std::memcpy(head, payload.data() + at, sizeof head);
            at += sizeof head;
            const bool inOrder =
                objects.empty() ? head[0] == 0 : head[0] > objects.back().firstTriangle;
            if (!inOrder || head[0] >= triangles || head[1] > kMaxNameBytes ||
                head[1] > payload.size() - at)
                return fail("it sent malformed objects");
            objects.push_back({std::string(payload.begin() + std::ptrdiff_t(at),
                                           payload.begin() + std::ptrdiff_t(at + head[1])),
                               head[0]});
            at += head[1];
        }
        m_mesh->objects = std::move(objects);
        return true;
    }

    /** The scene to write back; its JSON is parsed here (the write-back checks its indices). */
    bool sourceSceneFrame(std::uint64_t length) {
        SourceSceneHeader h{};
        if (!m_mesh || m_mesh->source || length < sizeof h)
            return fail("it sent a malformed scene");
        if (!m_source.read(&h, sizeof h))
            return false;
        const std::uint64_t primitiveBytes = mul(h.primitives, sizeof(SourcePrimitive));
        const std::uint64_t usedBytes = mul(h.usedVertices, sizeof(std::uint32_t));
        if (h.primitives > m_limits.maxTriangles || h.usedVertices > m_limits.maxVertices ||
            add(add(add(add(h.jsonLength, h.binLength), primitiveBytes), usedBytes),
                h.notKeptLength) != length - sizeof h ||
            h.notKeptLength > kMaxTextBytes)
            return fail("it sent a malformed scene");
        auto scene = std::make_shared<SourceScene>();
        std::string json(static_cast<std::size_t>(h.jsonLength), '\0');
        std::string notKept(h.notKeptLength, '\0');
        scene->primitives.resize(static_cast<std::size_t>(h.primitives));
        scene->usedVertices.resize(static_cast<std::size_t>(h.usedVertices));
        scene->bin.resize(static_cast<std::size_t>(h.binLength));
        if ((!json.empty() && !m_source.read(json.data(), json.size())) ||
            (!notKept.empty() && !m_source.read(notKept.data(), notKept.size())) ||
            (primitiveBytes > 0 &&
             !m_source.read(scene->primitives.data(), static_cast<std::size_t>(primitiveBytes))) ||
            (usedBytes > 0 &&
             !m_source.read(scene->usedVertices.data(), static_cast<std::size_t>(usedBytes))) ||
            (!scene->bin.empty() && !m_source.read(scene->bin.data(), scene->bin.size())))
            return false;
        scene->notKept = cleanText(std::move(notKept));
        scene->uvHash = h.uvHash;
        scene->colorHash = h.colorHash;
        if (!json.empty()) {
            if (jsonNestingTooDeep(json))
                return fail("it sent a scene nested too deeply");
            try {
                scene->json = nlohmann::json::parse(json);
            } catch (const nlohmann::json::exception&) {
                return fail("it sent a scene that is not JSON");
            }
            if (!scene->json.is_object())
                return fail("it sent a scene that is not a JSON object");
        }
        m_mesh->source = std::move(scene);
        return true;
    }

    bool textureFrame(std::uint64_t length) {
        if (!m_mesh || m_mesh->textures.size() >= m_header.textures)
            return fail("it sent more textures than it announced");
        Image image;
        if (!readImage(length, image))
            return false;
        m_mesh->textures.push_back(std::move(image));
        return true;
    }

    /** The end of the mesh: everything its header announced must have come. */
    bool meshEnd(std::uint64_t length) {
        if (!m_mesh || length != 0)
            return fail("it ended a mesh it had not started");
        const bool complete = m_seen[0] && (m_header.normals == 0 || m_seen[1]) &&
                              (m_header.uvs == 0 || m_seen[2]) &&
                              (m_header.colors == 0 || m_seen[3]) && m_seen[4] &&
                              (m_header.tangents == 0 || m_seen[6]) &&
                              (m_header.triangleMaterials == 0 || m_seen[5]) &&
                              m_mesh->materials.size() == m_header.materials &&
                              m_mesh->textures.size() == m_header.textures;
        if (!complete)
            return fail("it ended a mesh before sending all of it");
        if (!m_mesh->textureSources.empty())
            m_mesh->textureSources.resize(m_mesh->textures.size());
        m_mesh->warnings = m_received.warnings;
        m_received.mesh = std::move(m_mesh);
        m_done = true;
        return true;
    }

    FrameSource& m_source;
    const LoadLimits& m_limits;
    const ProgressFn& m_progress;
    std::uint64_t m_budget;
    Received m_received;
    bool m_done = false;
    std::optional<Mesh> m_mesh;
    MeshHeader m_header{};
    // positions, normals, uvs, colors, indices, triangle materials, tangents
    bool m_seen[7] = {};
};

} // namespace

Received readFrames(FrameSource& source, const LoadLimits& limits, const ProgressFn& progress) {
    return Reader(source, limits, progress).run();
}

} // namespace core::importer
