// SPDX-License-Identifier: GPL-3.0-or-later
// Assimp's scene checked and flattened into one Mesh (see assimp_flatten.h).
#include "core/io/assimp/assimp_flatten.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

#include <assimp/material.h>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "core/base/color.h"
#include "core/io/assimp/assimp_file_access.h"
#include "core/io/importer/mesh_io_in_process.h"

namespace core::detail::assimp {

namespace fs = std::filesystem;

namespace {

glm::dmat4 toGlm(const aiMatrix4x4& m) {
    // aiMatrix4x4 is row-major (a1..a4 is the first row); glm is column-major.
    return glm::dmat4(m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4,
                      m.b4, m.c4, m.d4);
}

} // namespace

Status checkRawScene(const aiScene& scene, const LoadLimits& limits) {
    if (scene.mNumMeshes > 0 && scene.mMeshes == nullptr)
        return Error{"the file's mesh list is missing", ErrorKind::BadInput};
    // Before JoinIdenticalVertices an importer may hold a vertex per face corner; beyond that
    // the count is a broken or hostile header.
    const std::uint64_t maxRawVertices = limits.maxVertices * 4;
    std::uint64_t rawVertices = 0;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        aiMesh* mesh = scene.mMeshes[m];
        const std::string where = "mesh " + std::to_string(m);
        if (mesh == nullptr)
            return Error{where + " is missing", ErrorKind::BadInput};
        const unsigned nv = mesh->mNumVertices;
        rawVertices += nv;
        if (rawVertices > maxRawVertices)
            return Error{"too many vertices (more than " + std::to_string(maxRawVertices) +
                             " before merging)",
                         ErrorKind::BadInput};
        if (nv > 0 && mesh->mVertices == nullptr)
            return Error{where + " has no vertex positions", ErrorKind::BadInput};
        if (mesh->mNumFaces > 0 && mesh->mFaces == nullptr)
            return Error{where + " has no face list", ErrorKind::BadInput};
        unsigned types = 0;
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const aiFace& face = mesh->mFaces[f];
            if (face.mNumIndices == 0 || face.mIndices == nullptr)
                return Error{where + " has a face without vertices", ErrorKind::BadInput};
            for (unsigned k = 0; k < face.mNumIndices; ++k)
                if (face.mIndices[k] >= nv)
                    return Error{where + ": vertex index " + std::to_string(face.mIndices[k]) +
                                     " is out of range (the mesh has " + std::to_string(nv) +
                                     " vertices)",
                                 ErrorKind::BadInput};
            types |= face.mNumIndices == 1   ? aiPrimitiveType_POINT
                     : face.mNumIndices == 2 ? aiPrimitiveType_LINE
                     : face.mNumIndices == 3 ? aiPrimitiveType_TRIANGLE
                                             : aiPrimitiveType_POLYGON;
        }
        mesh->mPrimitiveTypes = types;
        if (mesh->mNumBones > 0 && mesh->mBones == nullptr)
            return Error{where + " has a missing bone list", ErrorKind::BadInput};
        for (unsigned b = 0; b < mesh->mNumBones; ++b) {
            const aiBone* bone = mesh->mBones[b];
            if (bone == nullptr || (bone->mNumWeights > 0 && bone->mWeights == nullptr))
                return Error{where + " has a broken bone", ErrorKind::BadInput};
            for (unsigned w = 0; w < bone->mNumWeights; ++w)
                if (bone->mWeights[w].mVertexId >= nv)
                    return Error{where + " has a bone weight for a vertex that does not exist",
                                 ErrorKind::BadInput};
        }
        if (mesh->mNumAnimMeshes > 0 && mesh->mAnimMeshes == nullptr)
            return Error{where + " has a missing morph target list", ErrorKind::BadInput};
        for (unsigned a = 0; a < mesh->mNumAnimMeshes; ++a) {
            const aiAnimMesh* anim = mesh->mAnimMeshes[a];
            if (anim == nullptr || anim->mNumVertices != nv ||
                (nv > 0 && anim->mVertices == nullptr))
                return Error{where + " has a broken morph target", ErrorKind::BadInput};
        }
    }
    return {};
}

