// SPDX-License-Identifier: GPL-3.0-or-later
// Loader for everything Assimp reads (OBJ, PLY, STL, OFF, ...).
//
// Before Assimp: OFF and PLY header counts must fit the file (Assimp allocates and loops over
// them first: the corpus's 309-byte OutOfMemory.off cost 16 GB and 20 s), and an OBJ face
// statement without vertices is refused (Assimp drops it silently).
//
// Assimp reads with no post-processing first; checkRawScene() then checks every face index, bone
// weight and morph mesh that the post-processing steps read. That replaces
// aiProcess_ValidateDataStructure, which checks the same but rejects whole files for harmless
// defects (an empty solid in an STL, an empty mesh) and animation data never used here. The
// steps: Triangulate (polygons to triangles; points and lines stay and are skipped with a
// warning) and JoinIdenticalVertices (OBJ/STL importers emit one vertex per face corner; joining
// restores shared vertices, so vertex counts are those of distinct position/normal/UV/color
// tuples per mesh, compared with Assimp's small epsilon). Not used: PreTransformVertices and
// SortByPType (both reorder triangles; node transforms are applied here, nodes depth-first,
// meshes in node order), FindDegenerates (drops triangles and shifts the ids), GenNormals
// (normals are computed area-weighted in loadMesh).
//
// Files: Assimp opens files only inside the model's folder (FolderIOSystem); a reference outside
// it (mtllib ../x.mtl) is not read and becomes a warning. Texture paths are resolved the same
// way, falling back to the bare file name in the model's folder (OBJ files written on Windows
// often carry absolute paths).
//
// Conventions: UVs are flipped to glTF's (origin at the top-left, v down) so that they index
// Image rows top first. Vertex colors are treated as sRGB-encoded display values (as PLY/OBJ
// tools do) and converted to linear. With a diffuse texture, a legacy diffuse color does not
// tint it (OBJ viewers show map_Kd as is); a PBR base color factor does.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <unordered_set>
#include <vector>

#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/ProgressHandler.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "core/base/color.h"
#include "core/io/mesh_io.h"

namespace core::detail {

Result<Mesh> loadAssimp(const std::filesystem::path& file, const ProgressFn& progress,
                        const LoadLimits& limits);

namespace {

namespace fs = std::filesystem;

std::string str(std::uint64_t v) {
    return std::to_string(v);
}

bool isInside(const fs::path& p, const fs::path& folder) {
    const std::string s = p.string(), f = folder.string();
    const std::string prefix = f == "/" ? f : f + "/";
    return s.size() > prefix.size() && s.compare(0, prefix.size(), prefix) == 0;
}

/**
 * A path inside `folder` (after resolving "..", relative paths and symbolic links), or empty.
 * `outside` is set when the path leads outside the folder.
 */
fs::path confine(const fs::path& requested, const fs::path& folder, bool* outside = nullptr) {
    const fs::path abs =
        (requested.is_absolute() ? requested : folder / requested).lexically_normal();
    if (!isInside(abs, folder)) {
        if (outside)
            *outside = true;
        return {};
    }
    std::error_code ec;
    const fs::path real = fs::weakly_canonical(abs, ec);
    if (ec)
        return {};
    if (!isInside(real, folder)) {
        if (outside)
            *outside = true;
        return {};
    }
    return real;
}

/** Assimp's file access, confined to the model's folder and to the size limit. */
class FolderIOSystem : public Assimp::DefaultIOSystem {
public:
    FolderIOSystem(fs::path folder, std::uint64_t maxBytes)
        : m_folder(std::move(folder)), m_maxBytes(maxBytes) {}

