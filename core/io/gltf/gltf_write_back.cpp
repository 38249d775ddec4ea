// SPDX-License-Identifier: GPL-3.0-or-later
// The copy-on-write glTF writer (see gltf_write_back.h). The scene's JSON is copied and edited
// where something was painted; the BIN chunk is laid out anew from the buffer views, each view's
// bytes copied as they were unless a painted image replaced them.
#include "core/io/gltf/gltf_write_back.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "core/document/project_state.h"
#include "core/io/gltf/gltf_write_back_geometry.h"
#include "core/io/image/image_encode.h"
#include "core/model/source_scene.h"

namespace core::detail::gltf {

using Json = nlohmann::json;

namespace {
using Bytes = std::vector<std::uint8_t>;

constexpr const char* kSpecularGlossiness = "KHR_materials_pbrSpecularGlossiness";

/** Where a painted page goes in its materials. */
enum class Slot { BaseColor, MetallicRoughness };

const char* slotPointer(Slot slot) {
    return slot == Slot::BaseColor ? "/pbrMetallicRoughness/baseColorTexture"
                                   : "/pbrMetallicRoughness/metallicRoughnessTexture";
}

/** Calls fn on every integer under a "bufferView" key in json. */
template <typename Fn> void forEachViewReference(Json& json, const Fn& fn) {
    if (json.is_object()) {
        for (auto it = json.begin(); it != json.end(); ++it) {
            if (it.key() == "bufferView" && it->is_number_integer())
                fn(*it);
            else
                forEachViewReference(*it, fn);
        }
    } else if (json.is_array()) {
        for (Json& item : json)
            forEachViewReference(item, fn);
    }
}

/** The textureInfo objects of a material: JSON pointer (within it) -> texture index. */
void collectTextureInfos(const Json& json, const std::string& at,
                         std::vector<std::pair<std::string, int>>& out) {
    if (!json.is_object())
        return;
    for (auto it = json.begin(); it != json.end(); ++it) {
        const std::string key = it.key();
        const std::string here = at + "/" + key;
        const bool named = key.size() > 7 && (key.ends_with("Texture") || key.ends_with("texture"));
        if (named && it->is_object() && it->contains("index") && (*it)["index"].is_number_integer())
            out.emplace_back(here, (*it)["index"].get<int>());
        else
            collectTextureInfos(*it, here, out);
    }
}

/** The texture coordinate set and KHR_texture_transform of a textureInfo (no index). */
Json placementOf(const Json& textureInfo) {
    Json placement = Json::object();
    if (textureInfo.contains("texCoord"))
        placement["texCoord"] = textureInfo["texCoord"];
    const Json exts = textureInfo.value("extensions", Json::object());
    if (exts.is_object() && exts.contains("KHR_texture_transform"))
        placement["extensions"]["KHR_texture_transform"] = exts["KHR_texture_transform"];
    return placement;
}

/** Whether texture shows image, as its source or an extension's (KHR_texture_basisu, ...). */
bool showsImage(const Json& texture, int image) {
    if (texture.value("source", -1) == image)
        return true;
    const Json exts = texture.value("extensions", Json::object());
    if (exts.is_object())
        for (const Json& ext : exts)
            if (ext.is_object() && ext.value("source", -1) == image)
                return true;
    return false;
}

constexpr int kVertexData = 34962, kIndexData = 34963;

/** A buffer view to add: its bytes and its fields besides buffer, offset and length. */
struct AddedView {
    Bytes bytes;
    Json fields;
};

class SceneWriter {
public:
    SceneWriter(const Mesh& mesh, const GlbAdditions& additions, const ProgressFn& progress,
                std::vector<std::string>& warnings)
        : m_mesh(mesh), m_scene(*mesh.source), m_additions(additions), m_progress(progress),
          m_warnings(warnings), m_json(mesh.source->json) {}