namespace {

class AssimpFlattener : public Flattener {
public:
    AssimpFlattener(const aiScene& scene, fs::path folder, const LoadLimits& limits)
        : m_scene(scene), m_folder(std::move(folder)), m_limits(limits) {}

    bool run(Mesh& out);

private:
    const aiScene& m_scene;
    fs::path m_folder;
    const LoadLimits& m_limits;
    std::size_t m_skippedFaces = 0;
    std::map<std::string, int> m_textureCache;

    bool addMesh(unsigned meshIndex, const glm::dmat4& transform);
    /** What the file calls node's mesh meshIndex: the node's name, else the mesh's, else "". */
    std::string objectName(const aiNode& node, unsigned meshIndex) const;
    void addMaterials();
    /** The factors, alpha and base colour of am. */
    Material readMaterial(const aiMaterial& am, unsigned index);
    /** The maps of am besides the base colour, loaded after every base colour texture. */
    void readMaterialMaps(const aiMaterial& am, Material& mat);
    /**
     * Whether am has a texture of one of types, and the first one's path. map names the map in
     * the warning for a texture on another coordinate set, which is kept on set 0 (nullptr: the
     * base colour, which is then left out).
     */
    bool firstTexture(const aiMaterial& am, std::initializer_list<aiTextureType> types,
                      const Material& mat, const char* map, std::string& path);
    int loadTexture(const std::string& path);
    /** Separate metalness and roughness images as one glTF metallic-roughness texture. */
    int combinedMetallicRoughness(int metal, int rough);
    /**
     * Keeps only the textures the materials use (not the separate metalness and roughness
     * images), base colour textures first.
     */
    void dropUnusedTextures();
};

bool AssimpFlattener::addMesh(unsigned meshIndex, const glm::dmat4& transform) {
    if (meshIndex >= m_scene.mNumMeshes || m_scene.mMeshes == nullptr ||
        m_scene.mMeshes[meshIndex] == nullptr)
        return fail("a node uses mesh " + std::to_string(meshIndex) + ", which does not exist");
    const aiMesh& am = *m_scene.mMeshes[meshIndex];
    const unsigned vertexCount = am.mNumVertices;
    if (vertexCount == 0 || am.mVertices == nullptr || am.mFaces == nullptr)
        return true;

    // Triangles only; remember which vertices they use.
    std::vector<std::uint32_t> tris;
    tris.reserve(static_cast<std::size_t>(am.mNumFaces) * 3);
    for (unsigned f = 0; f < am.mNumFaces; ++f) {
        const aiFace& face = am.mFaces[f];
        if (face.mNumIndices != 3 || face.mIndices == nullptr) {
            ++m_skippedFaces;
            continue;
        }
        for (unsigned k = 0; k < 3; ++k) {
            if (face.mIndices[k] >= vertexCount)
                return fail("mesh " + std::to_string(meshIndex) + ": vertex index " +
                            std::to_string(face.mIndices[k]) + " is out of range (the mesh has " +
                            std::to_string(vertexCount) + " vertices)");
            tris.push_back(face.mIndices[k]);
        }
    }
    if (tris.empty())
        return true;

    Result<UsedVertices> usedVertices = numberUsedVertices(tris, vertexCount, m_mesh, m_limits);
    if (!usedVertices)
        return fail(usedVertices.error());
    const std::vector<std::uint32_t>& remap = usedVertices->remap;

    const bool hasNormals = am.mNormals != nullptr;
    const bool hasUv = am.mTextureCoords[0] != nullptr;
    const bool hasColor = am.mColors[0] != nullptr;
    const glm::dmat3 normalMatrix = glm::inverseTranspose(glm::dmat3(transform));
    const bool mirrored = glm::determinant(glm::dmat3(transform)) < 0.0;
    const auto base = static_cast<std::uint32_t>(m_mesh.positions.size());
    for (unsigned v = 0; v < vertexCount; ++v) {
        if (remap[v] == std::numeric_limits<std::uint32_t>::max())
            continue;
        const aiVector3D& p = am.mVertices[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return fail("mesh " + std::to_string(meshIndex) +
                        ": a vertex position is not a finite number");
        glm::vec3 tp;
        if (!toFloat(glm::dvec3(transform * glm::dvec4(p.x, p.y, p.z, 1.0)), tp))
            return fail("mesh " + std::to_string(meshIndex) +
                        ": a vertex position is not finite after the node transform");
        m_mesh.positions.push_back(tp);
        if (hasNormals) {
            const aiVector3D& n = am.mNormals[v];
            m_mesh.normals.push_back(unitNormal(normalMatrix * glm::dvec3(n.x, n.y, n.z)));
        } else {
            m_mesh.normals.push_back(glm::vec3(0.0f));
        }
        m_hasNormal.push_back(hasNormals ? 1 : 0);
        if (hasUv) {
            const aiVector3D& t = am.mTextureCoords[0][v];
            const float tv = am.mNumUVComponents[0] >= 2 ? t.y : 0.0f;
            m_mesh.uvs.push_back(glm::vec2(t.x, 1.0f - tv));
        } else {
            m_mesh.uvs.push_back(glm::vec2(0.0f));
        }
        if (hasColor) {
            const aiColor4D& c = am.mColors[0][v];
            m_mesh.colors.push_back(
                glm::vec4(srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b),
                          std::isfinite(c.a) ? std::clamp(c.a, 0.0f, 1.0f) : 1.0f));
        } else {
            m_mesh.colors.push_back(glm::vec4(1.0f));
        }
    }
    m_anyUv = m_anyUv || hasUv;
    m_anyColor = m_anyColor || hasColor;

    const std::uint32_t material =
        am.mMaterialIndex < m_scene.mNumMaterials ? am.mMaterialIndex : m_scene.mNumMaterials;
    for (std::size_t t = 0; t < tris.size(); t += 3) {
        const std::uint32_t a = base + remap[tris[t]];
        const std::uint32_t b = base + remap[tris[t + 1]];
        const std::uint32_t c = base + remap[tris[t + 2]];
        if (mirrored) // keep triangles front-facing under a mirroring node transform
            m_mesh.indices.insert(m_mesh.indices.end(), {a, c, b});
        else
            m_mesh.indices.insert(m_mesh.indices.end(), {a, b, c});
        m_mesh.triangleMaterial.push_back(material);
    }
    return true;
}

int AssimpFlattener::loadTexture(const std::string& path) {
    if (const auto it = m_textureCache.find(path); it != m_textureCache.end())
        return it->second;
    int result = -1;
    const std::string label = "texture \"" + path + "\"";
    std::vector<std::uint8_t> bytes;
    const aiTexture* embedded = m_scene.GetEmbeddedTexture(path.c_str());
    if (embedded != nullptr) {
        if (embedded->mHeight == 0) { // compressed (PNG, JPEG, ...), mWidth bytes
            const auto* data = reinterpret_cast<const std::uint8_t*>(embedded->pcData);
            if (data == nullptr || embedded->mWidth == 0) {
                m_mesh.warnings.push_back(label + " is empty; the material has no texture");
            } else {
                Result<Image> img = decodeImage(data, embedded->mWidth, label, m_limits);
                if (img) {
                    result = addTexture(std::move(img).value(), data, embedded->mWidth);
                } else {
                    m_mesh.warnings.push_back(img.error() + "; the material has no texture");
                }
            }
        } else { // raw BGRA texels
            const std::uint64_t w = embedded->mWidth, h = embedded->mHeight;
            if (embedded->pcData == nullptr || w * h > m_limits.maxImagePixels || w > 65536 ||
                h > 65536) {
                m_mesh.warnings.push_back(label + " is too large or empty; the material has no "
                                                  "texture");
            } else {
                Image img;
                img.width = static_cast<int>(w);
                img.height = static_cast<int>(h);
                img.rgba.resize(static_cast<std::size_t>(w * h * 4));
                for (std::size_t i = 0; i < w * h; ++i) {
                    const aiTexel& t = embedded->pcData[i];
                    img.rgba[i * 4 + 0] = t.r;
                    img.rgba[i * 4 + 1] = t.g;
                    img.rgba[i * 4 + 2] = t.b;
                    img.rgba[i * 4 + 3] = t.a;
                }
                result = addTexture(std::move(img));
            }
        }
    } else if (!path.empty() && path[0] == '*') {
        m_mesh.warnings.push_back(label + " refers to a missing embedded texture");
    } else {
        // External file: inside the model's folder only. Paths written on Windows use '\';
        // absolute or escaping paths fall back to the bare file name in the model's folder.
        std::string clean = path;
        std::replace(clean.begin(), clean.end(), '\\', '/');
        bool outside = false;
        fs::path real = confine(fs::path(clean), m_folder, &outside);
        std::error_code ec;
        if (real.empty() || !fs::is_regular_file(real, ec)) {
            const fs::path name = fs::path(clean).filename();
            if (!name.empty() && name != "." && name != "..")
                real = confine(name, m_folder);
        }
        if (real.empty() || !fs::is_regular_file(real, ec)) {
            m_mesh.warnings.push_back(
                label + (outside ? " is outside the model's folder" : " was not found") +
                "; the material has no texture");
        } else if (!readFile(real, m_limits.maxFileBytes, bytes)) {
            m_mesh.warnings.push_back(label + " cannot be read; the material has no texture");
        } else {
            Result<Image> img = decodeImage(bytes.data(), bytes.size(), label, m_limits);
            if (img) {
                result = addTexture(std::move(img).value(), bytes.data(), bytes.size());
            } else {
                m_mesh.warnings.push_back(img.error() + "; the material has no texture");
            }
        }
    }
    m_textureCache[path] = result;
    return result;
}

Material AssimpFlattener::readMaterial(const aiMaterial& am, unsigned index) {
    Material mat; // rough plastic, not metal, unless the file says otherwise
    aiString name;
    mat.name = am.Get(AI_MATKEY_NAME, name) == AI_SUCCESS && name.length > 0
                   ? std::string(name.C_Str())
                   : "material " + std::to_string(index);
    aiColor4D color(1.0f, 1.0f, 1.0f, 1.0f);
    const bool pbrColor = am.Get(AI_MATKEY_BASE_COLOR, color) == AI_SUCCESS;
    bool diffuseColor = false;
    if (!pbrColor)
        diffuseColor = am.Get(AI_MATKEY_COLOR_DIFFUSE, color) == AI_SUCCESS;
    float opacity = 1.0f;
    if (am.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS && std::isfinite(opacity)) {
        color.a = std::clamp(opacity, 0.0f, 1.0f) * (pbrColor ? color.a : 1.0f);
        if (opacity < 1.0f)
            mat.alphaMode = AlphaMode::Blend;
    }
    // Assimp invents "DefaultMaterial" (grey) for files without one: use glTF's white.
    if (mat.name == AI_DEFAULT_MATERIAL_NAME)
        color = aiColor4D(1.0f, 1.0f, 1.0f, 1.0f);
    mat.baseColorFactor = glm::vec4(color.r, color.g, color.b, color.a);

    const auto factor = [&](const char* key, unsigned type, unsigned idx, float& out, float lo,
                            float hi) {
        float v = 0.0f;
        if (am.Get(key, type, idx, v) == AI_SUCCESS && std::isfinite(v))
            out = std::clamp(v, lo, hi);
    };
    factor(AI_MATKEY_METALLIC_FACTOR, mat.metallicFactor, 0.0f, 1.0f);
    factor(AI_MATKEY_ROUGHNESS_FACTOR, mat.roughnessFactor, 0.0f, 1.0f);
    factor(AI_MATKEY_EMISSIVE_INTENSITY, mat.emissiveStrength, 0.0f, 1e6f);
    aiColor3D emissive(0.0f, 0.0f, 0.0f);
    if (am.Get(AI_MATKEY_COLOR_EMISSIVE, emissive) == AI_SUCCESS)
        mat.emissiveFactor = glm::vec3(emissive.r, emissive.g, emissive.b);
    int twoSided = 0;
    if (am.Get(AI_MATKEY_TWOSIDED, twoSided) == AI_SUCCESS)
        mat.doubleSided = twoSided != 0;

    std::string path;
    if (firstTexture(am, {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE}, mat, nullptr, path)) {
        mat.baseColorTexture = loadTexture(path);
        if (mat.baseColorTexture >= 0 && diffuseColor)
            mat.baseColorFactor = glm::vec4(1.0f, 1.0f, 1.0f, mat.baseColorFactor.a);
    }
    for (int k = 0; k < 4; ++k)
        if (!std::isfinite(mat.baseColorFactor[k]))
            mat.baseColorFactor[k] = 1.0f;
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(mat.emissiveFactor[k]) || mat.emissiveFactor[k] < 0.0f)
            mat.emissiveFactor[k] = 0.0f;
    return mat;
}