    bool Exists(const char* file) const override {
        const fs::path p = allowed(file);
        std::error_code ec;
        return !p.empty() && fs::is_regular_file(p, ec);
    }
    Assimp::IOStream* Open(const char* file, const char* mode) override {
        if (mode == nullptr || std::strchr(mode, 'w') || std::strchr(mode, 'a') ||
            std::strchr(mode, '+'))
            return nullptr; // loading never writes
        const fs::path p = allowed(file);
        std::error_code ec;
        if (p.empty() || !fs::is_regular_file(p, ec))
            return nullptr;
        const std::uintmax_t size = fs::file_size(p, ec);
        if (ec || size > m_maxBytes)
            return nullptr;
        return DefaultIOSystem::Open(p.string().c_str(), mode);
    }
    const std::string& rejected() const { return m_rejected; }

private:
    fs::path allowed(const char* file) const {
        if (file == nullptr || *file == '\0')
            return {};
        bool outside = false;
        fs::path p = confine(fs::path(file), m_folder, &outside);
        if (outside && m_rejected.empty())
            m_rejected = file;
        return p;
    }

    fs::path m_folder;
    std::uint64_t m_maxBytes;
    mutable std::string m_rejected; // the first file outside the folder Assimp asked for
};

/** Maps Assimp's progress to [0, 0.5] and relays cancellation. */
class Progress : public Assimp::ProgressHandler {
public:
    explicit Progress(const ProgressFn& fn) : m_fn(fn) {}
    bool Update(float percentage) override {
        const double f = percentage >= 0.0f ? std::clamp(double(percentage), 0.0, 1.0) : 0.0;
        if (!reportProgress(m_fn, 0.05 + 0.45 * f))
            m_cancelled = true;
        return !m_cancelled;
    }
    bool cancelled() const { return m_cancelled; }

private:
    const ProgressFn& m_fn;
    bool m_cancelled = false;
};

/** p as floats, or false if it does not fit (a double beyond float range is not castable). */
bool toFloat(const glm::dvec3& p, glm::vec3& out) {
    constexpr double kMax = std::numeric_limits<float>::max();
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(p[k]) || std::abs(p[k]) > kMax)
            return false;
    out = glm::vec3(p);
    return true;
}

/** n normalized in double precision; zero (recomputed later) when it has no direction. */
glm::vec3 unitNormal(const glm::dvec3& n) {
    const double len = glm::length(n);
    return std::isfinite(len) && len > 0.0 ? glm::vec3(n / len) : glm::vec3(0.0f);
}

glm::dmat4 toGlm(const aiMatrix4x4& m) {
    // aiMatrix4x4 is row-major (a1..a4 is the first row); glm is column-major.
    return glm::dmat4(m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4,
                      m.b4, m.c4, m.d4);
}

bool readFile(const fs::path& p, std::uint64_t maxBytes, std::vector<std::uint8_t>& out) {
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(p, ec);
    if (ec || size == 0 || size > maxBytes)
        return false;
    std::ifstream in(p, std::ios::binary);
    out.resize(static_cast<std::size_t>(size));
    return in && in.read(reinterpret_cast<char*>(out.data()), static_cast<std::streamsize>(size));
}

/**
 * What the post-processing steps read, checked before they run (see the top of the file). Also
 * sets each mesh's primitive types from its faces: Triangulate asserts (and Debian's Assimp
 * aborts) when an importer declared them wrongly.
 */
std::string checkRawScene(const aiScene& scene, const LoadLimits& limits) {
    if (scene.mNumMeshes > 0 && scene.mMeshes == nullptr)
        return "the file's mesh list is missing";
    // Before JoinIdenticalVertices an importer may hold a vertex per face corner; beyond that
    // the count is a broken or hostile header.
    const std::uint64_t maxRawVertices = limits.maxVertices * 4;
    std::uint64_t rawVertices = 0;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        aiMesh* mesh = scene.mMeshes[m];
        const std::string where = "mesh " + str(m);
        if (mesh == nullptr)
            return where + " is missing";
        const unsigned nv = mesh->mNumVertices;
        rawVertices += nv;
        if (rawVertices > maxRawVertices)
            return "too many vertices (more than " + str(maxRawVertices) + " before merging)";
        if (nv > 0 && mesh->mVertices == nullptr)
            return where + " has no vertex positions";
        if (mesh->mNumFaces > 0 && mesh->mFaces == nullptr)
            return where + " has no face list";
        unsigned types = 0;
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const aiFace& face = mesh->mFaces[f];
            if (face.mNumIndices == 0 || face.mIndices == nullptr)
                return where + " has a face without vertices";
            for (unsigned k = 0; k < face.mNumIndices; ++k)
                if (face.mIndices[k] >= nv)
                    return where + ": vertex index " + str(face.mIndices[k]) +
                           " is out of range (the mesh has " + str(nv) + " vertices)";
            types |= face.mNumIndices == 1   ? aiPrimitiveType_POINT
                     : face.mNumIndices == 2 ? aiPrimitiveType_LINE
                     : face.mNumIndices == 3 ? aiPrimitiveType_TRIANGLE
                                             : aiPrimitiveType_POLYGON;
        }
        mesh->mPrimitiveTypes = types;
        if (mesh->mNumBones > 0 && mesh->mBones == nullptr)
            return where + " has a missing bone list";
        for (unsigned b = 0; b < mesh->mNumBones; ++b) {
            const aiBone* bone = mesh->mBones[b];
            if (bone == nullptr || (bone->mNumWeights > 0 && bone->mWeights == nullptr))
                return where + " has a broken bone";
            for (unsigned w = 0; w < bone->mNumWeights; ++w)
                if (bone->mWeights[w].mVertexId >= nv)
                    return where + " has a bone weight for a vertex that does not exist";
        }
        if (mesh->mNumAnimMeshes > 0 && mesh->mAnimMeshes == nullptr)
            return where + " has a missing morph target list";
        for (unsigned a = 0; a < mesh->mNumAnimMeshes; ++a) {
            const aiAnimMesh* anim = mesh->mAnimMeshes[a];
            if (anim == nullptr || anim->mNumVertices != nv ||
                (nv > 0 && anim->mVertices == nullptr))
                return where + " has a broken morph target";
        }
    }
    return {};
}

