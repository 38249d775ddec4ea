// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/texture_sets/texture_set_export.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <set>

#include "core/base/color.h"
#include "core/base/parallel.h"
#include "core/base/text.h"
#include "core/io/atomic_write.h"
#include "core/io/image/image_encode.h"
#include "core/model/image_sample.h"
#include "core/paint/targets/uv_raster.h"

namespace core {

namespace {

constexpr std::uint32_t kNoOwner = std::numeric_limits<std::uint32_t>::max();
constexpr int kChannelCount = 7;

/** Per texel of a set's texture: the slot in TextureSet::materials of its material, or none. */
struct SetRaster {
    int width = 0, height = 0;
    std::vector<std::uint32_t> owner;

    std::vector<std::uint8_t> covered() const {
        std::vector<std::uint8_t> out(owner.size());
        for (std::size_t i = 0; i < owner.size(); ++i)
            out[i] = owner[i] != kNoOwner ? 1 : 0;
        return out;
    }
};

/** Marks the texels whose centres each triangle of set's materials covers (UVs repeat). */
SetRaster rasterize(const Mesh& mesh, const TextureSet& set) {
    SetRaster r{
        set.width, set.height,
        std::vector<std::uint32_t>(std::size_t(set.width) * std::size_t(set.height), kNoOwner)};
    if (!mesh.hasUvs())
        return r;
    std::vector<std::uint32_t> slotOf(mesh.materials.size(), kNoOwner);
    for (std::size_t s = 0; s < set.materials.size(); ++s)
        slotOf[set.materials[s]] = std::uint32_t(s);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t m = mesh.triangleMaterial[t];
        if (m >= slotOf.size() || slotOf[m] == kNoOwner)
            continue;
        const glm::vec2 uv[3] = {mesh.uvs[mesh.indices[3 * t]], mesh.uvs[mesh.indices[3 * t + 1]],
                                 mesh.uvs[mesh.indices[3 * t + 2]]};
        uv::UvTriangle tri;
        if (!uv::setUpUv(uv, r.width, r.height, tri))
            continue;
        // One period of the repeat visits every texel the triangle can cover once at most.
        const int x1 = std::min(tri.maxX, tri.minX + r.width - 1);
        const int y1 = std::min(tri.maxY, tri.minY + r.height - 1);
        uv::scanUv(tri, tri.minX, x1, tri.minY, y1,
                   [&](int x, int y, std::int64_t, std::int64_t, std::int64_t) {
                       r.owner[std::size_t(uv::wrapIndex(y, r.height)) * std::size_t(r.width) +
                               std::size_t(uv::wrapIndex(x, r.width))] = slotOf[m];
                   });
    }
    return r;
}

using ChannelValues = std::array<std::array<double, 3>, kChannelCount>;

/** Evaluates a set's channels at its texels. */
class SetChannels {
public:
    SetChannels(const Mesh& mesh, const TextureSet& set)
        : m_mesh(mesh), m_set(set), m_page(mesh.textures[std::size_t(set.texture)]) {}