    Result<GlbContent> run() {
        if (Status s = dropProjectState(); !s)
            return s.takeError();
        if (Status s = collectMaterialPrimitives(); !s)
            return s.takeError();
        if (hashValues(m_mesh.uvs) != m_scene.uvHash)
            if (Status s = relayPrimitives(); !s)
                return s.takeError();
        if (Status s = writePages(Slot::BaseColor); !s)
            return s.takeError();
        if (Status s = writePages(Slot::MetallicRoughness); !s)
            return s.takeError();
        if (Status s = writeVertexColours(); !s)
            return s.takeError();
        dropUnusedExtension(kSpecularGlossiness);
        warnAboutFileImages();
        if (Status s = addExtras(); !s)
            return s.takeError();
        return assemble();
    }

private:
    const Mesh& m_mesh;
    const SourceScene& m_scene;
    const GlbAdditions& m_additions;
    const ProgressFn& m_progress;
    std::vector<std::string>& m_warnings;
    Json m_json;
    std::vector<std::size_t> m_keptViews;    // the scene's view per written view, in order
    std::map<std::size_t, Bytes> m_replaced; // written view -> its new bytes
    std::vector<AddedView> m_added;          // views after the kept ones
    bool m_relaid = false; // the primitives take the automatic UV layout's vertices
    static constexpr std::uint32_t kUnnumbered = 0xFFFFFFFFu;
    std::vector<std::uint32_t> m_number; // per mesh vertex: its number in the primitive
    std::size_t m_fileMaterials = 0;     // the scene's materials (the mesh may add a default)
    std::vector<std::set<std::pair<std::size_t, std::size_t>>> m_primitivesOf; // per material

    Json& materials() { return m_json["materials"]; }
    Json& images() { return m_json["images"]; }
    Json& textures() { return m_json["textures"]; }

    // ---- the scene's own state of a previous project, and its buffer views

    /**
     * A project's state under asset.extras goes (the additions bring the new one); the views its
     * attachments took are dropped where nothing else uses them, and the others renumbered.
     */
    Status dropProjectState() {
        std::set<std::int64_t> attachments;
        if (m_json.contains("asset") && m_json["asset"].is_object()) {
            Json& asset = m_json["asset"];
            if (asset.contains("extras") && asset["extras"].is_object() &&
                asset["extras"].contains(kProjectExtrasKey)) {
                const Json& state = asset["extras"][kProjectExtrasKey];
                for (const char* at : {"/paint_layers/images", "/brush_tip_views"}) {
                    const Json::json_pointer pointer(at);
                    if (state.is_object() && state.contains(pointer) && state[pointer].is_array())
                        for (const Json& v : state[pointer])
                            if (v.is_number_integer())
                                attachments.insert(v.get<std::int64_t>());
                }
                asset["extras"].erase(kProjectExtrasKey);
                if (asset["extras"].empty())
                    asset.erase("extras");
            }
        }
        const std::size_t viewCount =
            m_json.contains("bufferViews") ? m_json["bufferViews"].size() : 0;
        std::vector<char> used(viewCount, 0);
        forEachViewReference(m_json, [&](Json& ref) {
            const auto v = ref.get<std::int64_t>();
            if (v >= 0 && std::size_t(v) < viewCount)
                used[std::size_t(v)] = 1;
        });
        std::vector<std::int64_t> renumbered(viewCount, -1);
        for (std::size_t v = 0; v < viewCount; ++v) {
            if (!used[v] && attachments.count(std::int64_t(v)))
                continue;
            renumbered[v] = std::int64_t(m_keptViews.size());
            m_keptViews.push_back(v);
        }
        bool dangling = false;
        forEachViewReference(m_json, [&](Json& ref) {
            const auto v = ref.get<std::int64_t>();
            if (v < 0 || std::size_t(v) >= viewCount)
                dangling = true;
            else
                ref = renumbered[std::size_t(v)];
        });
        if (dangling)
            return Error{"the scene uses a buffer view that does not exist"};
        return {};
    }

    // ---- which primitives each material has