/**
 * OBJ syntax Assimp forgives silently: a face statement without vertices. Such a file is
 * malformed (truncated or hand-broken), so it is refused instead of loading with a hole.
 */
std::string checkObjFaces(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::string line, logical;
    std::uint64_t lineNo = 0, startLine = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        if (logical.empty())
            startLine = lineNo;
        if (!line.empty() && line.back() == '\\') { // continued on the next line
            line.pop_back();
            logical += line + " ";
            continue;
        }
        logical += line;
        const std::size_t hash = logical.find('#');
        if (hash != std::string::npos)
            logical.resize(hash);
        const std::size_t b = logical.find_first_not_of(" \t");
        if (b != std::string::npos && logical[b] == 'f' &&
            (b + 1 == logical.size() || logical[b + 1] == ' ' || logical[b + 1] == '\t') &&
            logical.find_first_not_of(" \t", b + 1) == std::string::npos)
            return "line " + str(startLine) + ": a face without vertices";
        logical.clear();
    }
    return {};
}

/** The first bytes of a file (headers are small). */
std::string readHead(const fs::path& file, std::size_t max) {
    std::ifstream in(file, std::ios::binary);
    std::string head(max, '\0');
    in.read(head.data(), static_cast<std::streamsize>(max));
    head.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
    return head;
}

/** A decimal count, or false when absent or absurdly long. */
bool parseCount(const std::string& token, std::uint64_t& out) {
    if (token.empty() || token.size() > 19 ||
        !std::all_of(token.begin(), token.end(), [](unsigned char c) { return std::isdigit(c); }))
        return false;
    out = std::stoull(token);
    return true;
}

std::string tooManyElements(std::uint64_t count, const std::string& what, std::uint64_t size) {
    return "the header declares " + str(count) + " " + what + ", more than the " + str(size) +
           "-byte file can hold";
}

/**
 * Text OFF: every face lists as many vertex indices as its first number says, each a vertex of
 * the file, and the faces the header declares are there. Assimp 5.2 reads on past a short face
 * line, into the next lines and past the end of its buffer (found by fuzzing). Files that are not
 * text OFF, or whose header cannot be read here, are left to Assimp.
 */
