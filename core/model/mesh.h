// SPDX-License-Identifier: GPL-3.0-or-later
// core/model/: the mesh and what is made from it alone: topology, camera and view, the
// built-in models, the automatic UV layout, the stand-in drawn while the camera moves.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/base/result.h"

namespace core {

/** An 8-bit RGBA image, rows top first. Base color textures hold sRGB-encoded values. */
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba; // width * height * 4

    bool empty() const { return width <= 0 || height <= 0; }
};

/**
 * A texture's file as the model held it (PNG or JPEG), kept so that a map nobody painted is
 * written back byte for byte instead of re-encoded.
 */
struct EncodedImage {
    std::string mimeType; // "image/png" or "image/jpeg"
    std::vector<std::uint8_t> bytes;

    bool empty() const { return bytes.empty(); }
};

struct SourceScene; // core/model/source_scene.h

/** What a texture is in the scene a mesh was loaded from (Mesh::source). */
struct TextureOrigin {
    int image = -1;         // the glTF image it was made from, -1 for none
    bool unchanged = false; // it shows what the scene's material shows (nothing was painted)
};

/**
 * A named object of the model's file (a glTF node, an OBJ object or group): the triangles from
 * firstTriangle to the next object's first one, or to the end.
 */
struct MeshObject {
    std::string name;
    std::uint32_t firstTriangle = 0;
};

/** How a material's alpha is used, as glTF's alphaMode. */
enum class AlphaMode : std::uint8_t { Opaque, Mask, Blend };

/**
 * Where a material's map other than the base colour lies: its texture and its placement
 * relative to the mesh's uvs (which carry the base colour texture's placement). A map that the
 * file places on another texture coordinate set than the base colour uses the mesh's uvs and
 * the load warns about it.
 */
struct MaterialMap {
    int texture = -1;            // index into Mesh::textures, -1 for none
    glm::mat3 uvTransform{1.0f}; // uv' = (uvTransform * (u, v, 1)).xy of the mesh's uvs
};

/**
 * A glTF 2.0 metallic-roughness material. Factors are linear; textures index Mesh::textures
 * (base colour and emissive hold sRGB-encoded values, the others linear values: metallic in
 * blue, roughness in green, occlusion in red, normals in tangent space). A material made in code
 * is rough plastic (metallicFactor 0); the glTF loader sets glTF's own default (1) where a file
 * says nothing.
 */
struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f}; // linear RGBA
    int baseColorTexture = -1;       // index into Mesh::textures, -1 for none

    float metallicFactor = 0.0f;
    float roughnessFactor = 1.0f;
    MaterialMap metallicRoughness;
    float normalScale = 1.0f;
    MaterialMap normal;
    float occlusionStrength = 1.0f;
    MaterialMap occlusion;
    glm::vec3 emissiveFactor{0.0f};
    float emissiveStrength = 1.0f; // KHR_materials_emissive_strength
    MaterialMap emissive;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
};

struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};

    glm::vec3 center() const { return (min + max) * 0.5f; }
    glm::vec3 size() const { return max - min; }
    /** Length of the longest side; the mesh's unit-cube scale is 1 / longestSide(). */
    float longestSide() const;
    bool valid() const { return min.x <= max.x && min.y <= max.y && min.z <= max.z; }
};

/**
 * A flattened triangle mesh in the file's coordinates. Triangle t uses indices[3t .. 3t+2];
 * triangles are numbered in the order of flattening the default scene (docs/architecture.md §3).
 */
struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals; // same size as positions
    std::vector<glm::vec2> uvs;     // empty, or same size as positions
    std::vector<glm::vec4> colors;  // empty, or same size as positions (linear RGBA)
    /**
     * Empty, or same size as positions: the file's tangents as glTF's TANGENT (w = 0 for the
     * vertices it gave none); vertexTangents() (mesh_tangents.h) fills the rest.
     */
    std::vector<glm::vec4> tangents;
    std::vector<std::uint32_t> indices;
    std::vector<std::uint32_t> triangleMaterial; // one per triangle, index into materials
    std::vector<Material> materials;             // at least one
    std::vector<Image> textures;
    /** Empty, or one per texture: its file's bytes where they are kept (else empty). */
    std::vector<EncodedImage> textureSources;
    std::vector<std::string> warnings; // non-fatal problems met while loading
    /** The glTF scene the mesh was flattened from, to write it back (nullptr: none). */
    std::shared_ptr<const SourceScene> source;
    /** Empty, or one per texture: where it came from in source. */
    std::vector<TextureOrigin> textureOrigins;
    /**
     * Empty, or per vertex: the vertex of the mesh as flattened from source that it copies (an
     * automatic UV layout copies vertices along its seams).
     */
    std::vector<std::uint32_t> sourceVertices;
    /** Empty, or the file's named objects in triangle order (the first from triangle 0). */
    std::vector<MeshObject> objects;

    std::size_t vertexCount() const { return positions.size(); }
    std::size_t triangleCount() const { return indices.size() / 3; }
    bool hasUvs() const { return !uvs.empty(); }
    bool hasColors() const { return !colors.empty(); }
    /** The kept file of texture t, or nullptr. */
    const EncodedImage* textureSource(int t) const {
        return t >= 0 && std::size_t(t) < textureSources.size() &&
                       !textureSources[std::size_t(t)].empty()
                   ? &textureSources[std::size_t(t)]
                   : nullptr;
    }

    Bounds bounds() const;
    /** Area-weighted vertex normals from the triangles (for files without normals). */
    void computeNormals();
    /** Checks internal consistency (sizes, index ranges, finite values); the first problem. */
    Status validate() const;
};

} // namespace core