    Status collectMaterialPrimitives() {
        m_fileMaterials = m_json.contains("materials") ? m_json["materials"].size() : 0;
        if (m_mesh.materials.size() != m_fileMaterials &&
            m_mesh.materials.size() != m_fileMaterials + 1)
            return Error{"the materials differ from the scene's"};
        m_primitivesOf.resize(m_mesh.materials.size());
        const Json& meshes = m_json.at("meshes");
        for (const SourcePrimitive& run : m_scene.primitives) {
            const Json& primitive = meshes.at(run.mesh).at("primitives").at(run.primitive);
            const std::uint32_t m = m_mesh.triangleMaterial.at(run.firstTriangle);
            const std::size_t fileMaterial = primitive.contains("material")
                                                 ? primitive["material"].get<std::size_t>()
                                                 : m_fileMaterials;
            if (fileMaterial != m)
                return Error{"the materials differ from the scene's"};
            m_primitivesOf[m].insert({run.mesh, run.primitive});
        }
        return {};
    }

    Json& primitive(const std::pair<std::size_t, std::size_t>& at) {
        return m_json["meshes"][at.first]["primitives"][at.second];
    }

    /** The scene's material m, made (as "default", given to its primitives) if it has none. */
    Json& material(std::size_t m) {
        if (m == m_fileMaterials && materials().size() == m_fileMaterials) {
            materials().push_back({{"name", m_mesh.materials[m].name}});
            for (const auto& at : m_primitivesOf[m])
                primitive(at)["material"] = m;
        }
        return materials()[m];
    }

    // ---- painted pages

    /** The mesh texture of material m's slot if it was painted (else -1). */
    int paintedTexture(std::size_t m, Slot slot) const {
        const Material& mat = m_mesh.materials[m];
        const int t =
            slot == Slot::BaseColor ? mat.baseColorTexture : mat.metallicRoughness.texture;
        if (t < 0 || std::size_t(t) >= m_mesh.textureOrigins.size() ||
            m_mesh.textureOrigins[std::size_t(t)].unchanged)
            return -1;
        return t;
    }

    Status writePages(Slot slot) {
        std::map<int, std::vector<std::size_t>> groups; // painted texture -> its materials
        for (std::size_t m = 0; m < m_mesh.materials.size(); ++m)
            if (const int t = paintedTexture(m, slot); t >= 0)
                groups[t].push_back(m);
        std::size_t done = 0;
        for (const auto& [texture, group] : groups) {
            if (Status s = writePage(texture, group, slot); !s)
                return s;
            const double base = slot == Slot::BaseColor ? 0.0 : 0.4;
            if (!reportProgress(m_progress, base + 0.4 * double(++done) / double(groups.size())))
                return cancelledError();
        }
        return {};
    }

    /**
     * Where material m's textures lie on the mesh's UVs: its first textureInfo's placement, or
     * the automatic layout's TEXCOORD_0.
     */
    Json uvPlacement(std::size_t m) {
        if (m_relaid)
            return Json::object();
        const Json& mat = material(m);
        for (const char* at : {"/pbrMetallicRoughness/baseColorTexture",
                               "/pbrMetallicRoughness/metallicRoughnessTexture", "/normalTexture",
                               "/occlusionTexture", "/emissiveTexture"}) {
            const Json::json_pointer pointer(at);
            if (mat.contains(pointer) && mat[pointer].is_object())
                return placementOf(mat[pointer]);
        }
        return Json::object();
    }

    /** Whether every primitive of the materials has the texture coordinate set placement uses. */
    bool hasUvSet(const std::vector<std::size_t>& group, const Json& placement) {
        const std::string set = "TEXCOORD_" + std::to_string(placement.value("texCoord", 0));
        for (std::size_t m : group)
            for (const auto& at : m_primitivesOf[m])
                if (!primitive(at).value("attributes", Json::object()).contains(set))
                    return false;
        return true;
    }