std::string checkOffFaces(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::string line;
    std::vector<std::string> tokens;
    enum class Stage { Magic, Counts, Vertices, Faces } stage = Stage::Magic;
    bool dimension = false;
    std::uint64_t vertices = 0, faces = 0, seenVertices = 0, seenFaces = 0, lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (const std::size_t hash = line.find('#'); hash != std::string::npos)
            line.resize(hash);
        tokens.clear();
        std::istringstream words(line);
        for (std::string w; words >> w;)
            tokens.push_back(w);
        if (tokens.empty())
            continue;
        std::size_t t = 0;
        if (stage == Stage::Magic) {
            const std::string& magic = tokens[0];
            if (magic.size() < 3 || magic.size() > 9 ||
                magic.compare(magic.size() - 3, 3, "OFF") != 0 ||
                (tokens.size() > 1 && tokens[1] == "BINARY"))
                return {};
            dimension = magic.find('n') != std::string::npos;
            stage = Stage::Counts;
            t = 1;
            if (t == tokens.size())
                continue;
        }
        if (stage == Stage::Counts) {
            if (dimension) {
                ++t; // nOFF: the dimension comes first
                dimension = false;
                if (t >= tokens.size())
                    continue;
            }
            if (t + 1 >= tokens.size() || !parseCount(tokens[t], vertices) ||
                !parseCount(tokens[t + 1], faces))
                return {};
            stage = vertices > 0 ? Stage::Vertices : Stage::Faces;
            continue;
        }
        if (stage == Stage::Vertices) {
            if (++seenVertices == vertices)
                stage = Stage::Faces;
            continue;
        }
        if (seenFaces == faces)
            break;
        ++seenFaces;
        std::uint64_t corners = 0;
        if (!parseCount(tokens[0], corners))
            return "line " + str(lineNo) + ": an OFF face must start with its number of vertices";
        if (tokens.size() < corners + 1)
            return "line " + str(lineNo) + ": the face lists " + str(tokens.size() - 1) +
                   " vertex indices but says it has " + str(corners);
        for (std::size_t k = 1; k <= corners; ++k) {
            std::uint64_t index = 0;
            if (!parseCount(tokens[k], index) || index >= vertices)
                return "line " + str(lineNo) + ": the face uses vertex \"" + tokens[k] +
                       "\", which is not one of the file's " + str(vertices) + " vertices";
        }
    }
    if (stage == Stage::Faces && seenFaces < faces)
        return "the OFF file ends after " + str(seenFaces) + " of the " + str(faces) +
               " faces its header declares";
    return {};
}

/**
 * OFF and PLY headers declare element counts that Assimp allocates and loops over before it
 * notices the data is missing: a 300-byte file can cost gigabytes and minutes. The counts must
 * fit the file: an ASCII value takes at least 2 bytes ("0 "), a binary one its size.
 */