bool AssimpFlattener::firstTexture(const aiMaterial& am, std::initializer_list<aiTextureType> types,
                                   const Material& mat, const char* map, std::string& path) {
    for (aiTextureType type : types) {
        if (am.GetTextureCount(type) == 0)
            continue;
        aiString texPath;
        unsigned uvIndex = 0;
        if (am.GetTexture(type, 0, &texPath, nullptr, &uvIndex) != AI_SUCCESS)
            continue;
        if (uvIndex != 0) {
            if (map == nullptr) {
                warnOnce("textures on texture coordinate sets other than 0 are ignored");
                return false;
            }
            // As a glTF map on another set: kept, on the mesh's UVs.
            m_mesh.warnings.push_back(
                "material \"" + mat.name + "\": its " + map + " map uses texture coordinate set " +
                std::to_string(uvIndex) + ", which is not loaded; it is placed on set 0 instead");
        }
        path = texPath.C_Str();
        return true;
    }
    return false;
}

namespace {

/** Texel (x, y) of image's channel, the image stretched over width × height (nearest). */
std::uint8_t stretched(const Image& image, int channel, int x, int y, int width, int height) {
    const int sx = int((std::int64_t(x) * image.width) / width);
    const int sy = int((std::int64_t(y) * image.height) / height);
    return image.rgba[(std::size_t(sy) * std::size_t(image.width) + std::size_t(sx)) * 4 +
                      std::size_t(channel)];
}

} // namespace