    Status writePage(int texture, const std::vector<std::size_t>& group, Slot slot) {
        const Json placement = uvPlacement(group.front());
        if (!hasUvSet(group, placement)) {
            m_warnings.push_back("the painting on material \"" +
                                 m_mesh.materials[group.front()].name +
                                 "\" is not kept: its primitives lack the texture coordinates "
                                 "it was painted on");
            return {};
        }
        Result<Bytes> png = encodeImage(m_mesh.textures[std::size_t(texture)], ExportFormat::Png8);
        if (!png)
            return Error{"a painted texture cannot be encoded as PNG (" + png.error() + ")",
                         png.errorKind()};
        const int image = m_mesh.textureOrigins[std::size_t(texture)].image;
        if (!replaceImage(image, group, slot, placement, *png)) {
            const int added = addTexture(std::move(png).value(), samplerOf(group.front(), slot));
            for (std::size_t m : group) {
                Json info = placement;
                info["index"] = added;
                material(m)[Json::json_pointer(slotPointer(slot))] = std::move(info);
            }
        }
        for (std::size_t m : group)
            slot == Slot::BaseColor ? bakedBaseColor(m) : bakedMetallicRoughness(m);
        return {};
    }

    /**
     * Puts png in place of image's bytes if only the group's slots show that image and they
     * place it as the mesh's UVs; false (nothing done) otherwise.
     */
    bool replaceImage(int image, const std::vector<std::size_t>& group, Slot slot,
                      const Json& placement, const Bytes& png) {
        if (image < 0 || !m_json.contains("images") || std::size_t(image) >= images().size())
            return false;
        const Json& img = images()[std::size_t(image)];
        if (!img.contains("bufferView") || !img["bufferView"].is_number_integer())
            return false;
        const auto view = img["bufferView"].get<std::size_t>();
        for (std::size_t i = 0; i < images().size(); ++i)
            if (i != std::size_t(image) && images()[i].value("bufferView", Json()) == view)
                return false;
        // The textures showing the image, and every use of them.
        std::set<int> showing;
        if (m_json.contains("textures"))
            for (std::size_t t = 0; t < textures().size(); ++t)
                if (showsImage(textures()[t], image))
                    showing.insert(int(t));
        const std::set<std::size_t> members(group.begin(), group.end());
        for (std::size_t m = 0; m < materials().size(); ++m) {
            std::vector<std::pair<std::string, int>> infos;
            collectTextureInfos(materials()[m], "", infos);
            for (const auto& [at, t] : infos) {
                if (!showing.count(t))
                    continue;
                if (!members.count(m) || at != slotPointer(slot) ||
                    placementOf(materials()[m][Json::json_pointer(at)]) != placement)
                    return false;
            }
        }
        for (std::size_t m : group) {
            const Json::json_pointer at(slotPointer(slot));
            if (m >= materials().size() || !materials()[m].contains(at) ||
                !showing.count(materials()[m][at].value("index", -1)))
                return false;
        }
        m_replaced[view] = png;
        images()[std::size_t(image)]["mimeType"] = "image/png";
        return true;
    }

    /** The sampler of material m's slot's texture (or of its base colour's), or null. */
    Json samplerOf(std::size_t m, Slot slot) {
        const Json& mat = material(m);
        for (const char* at : {slotPointer(slot), slotPointer(Slot::BaseColor)}) {
            const Json::json_pointer pointer(at);
            if (!mat.contains(pointer) || !m_json.contains("textures"))
                continue;
            const int t = mat[pointer].value("index", -1);
            if (t >= 0 && std::size_t(t) < textures().size() && textures()[t].contains("sampler"))
                return textures()[t]["sampler"];
        }
        return Json();
    }