std::string checkDeclaredCounts(const fs::path& file, std::uint64_t fileSize,
                                const LoadLimits& limits) {
    const std::string head = readHead(file, 65536);
    std::vector<std::string> tokens; // whitespace-separated, '#' comments dropped
    {
        std::string token;
        bool comment = false;
        for (char c : head) {
            if (c == '\n' || c == '\r')
                comment = false;
            if (comment)
                continue;
            if (c == '#') {
                comment = true;
            } else if (std::isspace(static_cast<unsigned char>(c))) {
                if (!token.empty())
                    tokens.push_back(std::move(token));
                token.clear();
            } else {
                token += c;
            }
            if (tokens.size() > 4096)
                break;
        }
        if (!token.empty())
            tokens.push_back(token);
    }
    if (tokens.empty())
        return {};
    const std::uint64_t maxRaw = limits.maxVertices * 4;

    // OFF: [ST][C][N][4][n]OFF, then (for nOFF) a dimension, then vertex, face, edge counts.
    const std::string& magic = tokens[0];
    if (magic.size() >= 3 && magic.size() <= 9 && magic.compare(magic.size() - 3, 3, "OFF") == 0) {
        std::size_t t = 1;
        if (t < tokens.size() && tokens[t] == "BINARY")
            return {}; // Assimp refuses binary OFF itself
        if (magic.find('n') != std::string::npos)
            ++t;
        std::uint64_t vertices = 0, faces = 0;
        if (t + 1 >= tokens.size() || !parseCount(tokens[t], vertices) ||
            !parseCount(tokens[t + 1], faces))
            return {};
        if (vertices > maxRaw)
            return "too many vertices (the header declares " + str(vertices) + ")";
        // "0 0 0\n" is the shortest vertex line, "0\n" the shortest face line.
        if (vertices > fileSize / 6)
            return tooManyElements(vertices, "vertices", fileSize);
        if (faces > fileSize / 2)
            return tooManyElements(faces, "faces", fileSize);
        return {};
    }

    // PLY: sum over elements of count * the smallest size one element can have. The header is
    // read line by line and must be well formed: Assimp 5.2 hangs or reads wild on unknown
    // keywords, counts like "0.0" and headers without end_header (found by fuzzing). Assimp
    // takes any file that starts with the three letters for PLY ("ply," too).
    if (magic.rfind("ply", 0) != 0)
        return {};
    bool ascii = true;
    struct Element {
        std::string name;
        std::uint64_t count = 0;
        std::uint64_t minBytes = 0;
    };
    std::vector<Element> elements;
    auto typeSize = [](const std::string& t) -> std::uint64_t {
        if (t == "char" || t == "uchar" || t == "int8" || t == "uint8")
            return 1;
        if (t == "short" || t == "ushort" || t == "int16" || t == "uint16")
            return 2;
        if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" ||
            t == "float32")
            return 4;
        if (t == "double" || t == "float64")
            return 8;
        return 0; // not a PLY type
    };
    std::uint64_t bodyStart = 0;
    bool ended = false;
    std::size_t lineStart = 0;
    for (int lineNo = 1; lineStart < head.size() && !ended; ++lineNo) {
        std::size_t lineEnd = head.find('\n', lineStart);
        if (lineEnd == std::string::npos)
            break; // the header runs past what was read, or the file ends in it
        std::istringstream words(head.substr(lineStart, lineEnd - lineStart));
        lineStart = lineEnd + 1;
        std::vector<std::string> w;
        for (std::string word; words >> word;)
            w.push_back(word);
        const std::string where = "line " + str(std::uint64_t(lineNo)) + " of the PLY header: ";
        if (w.empty() || w[0] == "comment" || w[0] == "obj_info" ||
            (lineNo == 1 && w[0].rfind("ply", 0) == 0))
            continue;
        if (w[0] == "format" && w.size() == 3) {
            ascii = w[1] == "ascii";
        } else if (w[0] == "element" && w.size() == 3) {
            Element e;
            e.name = w[1];
            if (!parseCount(w[2], e.count))
                return where + "the element \"" + e.name +
                       "\" has a count that is not a whole number (\"" + w[2] + "\")";
            elements.push_back(e);
        } else if (w[0] == "property" && !elements.empty() &&
                   ((w.size() == 3 && typeSize(w[1]) > 0) ||
                    (w.size() == 5 && w[1] == "list" && typeSize(w[2]) > 0 &&
                     typeSize(w[3]) > 0))) {
            // A list costs at least its (zero) count; a scalar its size.
            elements.back().minBytes += ascii ? 2 : typeSize(w.size() == 5 ? w[2] : w[1]);
        } else if (w[0] == "end_header" && w.size() == 1) {
            ended = true;
            bodyStart = lineStart;
        } else if (w[0] == "format" || w[0] == "element" || w[0] == "property" ||
                   w[0] == "end_header") {
            return where + "\"" + w[0] + "\" is not followed by what it needs";
        }
        // Other lines are skipped, as Assimp does (exporters write free text there).
    }
    if (!ended)
        return "the PLY header does not end (no end_header line in its first " + str(head.size()) +
               " bytes)"; // Assimp would read on and hang
    const std::uint64_t body = fileSize > bodyStart ? fileSize - bodyStart : 0;
    for (const Element& e : elements)
        if (e.count > 0 && e.minBytes == 0) // Assimp would loop over them without moving on
            return "the PLY header declares " + str(e.count) + " \"" + e.name +
                   "\" elements without properties";
    std::uint64_t needed = 0;
    for (const Element& e : elements) {
        if (e.name == "vertex" && e.count > maxRaw)
            return "too many vertices (the header declares " + str(e.count) + ")";
        std::uint64_t bytes = 0;
        if (__builtin_mul_overflow(e.count, std::max<std::uint64_t>(e.minBytes, 1), &bytes) ||
            __builtin_add_overflow(needed, bytes, &needed) || needed > body)
            return tooManyElements(e.count, "\"" + e.name + "\" elements", fileSize);
    }
    return {};
}