int AssimpFlattener::combinedMetallicRoughness(int metal, int rough) {
    const Image* m = metal >= 0 ? &m_mesh.textures[std::size_t(metal)] : nullptr;
    const Image* r = rough >= 0 ? &m_mesh.textures[std::size_t(rough)] : nullptr;
    // The larger size; the other image is stretched over it. A missing one is 1 (its factor
    // alone then says the value).
    Image out;
    out.width = std::max(m ? m->width : 0, r ? r->width : 0);
    out.height = std::max(m ? m->height : 0, r ? r->height : 0);
    out.rgba.resize(std::size_t(out.width) * std::size_t(out.height) * 4);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            std::uint8_t* px =
                &out.rgba[(std::size_t(y) * std::size_t(out.width) + std::size_t(x)) * 4];
            px[0] = 255;
            px[1] = r ? stretched(*r, 0, x, y, out.width, out.height) : 255;
            px[2] = m ? stretched(*m, 0, x, y, out.width, out.height) : 255;
            px[3] = 255;
        }
    return addTexture(std::move(out));
}

void AssimpFlattener::readMaterialMaps(const aiMaterial& am, Material& mat) {
    std::string path, diffusePath;
    firstTexture(am, {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE}, mat, nullptr, diffusePath);
    if (firstTexture(am, {aiTextureType_NORMALS, aiTextureType_NORMAL_CAMERA}, mat, "normal",
                     path)) {
        mat.normal.texture = loadTexture(path);
    } else if (am.GetTextureCount(aiTextureType_HEIGHT) > 0) {
        m_mesh.warnings.push_back("material \"" + mat.name +
                                  "\": its height (bump) map is not a normal map and is not used");
    }
    if (firstTexture(am, {aiTextureType_EMISSION_COLOR, aiTextureType_EMISSIVE}, mat, "emissive",
                     path)) {
        mat.emissive.texture = loadTexture(path);
        // A texture without a colour to scale it shows as it is.
        if (mat.emissive.texture >= 0 && mat.emissiveFactor == glm::vec3(0.0f))
            mat.emissiveFactor = glm::vec3(1.0f);
    }
    // Ambient occlusion; an ambient map that is the diffuse map again is no occlusion.
    if (firstTexture(am, {aiTextureType_AMBIENT_OCCLUSION, aiTextureType_LIGHTMAP}, mat,
                     "occlusion", path) ||
        (firstTexture(am, {aiTextureType_AMBIENT}, mat, "occlusion", path) && path != diffusePath))
        mat.occlusion.texture = loadTexture(path);

    std::string metalPath, roughPath;
    const bool hasMetal = firstTexture(am, {aiTextureType_METALNESS}, mat, "metallic", metalPath);
    const bool hasRough =
        firstTexture(am, {aiTextureType_DIFFUSE_ROUGHNESS}, mat, "roughness", roughPath);
    if (hasMetal && hasRough && metalPath == roughPath) {
        mat.metallicRoughness.texture = loadTexture(metalPath); // one glTF-style image
    } else if (hasMetal || hasRough) {
        const int metal = hasMetal ? loadTexture(metalPath) : -1;
        const int rough = hasRough ? loadTexture(roughPath) : -1;
        if (metal >= 0 || rough >= 0)
            mat.metallicRoughness.texture = combinedMetallicRoughness(metal, rough);
    }
    // A metalness map means metal where it says so.
    if (mat.metallicRoughness.texture >= 0 && hasMetal &&
        am.Get(AI_MATKEY_METALLIC_FACTOR, mat.metallicFactor) != AI_SUCCESS)
        mat.metallicFactor = 1.0f;
}