    /** png as a new image in a new view and a new texture of it; the texture's index. */
    int addTexture(Bytes png, const Json& sampler) {
        if (!m_json.contains("images"))
            images() = Json::array();
        if (!m_json.contains("textures"))
            textures() = Json::array();
        m_added.push_back({std::move(png), Json::object()});
        images().push_back(
            {{"bufferView", m_keptViews.size() + m_added.size() - 1}, {"mimeType", "image/png"}});
        Json texture = {{"source", images().size() - 1}};
        if (!sampler.is_null())
            texture["sampler"] = sampler;
        textures().push_back(std::move(texture));
        return int(textures().size() - 1);
    }

    /** Material m's page holds its base colour factor and vertex colours now. */
    void bakedBaseColor(std::size_t m) {
        Json& mat = material(m);
        Json& pbr = mat["pbrMetallicRoughness"];
        whiteBaseColorFactor(m, "the painted base colour texture");
        if (mat.contains("extensions") && mat["extensions"].contains(kSpecularGlossiness)) {
            mat["extensions"].erase(kSpecularGlossiness);
            if (mat["extensions"].empty())
                mat.erase("extensions");
            pbr["metallicFactor"] = m_mesh.materials[m].metallicFactor;
            pbr["roughnessFactor"] = m_mesh.materials[m].roughnessFactor;
            m_warnings.push_back("material \"" + m_mesh.materials[m].name +
                                 "\": " + kSpecularGlossiness +
                                 " is written as metallic-roughness with the painted colour");
        }
        for (const auto& at : m_primitivesOf[m]) {
            Json& prim = primitive(at);
            if (prim.contains("attributes"))
                prim["attributes"].erase("COLOR_0");
            const Json::json_pointer draco("/extensions/KHR_draco_mesh_compression/attributes");
            if (prim.contains(draco) && prim[draco].is_object())
                prim[draco].erase("COLOR_0");
        }
    }

    /** Material m's metallic-roughness page holds its factors now. */
    void bakedMetallicRoughness(std::size_t m) {
        Json& pbr = material(m)["pbrMetallicRoughness"];
        pbr.erase("metallicFactor");
        pbr.erase("roughnessFactor");
    }

    // ---- an automatic UV layout's vertices

    /**
     * Each primitive (at its first placement) gets the layout's vertices: its attributes and
     * morph targets gathered at the vertices they copy, the layout's UVs as TEXCOORD_0 and its
     * triangles as uint32 indices. Only primitives without texture coordinates of their own.
     */
    Status relayPrimitives() {
        if (m_mesh.sourceVertices.size() != m_mesh.vertexCount() || m_mesh.hasColors())
            return Error{"its texture coordinates were laid out anew"};
        m_relaid = true;
        std::set<std::pair<std::uint32_t, std::uint32_t>> done;
        std::size_t used = 0;
        bool instanced = false;
        for (const SourcePrimitive& run : m_scene.primitives) {
            const std::size_t usedAt = used;
            used += run.flags & SourcePrimitive::kPartial ? run.vertexCount : 0;
            if (!done.insert({run.mesh, run.primitive}).second) {
                instanced = true;
                continue;
            }
            if (Status s = relayPrimitive(run, usedAt); !s)
                return s;
        }
        if (instanced)
            m_warnings.push_back("meshes placed more than once show the painting of their first "
                                 "placement");
        return {};
    }