class AssimpFlattener {
public:
    AssimpFlattener(const aiScene& scene, fs::path folder, const LoadLimits& limits)
        : m_scene(scene), m_folder(std::move(folder)), m_limits(limits) {}

    bool run(Mesh& out);
    const Error& error() const { return m_error; }

private:
    const aiScene& m_scene;
    fs::path m_folder;
    const LoadLimits& m_limits;
    Error m_error;
    Mesh m_mesh;
    std::set<std::string> m_warned;
    bool m_anyNormals = false, m_anyUv = false, m_anyColor = false;
    std::vector<char> m_hasNormal;
    std::size_t m_skippedFaces = 0;
    std::map<std::string, int> m_textureCache;

    bool fail(std::string msg, ErrorKind kind = ErrorKind::BadInput) {
        if (m_error.message.empty())
            m_error = Error{std::move(msg), kind};
        return false;
    }
    void warnOnce(const std::string& msg) {
        if (m_warned.insert(msg).second)
            m_mesh.warnings.push_back(msg);
    }
    bool addMesh(unsigned meshIndex, const glm::dmat4& transform);
    void addMaterials();
    int loadTexture(const std::string& path);
};

bool AssimpFlattener::addMesh(unsigned meshIndex, const glm::dmat4& transform) {
    if (meshIndex >= m_scene.mNumMeshes || m_scene.mMeshes == nullptr ||
        m_scene.mMeshes[meshIndex] == nullptr)
        return fail("a node uses mesh " + str(meshIndex) + ", which does not exist");
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
                return fail("mesh " + str(meshIndex) + ": vertex index " + str(face.mIndices[k]) +
                            " is out of range (the mesh has " + str(vertexCount) + " vertices)");
            tris.push_back(face.mIndices[k]);
        }
    }
    if (tris.empty())
        return true;

    std::vector<std::uint32_t> remap(vertexCount, std::numeric_limits<std::uint32_t>::max());
    for (std::uint32_t v : tris)
        remap[v] = 0;
    std::uint64_t used = 0;
    for (std::uint32_t& r : remap)
        if (r == 0)
            r = static_cast<std::uint32_t>(used++);
    if (m_mesh.positions.size() + used > m_limits.maxVertices)
        return fail("too many vertices (more than " + str(m_limits.maxVertices) + ")");
    if (m_mesh.triangleCount() + tris.size() / 3 > m_limits.maxTriangles)
        return fail("too many triangles (more than " + str(m_limits.maxTriangles) + ")");

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
            return fail("mesh " + str(meshIndex) + ": a vertex position is not a finite number");
        glm::vec3 tp;
        if (!toFloat(glm::dvec3(transform * glm::dvec4(p.x, p.y, p.z, 1.0)), tp))
            return fail("mesh " + str(meshIndex) +
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
    m_anyNormals = m_anyNormals || hasNormals;
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
                    result = static_cast<int>(m_mesh.textures.size());
                    m_mesh.textures.push_back(std::move(img).value());
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
                result = static_cast<int>(m_mesh.textures.size());
                m_mesh.textures.push_back(std::move(img));
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
                result = static_cast<int>(m_mesh.textures.size());
                m_mesh.textures.push_back(std::move(img).value());
            } else {
                m_mesh.warnings.push_back(img.error() + "; the material has no texture");
            }
        }
    }
    m_textureCache[path] = result;
    return result;
}