    /** The channels in needed (bits of SetChannel) at texel (x, y) of material slot. */
    void evaluate(std::uint32_t slot, int x, int y, unsigned needed, ChannelValues& out) const {
        const Material& m = m_mesh.materials[m_set.materials[slot]];
        const double u = (x + 0.5) / m_set.width, v = (y + 0.5) / m_set.height;
        const std::uint8_t* texel =
            &m_page.rgba[(std::size_t(y) * std::size_t(m_set.width) + std::size_t(x)) * 4];
        const auto wants = [needed](SetChannel c) { return (needed >> unsigned(c)) & 1u; };
        const auto row = [&out](SetChannel c) -> std::array<double, 3>& {
            return out[std::size_t(c)];
        };
        if (wants(SetChannel::BaseColor))
            for (int k = 0; k < 3; ++k)
                row(SetChannel::BaseColor)[std::size_t(k)] = texel[k] / 255.0;
        if (wants(SetChannel::Opacity))
            row(SetChannel::Opacity)[0] = texel[3] / 255.0;
        if (wants(SetChannel::Roughness) || wants(SetChannel::Metallic)) {
            const glm::dvec4 mr = sample(m.metallicRoughness, u, v).value_or(glm::dvec4(1.0));
            row(SetChannel::Roughness)[0] = double(m.roughnessFactor) * mr.g;
            row(SetChannel::Metallic)[0] = double(m.metallicFactor) * mr.b;
        }
        if (wants(SetChannel::Normal))
            row(SetChannel::Normal) = normal(m, u, v);
        if (wants(SetChannel::Occlusion)) {
            const std::optional<glm::dvec4> o = sample(m.occlusion, u, v);
            row(SetChannel::Occlusion)[0] =
                o ? 1.0 + double(m.occlusionStrength) * (o->r - 1.0) : 1.0;
        }
        if (wants(SetChannel::Emissive)) {
            const std::optional<glm::dvec4> e = sample(m.emissive, u, v);
            for (int k = 0; k < 3; ++k) {
                const double map = e ? double(srgbToLinear(float((*e)[k]))) : 1.0;
                const double linear = double(m.emissiveFactor[k]) * map;
                row(SetChannel::Emissive)[std::size_t(k)] =
                    double(encodeSrgb(float(std::clamp(linear, 0.0, 1.0))));
            }
        }
    }

private:
    std::optional<glm::dvec4> sample(const MaterialMap& map, double u, double v) const {
        if (map.texture < 0 || std::size_t(map.texture) >= m_mesh.textures.size() ||
            m_mesh.textures[std::size_t(map.texture)].empty())
            return std::nullopt;
        // As the texture target reads a material's maps (its starting roughness and metallic).
        const Image& image = m_mesh.textures[std::size_t(map.texture)];
        const glm::vec2 uv(map.uvTransform * glm::vec3(float(u), float(v), 1.0f));
        return glm::dvec4(sampleChannel(image, uv, 0), sampleChannel(image, uv, 1),
                          sampleChannel(image, uv, 2), sampleChannel(image, uv, 3));
    }

    std::array<double, 3> normal(const Material& m, double u, double v) const {
        const std::optional<glm::dvec4> n = sample(m.normal, u, v);
        if (!n)
            return {0.5, 0.5, 1.0};
        if (m.normalScale == 1.0f)
            return {n->r, n->g, n->b};
        const double s = m.normalScale;
        glm::dvec3 t = (glm::dvec3(*n) * 2.0 - 1.0) * glm::dvec3(s, s, 1.0);
        t = glm::length(t) > 0.0 ? glm::normalize(t) : glm::dvec3(0.0, 0.0, 1.0);
        return {t.x * 0.5 + 0.5, t.y * 0.5 + 0.5, t.z * 0.5 + 0.5};
    }