    Status relayPrimitive(const SourcePrimitive& run, std::size_t usedAt) {
        Json& prim = primitive({run.mesh, run.primitive});
        for (auto it = prim["attributes"].begin(); it != prim["attributes"].end(); ++it)
            if (it.key().rfind("TEXCOORD_", 0) == 0)
                return Error{"the automatic UV layout would replace the file's texture "
                             "coordinates"};
        // The layout's vertices of the run, in order of first use, and what each copies.
        std::vector<std::uint32_t> vertices, local, indices;
        m_number.resize(m_mesh.vertexCount(), kUnnumbered);
        for (std::size_t i = 3 * std::size_t(run.firstTriangle);
             i < 3 * (std::size_t(run.firstTriangle) + run.triangleCount); ++i) {
            const std::uint32_t v = m_mesh.indices[i];
            const bool added = m_number[v] == kUnnumbered;
            if (added)
                m_number[v] = std::uint32_t(vertices.size());
            indices.push_back(m_number[v]);
            if (!added)
                continue;
            const std::uint32_t original = m_mesh.sourceVertices[v];
            if (original < run.firstVertex || original - run.firstVertex >= run.vertexCount)
                return Error{"the model's vertices changed"};
            const std::uint32_t k = original - run.firstVertex;
            vertices.push_back(v);
            local.push_back(
                run.flags & SourcePrimitive::kPartial ? m_scene.usedVertices.at(usedAt + k) : k);
        }
        for (std::uint32_t v : vertices)
            m_number[v] = kUnnumbered;
        if (Status s = gatherAttributes(prim["attributes"], local); !s)
            return s;
        if (prim.contains("targets"))
            for (Json& target : prim["targets"])
                if (Status s = gatherAttributes(target, local); !s)
                    return s;
        std::vector<float> uvs;
        for (std::uint32_t v : vertices)
            uvs.insert(uvs.end(), {m_mesh.uvs[v].x, m_mesh.uvs[v].y});
        prim["attributes"]["TEXCOORD_0"] =
            addAccessor(asBytes(uvs), {{"byteStride", 8}, {"target", kVertexData}},
                        {{"componentType", 5126}, {"count", vertices.size()}, {"type", "VEC2"}});
        prim["indices"] =
            addAccessor(asBytes(indices), {{"target", kIndexData}},
                        {{"componentType", 5125}, {"count", indices.size()}, {"type", "SCALAR"}});
        prim.erase("mode"); // triangles, as flattened
        return {};
    }

    /** Every accessor of attributes gathered at the primitive's vertices local. */
    Status gatherAttributes(Json& attributes, const std::vector<std::uint32_t>& local) {
        for (auto it = attributes.begin(); it != attributes.end(); ++it) {
            Result<GatheredAccessor> g =
                gatherAccessor(m_scene.json, m_scene.bin, it->get<std::size_t>(), local);
            if (!g)
                return g.takeError();
            *it = addAccessor(std::move(g->bytes),
                              {{"byteStride", g->stride}, {"target", kVertexData}},
                              std::move(g->accessor));
        }
        return {};
    }

    template <typename T> static Bytes asBytes(const std::vector<T>& values) {
        const auto* p = reinterpret_cast<const std::uint8_t*>(values.data());
        return Bytes(p, p + values.size() * sizeof(T));
    }

    /** bytes as a new view with fields, and accessor into it; the accessor's index. */
    std::size_t addAccessor(Bytes bytes, Json fields, Json accessor) {
        m_added.push_back({std::move(bytes), std::move(fields)});
        accessor["bufferView"] = m_keptViews.size() + m_added.size() - 1;
        m_json["accessors"].push_back(std::move(accessor));
        return m_json["accessors"].size() - 1;
    }

    // ---- painted vertex colours

    /**
     * Painted vertex colours as each primitive's COLOR_0 (float RGBA, linear; white where the
     * primitive has vertices no triangle uses); its materials' factors are in them.
     */
    Status writeVertexColours() {
        if (m_relaid || !m_mesh.hasColors() || hashValues(m_mesh.colors) == m_scene.colorHash)
            return {};
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<float>> written;
        bool differ = false;
        std::size_t used = 0;
        for (const SourcePrimitive& run : m_scene.primitives) {
            std::vector<float> colours(std::size_t(run.sourceVertices) * 4, 1.0f);
            const bool partial = run.flags & SourcePrimitive::kPartial;
            for (std::size_t k = 0; k < run.vertexCount; ++k) {
                const std::size_t local = partial ? m_scene.usedVertices.at(used + k) : k;
                const glm::vec4& c = m_mesh.colors.at(run.firstVertex + k);
                if (local >= run.sourceVertices)
                    return Error{"a primitive's vertices differ from the scene's"};
                std::copy(&c.x, &c.x + 4, colours.begin() + std::ptrdiff_t(local * 4));
            }
            used += partial ? run.vertexCount : 0;
            const auto [it, added] = written.emplace(std::pair(run.mesh, run.primitive), colours);
            if (!added) {
                differ = differ || it->second != colours;
                continue;
            }
            primitive({run.mesh, run.primitive})["attributes"]["COLOR_0"] = addAccessor(
                asBytes(colours), {{"target", kVertexData}},
                {{"componentType", 5126}, {"count", run.sourceVertices}, {"type", "VEC4"}});
        }
        if (differ)
            m_warnings.push_back("meshes placed more than once keep the colours painted on their "
                                 "first placement");
        for (std::size_t m = 0; m < m_mesh.materials.size(); ++m)
            if (!m_primitivesOf[m].empty())
                whiteBaseColorFactor(m, "the painted vertex colours");
        return {};
    }