void AssimpFlattener::addMaterials() {
    // Every base colour texture first, then the other maps (as the glTF loader orders them).
    for (unsigned i = 0; i < m_scene.mNumMaterials; ++i) {
        const aiMaterial* am = m_scene.mMaterials ? m_scene.mMaterials[i] : nullptr;
        if (am == nullptr) {
            Material mat;
            mat.name = "material " + std::to_string(i);
            m_mesh.materials.push_back(mat);
            continue;
        }
        m_mesh.materials.push_back(readMaterial(*am, i));
    }
    for (unsigned i = 0; i < m_scene.mNumMaterials; ++i)
        if (const aiMaterial* am = m_scene.mMaterials ? m_scene.mMaterials[i] : nullptr)
            readMaterialMaps(*am, m_mesh.materials[i]);
    dropUnusedTextures();
}

void AssimpFlattener::dropUnusedTextures() {
    Mesh& mesh = m_mesh;
    mesh.textureSources.resize(mesh.textures.size());
    std::vector<int> remap(mesh.textures.size(), -1);
    std::vector<Image> textures;
    std::vector<EncodedImage> sources;
    const auto use = [&](int& t) {
        if (t < 0)
            return;
        if (remap[std::size_t(t)] < 0) {
            remap[std::size_t(t)] = int(textures.size());
            textures.push_back(std::move(mesh.textures[std::size_t(t)]));
            sources.push_back(std::move(mesh.textureSources[std::size_t(t)]));
        }
        t = remap[std::size_t(t)];
    };
    for (Material& m : mesh.materials)
        use(m.baseColorTexture);
    for (Material& m : mesh.materials)
        for (MaterialMap* map : {&m.metallicRoughness, &m.normal, &m.occlusion, &m.emissive})
            use(map->texture);
    mesh.textures = std::move(textures);
    mesh.textureSources = std::move(sources);
}