    const Mesh& m_mesh;
    const TextureSet& m_set;
    const Image& m_page;
};

std::uint16_t toValue(double v) {
    return std::uint16_t(std::lround(std::clamp(v, 0.0, 1.0) * 65535.0));
}

/** The map's packed values at the texels the raster covers (0 elsewhere). */
PackedMap pack(const Mesh& mesh, const TextureSet& set, const SetRaster& raster,
               const PresetMap& map, NormalConvention convention) {
    PackedMap out{set.width, set.height, int(map.components.size()), {}};
    out.values.assign(raster.owner.size() * map.components.size(), 0);
    unsigned needed = 0;
    for (const MapComponent& c : map.components)
        if (c.channel)
            needed |= 1u << unsigned(*c.channel);
    const SetChannels channels(mesh, set);
    const std::size_t n = map.components.size();
    parallelRanges(set.height, 0, [&](int, int begin, int end) {
        ChannelValues values{};
        for (int y = begin; y < end; ++y)
            for (int x = 0; x < set.width; ++x) {
                const std::size_t i = std::size_t(y) * std::size_t(set.width) + std::size_t(x);
                if (raster.owner[i] == kNoOwner)
                    continue;
                channels.evaluate(raster.owner[i], x, y, needed, values);
                for (std::size_t k = 0; k < n; ++k) {
                    const MapComponent& c = map.components[k];
                    double v = c.constant;
                    if (c.channel) {
                        v = values[std::size_t(*c.channel)][std::size_t(c.component)];
                        if (*c.channel == SetChannel::Normal && c.component == 1 &&
                            convention == NormalConvention::DirectX)
                            v = 1.0 - v;
                        if (c.inverted)
                            v = 1.0 - v;
                    }
                    out.values[i * n + k] = toValue(v);
                }
            }
    });
    return out;
}

/** Per output index along an axis of in → out texels: the source texels and their weights. */
struct AxisWeights {
    std::vector<std::vector<std::pair<int, double>>> taps;
};

AxisWeights axisWeights(int in, int out) {
    AxisWeights w;
    w.taps.resize(std::size_t(out));
    const double scale = double(in) / double(out);
    for (int i = 0; i < out; ++i) {
        auto& taps = w.taps[std::size_t(i)];
        if (out < in) { // box: the source texels the output texel's footprint overlaps
            const double a = i * scale, b = (i + 1) * scale;
            for (int s = int(std::floor(a)); s < int(std::ceil(b)) && s < in; ++s) {
                const double overlap = std::min(b, s + 1.0) - std::max(a, double(s));
                if (overlap > 0.0)
                    taps.emplace_back(s, overlap / scale);
            }
        } else { // bilinear between the two nearest source centres
            const double c = std::clamp((i + 0.5) * scale - 0.5, 0.0, double(in - 1));
            const int s0 = int(std::floor(c));
            const int s1 = std::min(s0 + 1, in - 1);
            taps.emplace_back(s0, 1.0 - (c - s0));
            if (s1 != s0)
                taps.emplace_back(s1, c - s0);
        }
    }
    return w;
}

Result<std::vector<std::uint8_t>> encodeMap(const PackedMap& map, const PresetMap& source,
                                            const ExportPreset& preset,
                                            const ProgressFn& progress) {
    std::array<bool, 4> colour{};
    for (std::size_t k = 0; k < source.components.size(); ++k)
        colour[k] = source.components[k].channel && isColorChannel(*source.components[k].channel);
    return encodeValues(map.values.data(), map.width, map.height, map.components, colour,
                        preset.format, preset.bitDepth, progress);
}

/** value as its shortest text ("2.5"). */
std::string shortNumber(float value) {
    char buffer[32];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return ec == std::errc() ? std::string(buffer, end) : std::to_string(value);
}

std::vector<std::string> emissiveWarnings(const Mesh& mesh, const ExportPreset& preset) {
    bool usesEmissive = false;
    for (const PresetMap& map : preset.maps)
        for (const MapComponent& c : map.components)
            usesEmissive = usesEmissive || c.channel == SetChannel::Emissive;
    std::vector<std::string> out;
    if (!usesEmissive)
        return out;
    for (const Material& m : mesh.materials)
        if (m.emissiveStrength > 1.0f && m.emissiveFactor != glm::vec3(0.0f))
            out.push_back("material “" + printable(m.name) + "”: its emissive strength " +
                          shortNumber(m.emissiveStrength) +
                          " is not in the exported emissive map, which holds colours up to 1");
    return out;
}

} // namespace