    /**
     * Drops material m's base colour factor, which painting multiplied into where (the view
     * shows the painted colour, which a factor kept apart could not tint back for every colour);
     * a warning says so where it was other than white.
     */
    void whiteBaseColorFactor(std::size_t m, const char* where) {
        Json& pbr = material(m)["pbrMetallicRoughness"];
        if (!pbr.contains("baseColorFactor") || pbr["baseColorFactor"] == Json::array({1, 1, 1, 1}))
            return;
        pbr.erase("baseColorFactor");
        m_warnings.push_back("material \"" + m_mesh.materials[m].name +
                             "\": its base colour factor is multiplied into " + where +
                             " and written as white");
    }

    /** An extension nothing uses any longer leaves extensionsUsed and extensionsRequired. */
    void dropUnusedExtension(const char* name) {
        if (m_json.contains("materials"))
            for (const Json& mat : materials())
                if (mat.contains("extensions") && mat["extensions"].contains(name))
                    return;
        for (const char* list : {"extensionsUsed", "extensionsRequired"}) {
            if (!m_json.contains(list) || !m_json[list].is_array())
                continue;
            Json& names = m_json[list];
            names.erase(std::remove(names.begin(), names.end(), Json(name)), names.end());
            if (names.empty())
                m_json.erase(list);
        }
    }

    /** Images the scene could not take into its buffer stay references to their files. */
    void warnAboutFileImages() {
        if (!m_json.contains("images"))
            return;
        for (std::size_t i = 0; i < images().size(); ++i)
            if (images()[i].contains("uri") && images()[i]["uri"].is_string() &&
                images()[i]["uri"].get<std::string>().rfind("data:", 0) != 0)
                m_warnings.push_back("image " + std::to_string(i) + " (" +
                                     images()[i]["uri"].get<std::string>() +
                                     ") could not be read: the file refers to it by name");
    }

    // ---- extras, attachments, the BIN chunk

    Status addExtras() {
        const Json& extras = m_additions.extras;
        if (extras.is_null() && m_additions.attachments.empty())
            return {};
        if (!extras.is_null() && !extras.is_object())
            return Error{"the extras to save are not a JSON object"};
        Json& asset = m_json["asset"];
        if (asset.contains("extras") && !asset["extras"].is_object()) {
            m_warnings.push_back("the file's asset.extras is not a JSON object and is replaced");
            asset.erase("extras");
        }
        Json& out = asset["extras"];
        if (extras.is_object())
            for (auto it = extras.begin(); it != extras.end(); ++it)
                out[it.key()] = *it;
        if (!m_additions.attachments.empty()) {
            Json views = Json::array();
            for (const Bytes& bytes : m_additions.attachments) {
                m_added.push_back({bytes, Json::object()});
                views.push_back(m_keptViews.size() + m_added.size() - 1);
            }
            out[m_additions.attachmentsAt] = std::move(views);
        }
        return {};
    }