std::string AssimpFlattener::objectName(const aiNode& node, unsigned meshIndex) const {
    // Assimp names what a file leaves unnamed "<...>", "$..." or (OBJ) "defaultobject".
    const auto named = [](const aiString& name) {
        return name.length > 0 && name.data[0] != '<' && name.data[0] != '$' &&
               std::string_view(name.C_Str()) != "defaultobject";
    };
    if (named(node.mName))
        return node.mName.C_Str();
    if (meshIndex < m_scene.mNumMeshes && m_scene.mMeshes && m_scene.mMeshes[meshIndex] &&
        named(m_scene.mMeshes[meshIndex]->mName))
        return m_scene.mMeshes[meshIndex]->mName.C_Str();
    return {};
}

bool AssimpFlattener::run(Mesh& out) {
    if (m_scene.mRootNode == nullptr)
        return fail("the file has no scene");
    // Iterative depth-first walk, children in order; guarded against a malformed graph.
    struct Item {
        const aiNode* node;
        glm::dmat4 parent;
    };
    std::vector<Item> stack{{m_scene.mRootNode, glm::dmat4(1.0)}};
    std::unordered_set<const aiNode*> seen;
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        if (item.node == nullptr)
            continue;
        if (!seen.insert(item.node).second)
            return fail("the node hierarchy has a cycle");
        const glm::dmat4 global = item.parent * toGlm(item.node->mTransformation);
        for (unsigned m = 0; m < item.node->mNumMeshes; ++m) {
            if (item.node->mMeshes == nullptr)
                return fail("a node has an invalid mesh list");
            beginObject(objectName(*item.node, item.node->mMeshes[m]));
            if (!addMesh(item.node->mMeshes[m], global))
                return fail("a node has an invalid mesh list");
        }
        for (unsigned c = item.node->mNumChildren; c-- > 0;)
            if (item.node->mChildren != nullptr)
                stack.push_back(Item{item.node->mChildren[c], global});
    }
    if (m_skippedFaces > 0)
        m_mesh.warnings.push_back(m_skippedFaces == 1
                                      ? std::string("1 point or line face was skipped")
                                      : std::to_string(m_skippedFaces) +
                                            " point and line faces were skipped");
    if (m_mesh.indices.empty())
        return fail("the file contains no triangles");

    addMaterials();
    // Meshes without a valid material use a default one after the file's materials.
    const auto defaultIndex = static_cast<std::uint32_t>(m_mesh.materials.size());
    if (std::find(m_mesh.triangleMaterial.begin(), m_mesh.triangleMaterial.end(), defaultIndex) !=
            m_mesh.triangleMaterial.end() ||
        m_mesh.materials.empty())
        m_mesh.materials.push_back(Material{"default", glm::vec4(1.0f), -1});

    finish(out);
    return true;
}

} // namespace

Result<Mesh> flattenAssimp(const aiScene& scene, const fs::path& folder, const LoadLimits& limits) {
    Mesh mesh;
    AssimpFlattener flattener(scene, folder, limits);
    if (!flattener.run(mesh))
        return flattener.error();
    return mesh;
}

} // namespace core::detail::assimp