std::vector<TextureSet> textureSets(const Mesh& mesh) {
    std::map<int, TextureSet> byTexture;
    for (std::size_t m = 0; m < mesh.materials.size(); ++m) {
        const int t = mesh.materials[m].baseColorTexture;
        if (t < 0 || std::size_t(t) >= mesh.textures.size() ||
            mesh.textures[std::size_t(t)].empty())
            continue;
        TextureSet& set = byTexture[t];
        if (set.materials.empty()) {
            set.texture = t;
            set.width = mesh.textures[std::size_t(t)].width;
            set.height = mesh.textures[std::size_t(t)].height;
            set.name = fileNamePart(mesh.materials[m].name, "TextureSet");
        }
        set.materials.push_back(m);
    }
    std::vector<TextureSet> sets;
    std::set<std::string> taken;
    for (auto& [t, set] : byTexture) {
        const std::string base = set.name;
        for (int k = 2; !taken.insert(set.name).second; ++k)
            set.name = base + "-" + std::to_string(k);
        sets.push_back(std::move(set));
    }
    return sets;
}

Result<std::vector<std::string>> textureExportFileNames(const Mesh& mesh,
                                                        const TextureExportOptions& options) {
    if (Status s = checkPreset(options.preset); !s)
        return s.takeError();
    std::vector<std::string> names;
    std::set<std::string> taken;
    for (const TextureSet& set : textureSets(mesh))
        for (const PresetMap& map : options.preset.maps) {
            Result<std::string> stem =
                expandFileName(options.preset.fileName, options.meshName, set.name, map.name);
            if (!stem)
                return stem.takeError();
            const std::string name = *stem + mapFileExtension(options.preset.format);
            if (!taken.insert(name).second)
                return Error{"the file-name template “" + printable(options.preset.fileName) +
                             "” names two files " + name + " (add $textureSet or $channel)"};
            names.push_back(name);
        }
    return names;
}

PackedMap packMap(const Mesh& mesh, const TextureSet& set, const PresetMap& map,
                  const ExportPreset& preset) {
    const SetRaster raster = rasterize(mesh, set);
    PackedMap out = pack(mesh, set, raster, map, preset.normal);
    padMap(out, raster.covered(), preset.padding);
    return out;
}

void padMap(PackedMap& map, const std::vector<std::uint8_t>& covered, int padding) {
    const int w = map.width, h = map.height;
    const std::size_t n = std::size_t(map.components);
    enum : std::uint8_t { Empty, Filled, InRing };
    std::vector<std::uint8_t> state(covered.size());
    for (std::size_t i = 0; i < covered.size(); ++i)
        state[i] = covered[i] != 0 ? Filled : Empty;
    const auto forNeighbours = [w, h](std::size_t i, auto&& fn) {
        const int x = int(i % std::size_t(w)), y = int(i / std::size_t(w));
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                if ((dx != 0 || dy != 0) && x + dx >= 0 && x + dx < w && y + dy >= 0 && y + dy < h)
                    fn(std::size_t(y + dy) * std::size_t(w) + std::size_t(x + dx));
    };
    std::vector<std::size_t> ring;
    for (std::size_t i = 0; i < state.size(); ++i) {
        if (state[i] != Empty)
            continue;
        bool touches = false;
        forNeighbours(i, [&](std::size_t j) { touches = touches || state[j] == Filled; });
        if (touches) {
            state[i] = InRing;
            ring.push_back(i);
        }
    }
    std::vector<std::uint32_t> sums(n);
    std::vector<std::uint16_t> fresh;
    for (int r = 0; !ring.empty() && (padding == kPadToFill || r < padding); ++r) {
        fresh.assign(ring.size() * n, 0);
        for (std::size_t k = 0; k < ring.size(); ++k) {
            std::fill(sums.begin(), sums.end(), 0u);
            std::uint32_t count = 0;
            forNeighbours(ring[k], [&](std::size_t j) {
                if (state[j] != Filled)
                    return;
                ++count;
                for (std::size_t c = 0; c < n; ++c)
                    sums[c] += map.values[j * n + c];
            });
            for (std::size_t c = 0; c < n; ++c)
                fresh[k * n + c] = std::uint16_t((sums[c] + count / 2) / count);
        }
        std::vector<std::size_t> next;
        for (std::size_t k = 0; k < ring.size(); ++k) {
            std::copy_n(&fresh[k * n], n, &map.values[ring[k] * n]);
            state[ring[k]] = Filled;
        }
        for (const std::size_t i : ring)
            forNeighbours(i, [&](std::size_t j) {
                if (state[j] == Empty) {
                    state[j] = InRing;
                    next.push_back(j);
                }
            });
        ring = std::move(next);
    }
}