void AssimpFlattener::addMaterials() {
    for (unsigned i = 0; i < m_scene.mNumMaterials; ++i) {
        const aiMaterial* am = m_scene.mMaterials ? m_scene.mMaterials[i] : nullptr;
        Material mat;
        if (am == nullptr) {
            mat.name = "material " + str(i);
            m_mesh.materials.push_back(mat);
            continue;
        }
        aiString name;
        mat.name = am->Get(AI_MATKEY_NAME, name) == AI_SUCCESS && name.length > 0
                       ? std::string(name.C_Str())
                       : "material " + str(i);
        aiColor4D color(1.0f, 1.0f, 1.0f, 1.0f);
        const bool pbrColor = am->Get(AI_MATKEY_BASE_COLOR, color) == AI_SUCCESS;
        bool diffuseColor = false;
        if (!pbrColor)
            diffuseColor = am->Get(AI_MATKEY_COLOR_DIFFUSE, color) == AI_SUCCESS;
        float opacity = 1.0f;
        if (am->Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS && std::isfinite(opacity))
            color.a = std::clamp(opacity, 0.0f, 1.0f) * (pbrColor ? color.a : 1.0f);
        // Assimp invents "DefaultMaterial" (grey) for files without one: use glTF's white.
        if (mat.name == AI_DEFAULT_MATERIAL_NAME)
            color = aiColor4D(1.0f, 1.0f, 1.0f, 1.0f);
        mat.baseColorFactor = glm::vec4(color.r, color.g, color.b, color.a);

        for (aiTextureType type : {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE}) {
            if (am->GetTextureCount(type) == 0)
                continue;
            aiString texPath;
            unsigned uvIndex = 0;
            if (am->GetTexture(type, 0, &texPath, nullptr, &uvIndex) != AI_SUCCESS)
                continue;
            if (uvIndex != 0) {
                warnOnce("textures on texture coordinate sets other than 0 are ignored");
                break;
            }
            mat.baseColorTexture = loadTexture(texPath.C_Str());
            if (mat.baseColorTexture >= 0 && diffuseColor)
                mat.baseColorFactor = glm::vec4(1.0f, 1.0f, 1.0f, mat.baseColorFactor.a);
            break;
        }
        for (int k = 0; k < 4; ++k)
            if (!std::isfinite(mat.baseColorFactor[k]))
                mat.baseColorFactor[k] = 1.0f;
        m_mesh.materials.push_back(std::move(mat));
    }
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
        for (unsigned m = 0; m < item.node->mNumMeshes; ++m)
            if (item.node->mMeshes == nullptr || !addMesh(item.node->mMeshes[m], global))
                return fail("a node has an invalid mesh list");
        for (unsigned c = item.node->mNumChildren; c-- > 0;)
            if (item.node->mChildren != nullptr)
                stack.push_back(Item{item.node->mChildren[c], global});
    }
    if (m_skippedFaces > 0)
        m_mesh.warnings.push_back(m_skippedFaces == 1
                                      ? std::string("1 point or line face was skipped")
                                      : str(m_skippedFaces) + " point and line faces were skipped");
    if (m_mesh.indices.empty())
        return fail("the file contains no triangles");

    addMaterials();
    // Meshes without a valid material use a default one after the file's materials.
    const auto defaultIndex = static_cast<std::uint32_t>(m_mesh.materials.size());
    if (std::find(m_mesh.triangleMaterial.begin(), m_mesh.triangleMaterial.end(), defaultIndex) !=
            m_mesh.triangleMaterial.end() ||
        m_mesh.materials.empty())
        m_mesh.materials.push_back(Material{"default", glm::vec4(1.0f), -1});

    if (!m_anyUv)
        m_mesh.uvs.clear();
    if (!m_anyColor)
        m_mesh.colors.clear();
    if (!m_anyNormals) {
        m_mesh.normals.clear(); // loadMesh computes them all
    } else if (std::find(m_hasNormal.begin(), m_hasNormal.end(), 0) != m_hasNormal.end()) {
        Mesh computed;
        computed.positions = m_mesh.positions;
        computed.indices = m_mesh.indices;
        computed.computeNormals();
        for (std::size_t i = 0; i < m_hasNormal.size(); ++i)
            if (!m_hasNormal[i])
                m_mesh.normals[i] = computed.normals[i];
    }
    out = std::move(m_mesh);
    return true;
}

std::string oneLine(std::string s) {
    for (char& c : s)
        if (c == '\n' || c == '\r')
            c = ' ';
    while (!s.empty() && s.back() == ' ')
        s.pop_back();
    return s;
}