    /** The views laid out anew: the kept ones (replaced where painted), then the added ones. */
    Result<GlbContent> assemble() {
        GlbContent out;
        Json views = Json::array();
        const auto place = [&](const std::uint8_t* data, std::size_t size, Json view) {
            out.bin.resize((out.bin.size() + 3) & ~std::size_t{3}, 0);
            view["buffer"] = 0;
            view["byteOffset"] = out.bin.size();
            view["byteLength"] = size;
            out.bin.insert(out.bin.end(), data, data + size);
            views.push_back(std::move(view));
        };
        for (std::size_t v = 0; v < m_keptViews.size(); ++v) {
            Json view = m_json["bufferViews"][m_keptViews[v]];
            if (const auto it = m_replaced.find(v); it != m_replaced.end()) {
                view.erase("byteStride");
                place(it->second.data(), it->second.size(), std::move(view));
                continue;
            }
            const auto offset = view.value("byteOffset", std::uint64_t{0});
            const auto length = view.at("byteLength").get<std::uint64_t>();
            if (offset > m_scene.bin.size() || length > m_scene.bin.size() - offset)
                return Error{"a buffer view of the scene lies outside its buffer"};
            place(m_scene.bin.data() + offset, std::size_t(length), std::move(view));
        }
        for (const AddedView& added : m_added)
            place(added.bytes.data(), added.bytes.size(), added.fields);
        out.bin.resize((out.bin.size() + 3) & ~std::size_t{3}, 0);
        if (views.empty())
            m_json.erase("bufferViews");
        else
            m_json["bufferViews"] = std::move(views);
        if (out.bin.empty())
            m_json.erase("buffers");
        else
            m_json["buffers"] = Json::array({{{"byteLength", out.bin.size()}}});
        out.root = std::move(m_json);
        return out;
    }
};

} // namespace

std::string writeBackBlocker(const Mesh& mesh) {
    if (!mesh.source)
        return "the model was not read from a glTF file";
    const SourceScene& scene = *mesh.source;
    if (!scene.notKept.empty())
        return scene.notKept;
    std::uint64_t next = 0;
    for (const SourcePrimitive& run : scene.primitives) {
        if (run.firstTriangle != next)
            return "the model's triangles changed";
        next += run.triangleCount;
    }
    if (next != mesh.triangleCount())
        return "the model's triangles changed";
    const bool relaid = hashValues(mesh.uvs) != scene.uvHash;
    if (relaid && mesh.sourceVertices.empty())
        return "its texture coordinates were laid out anew; painting with vertex colours keeps "
               "it";
    std::uint64_t used = 0;
    const bool painted = mesh.hasColors() && hashValues(mesh.colors) != scene.colorHash;
    for (const SourcePrimitive& run : scene.primitives) {
        if (!relaid && std::uint64_t(run.firstVertex) + run.vertexCount > mesh.vertexCount())
            return "the model's vertices changed";
        used += run.flags & SourcePrimitive::kPartial ? run.vertexCount : 0;
        if (painted && (run.flags & SourcePrimitive::kDraco))
            return "vertex colours were painted on Draco-compressed primitives";
        if (relaid && (run.flags & SourcePrimitive::kDraco))
            return "the automatic UV layout is on Draco-compressed primitives";
    }
    if (used != scene.usedVertices.size())
        return "the model's vertices changed";
    if (mesh.textureOrigins.size() != mesh.textures.size())
        return "its textures' origins are unknown";
    return {};
}

Result<GlbContent> writeBack(const Mesh& mesh, const GlbAdditions& additions,
                             const ProgressFn& progress, std::vector<std::string>& warnings) {
    try {
        std::vector<std::string> found;
        Result<GlbContent> out = SceneWriter(mesh, additions, progress, found).run();
        if (out)
            warnings.insert(warnings.end(), found.begin(), found.end());
        return out;
    } catch (const nlohmann::json::exception& e) {
        return Error{std::string("the scene cannot be read (") + e.what() + ")"};
    }
}

} // namespace core::detail::gltf