PackedMap resampleMap(const PackedMap& map, int width, int height) {
    if (width == map.width && height == map.height)
        return map;
    const std::size_t n = std::size_t(map.components);
    const AxisWeights wx = axisWeights(map.width, width), wy = axisWeights(map.height, height);
    // Rows first (into doubles), then columns.
    std::vector<double> rows(std::size_t(width) * std::size_t(map.height) * n, 0.0);
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < width; ++x)
            for (const auto& [s, weight] : wx.taps[std::size_t(x)])
                for (std::size_t c = 0; c < n; ++c)
                    rows[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * n + c] +=
                        weight *
                        map.values[(std::size_t(y) * std::size_t(map.width) + std::size_t(s)) * n +
                                   c];
    PackedMap out{width, height, map.components, {}};
    out.values.resize(std::size_t(width) * std::size_t(height) * n);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (std::size_t c = 0; c < n; ++c) {
                double v = 0.0;
                for (const auto& [s, weight] : wy.taps[std::size_t(y)])
                    v += weight *
                         rows[(std::size_t(s) * std::size_t(width) + std::size_t(x)) * n + c];
                out.values[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * n + c] =
                    std::uint16_t(std::clamp(std::lround(v), 0L, 65535L));
            }
    return out;
}

Result<std::vector<std::string>> exportTextureSets(const std::string& folder, const Mesh& mesh,
                                                   const TextureExportOptions& options,
                                                   const ProgressFn& progress,
                                                   std::vector<std::string>* warnings) {
    Result<std::vector<std::string>> names = textureExportFileNames(mesh, options);
    if (!names)
        return names.takeError();
    const std::vector<TextureSet> sets = textureSets(mesh);
    if (sets.empty())
        return Error{"there is no texture set to export (the model is painted with vertex "
                     "colours)"};
    if (options.size < 0 || options.size > 16384)
        return Error{"the map size must be up to 16384 texels"};
    if (warnings) {
        const std::vector<std::string> more = emissiveWarnings(mesh, options.preset);
        warnings->insert(warnings->end(), more.begin(), more.end());
    }
    const ExportPreset& preset = options.preset;
    std::vector<std::string> written;
    const double steps = double(names->size());
    for (std::size_t s = 0; s < sets.size(); ++s) {
        const TextureSet& set = sets[s];
        const SetRaster raster = rasterize(mesh, set);
        const std::vector<std::uint8_t> covered = raster.covered();
        int width = set.width, height = set.height;
        if (options.size > 0) {
            const double scale = double(options.size) / double(std::max(width, height));
            width = std::max(1, int(std::lround(width * scale)));
            height = std::max(1, int(std::lround(height * scale)));
        }
        for (std::size_t m = 0; m < preset.maps.size(); ++m) {
            const std::size_t index = s * preset.maps.size() + m;
            if (!reportProgress(progress, double(index) / steps))
                return cancelledError();
            PackedMap map = pack(mesh, set, raster, preset.maps[m], preset.normal);
            padMap(map, covered, preset.padding);
            map = resampleMap(map, width, height);
            const std::string path = (std::filesystem::path(folder) / (*names)[index]).string();
            Result<std::vector<std::uint8_t>> bytes =
                encodeMap(map, preset.maps[m], preset, [&](double f) {
                    return reportProgress(progress, (double(index) + 0.9 * f) / steps);
                });
            if (bytes.cancelled())
                return cancelledError();
            if (!bytes)
                return Error{path + ": cannot be written (" + bytes.error() + ")"};
            if (Status st = writeFileAtomically(path, bytes->data(), bytes->size(), false); !st)
                return st.takeError();
            written.push_back(path);
        }
    }
    reportProgress(progress, 1.0);
    return written;
}

} // namespace core