/** The format a file's extension (lower case, with the dot) stands for, with its article. */
std::string formatName(const std::string& ext) {
    if (ext == ".obj")
        return "a Wavefront OBJ";
    if (ext == ".ply")
        return "a Stanford PLY";
    if (ext == ".stl")
        return "an STL";
    if (ext == ".off")
        return "an OFF";
    std::string name = ext.empty() ? ext : ext.substr(1);
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return "a " + name;
}

/**
 * What Assimp said about a file it could not read, in the user's words: its common messages
 * mapped, anything else kept as detail without the file's path or bytes that cannot be shown.
 */
std::string readError(const fs::path& file, const std::string& ext, std::string assimp) {
    const std::string format = formatName(ext);
    const auto says = [&](const char* text) { return assimp.find(text) != std::string::npos; };
    if (assimp.empty())
        return "could not be read as " + format + " model";
    if (says("No suitable reader found"))
        return "is not in a 3D model format LayerPaint can read";
    if (says("too small") || says("Unexpected end of file") || says("unexpected end"))
        return "is too short to be " + format + " model; it may be cut off or another kind of file";
    if (says("magic number") || says("Magic number") || says("storage representation") ||
        says("not a valid") || says("no data loaded"))
        return "is not " + format + " model; it may be damaged or another kind of file";
    // Otherwise Assimp's own words as the detail, without the path (the message names it).
    for (const std::string& path : {file.string(), file.filename().string()})
        for (std::size_t p; !path.empty() && (p = assimp.find(path)) != std::string::npos;)
            assimp.replace(p, path.size(), "the file");
    for (char& c : assimp)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F)
            c = '?';
    return "could not be read as " + format + " model (" + assimp + ")";
}

Result<Mesh> load(const fs::path& file, const ProgressFn& progress, const LoadLimits& limits) {
    const fs::path folder = file.parent_path();
    Assimp::Importer importer;
    // The importer owns and deletes both.
    auto* io = new FolderIOSystem(folder, limits.maxFileBytes);
    importer.SetIOHandler(io);
    auto* handler = new Progress(progress);
    importer.SetProgressHandler(handler);
    // Keep loaders from building skeleton-only placeholder meshes.
    importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);

    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".obj")
        if (std::string problem = checkObjFaces(file); !problem.empty())
            return Error{problem};
    std::error_code ec;
    const std::uintmax_t fileSize = fs::file_size(file, ec);
    if (ec)
        return Error{"cannot be read (" + ec.message() + ")"};
    if (std::string problem = checkDeclaredCounts(file, fileSize, limits); !problem.empty())
        return Error{problem};
    if (ext == ".off")
        if (std::string problem = checkOffFaces(file); !problem.empty())
            return Error{problem};

    const aiScene* raw = importer.ReadFile(file.string(), 0);
    if (handler->cancelled())
        return cancelledError();
    if (raw == nullptr)
        return Error{readError(file, ext, oneLine(importer.GetErrorString()))};
    // The importer owns the scene and post-processing changes it anyway.
    if (std::string problem = checkRawScene(*const_cast<aiScene*>(raw), limits); !problem.empty())
        return Error{problem};
    const aiScene* scene =
        importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
    if (handler->cancelled())
        return cancelledError();
    if (scene == nullptr)
        return Error{readError(file, ext, oneLine(importer.GetErrorString()))};
    Mesh mesh;
    AssimpFlattener flattener(*scene, folder, limits);
    if (!flattener.run(mesh))
        return flattener.error();
    if (!io->rejected().empty())
        mesh.warnings.push_back("a reference to a file outside the model's folder was ignored: " +
                                io->rejected());
    if (!reportProgress(progress, 0.9))
        return cancelledError();
    return mesh;
}

} // namespace

Result<Mesh> loadAssimp(const std::filesystem::path& file, const ProgressFn& progress,
                        const LoadLimits& limits) {
    try {
        return load(file, progress, limits);
    } catch (const std::bad_alloc&) {
        return Error{"not enough memory to load the file"};
    } catch (const std::exception& e) {
        return Error{std::string("cannot be loaded (") + e.what() + ")"};
    } catch (...) {
        return Error{"cannot be loaded (unexpected error)"};
    }
}

} // namespace core::detail
