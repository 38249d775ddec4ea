// SPDX-License-Identifier: GPL-3.0-or-later
// The importer process behind loadMesh() and loadImageFile(): the regression corpus replayed
// through the public loader, what a crashing, hanging, lying or cancelled importer gives (stand-in
// importers are shell scripts named by LAYERPAINT_IMPORTER), what the sandbox allows, and that a
// file gives the same result through the importer as in process.
#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/io/importer/import_protocol.h"
#include "core/io/importer/mesh_io_in_process.h"
#include "core/io/mesh_io.h"
#include "tests/core/test_files.h"

namespace importer_test {

namespace fs = std::filesystem;
using core_test::readFile;
using core_test::TempDir;
using core_test::writeFile;

const fs::path kCrashers = fs::path(LAYERPAINT_TEST_DATA) / "crashers";
const fs::path kModels = LAYERPAINT_ASSIMP_MODELS;
const std::string kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

/** Sets LAYERPAINT_IMPORTER while it lives (ctest sets it to the real importer). */
class ImporterOverride {
public:
    explicit ImporterOverride(const std::string& program) {
        if (const char* old = std::getenv("LAYERPAINT_IMPORTER"))
            m_old = old;
        ::setenv("LAYERPAINT_IMPORTER", program.c_str(), 1);
    }
    ~ImporterOverride() {
        if (m_old)
            ::setenv("LAYERPAINT_IMPORTER", m_old->c_str(), 1);
        else
            ::unsetenv("LAYERPAINT_IMPORTER");
    }

private:
    std::optional<std::string> m_old;
};

/** An executable /bin/sh script in dir standing in for the importer. */
std::string script(const TempDir& dir, const std::string& name, const std::string& body) {
    const std::string path = dir.file(name);
    writeFile(path, "#!/bin/sh\n" + body);
    ::chmod(path.c_str(), 0755);
    return path;
}

/** printf(1) octal escapes for bytes. */
std::string octal(const std::string& bytes) {
    std::string out;
    char buffer[8];
    for (unsigned char c : bytes) {
        std::snprintf(buffer, sizeof buffer, "\\%03o", c);
        out += buffer;
    }
    return out;
}

/** A frame header as the importer writes it. */
std::string header(core::importer::Tag tag, std::uint64_t length) {
    const core::importer::FrameHeader h{core::importer::kMagic, static_cast<std::uint32_t>(tag),
                                        length};
    return std::string(reinterpret_cast<const char*>(&h), sizeof h);
}

/** The frames the importer would send for mesh, written to path. */
void writeFrames(const std::string& path, const core::Mesh& mesh, const std::string& tail = {}) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    ASSERT_GE(fd, 0);
    core::importer::FrameWriter writer(fd);
    EXPECT_TRUE(writer.mesh(mesh));
    if (!tail.empty()) {
        EXPECT_EQ(::write(fd, tail.data(), tail.size()), ssize_t(tail.size()));
    }
    ::close(fd);
}

core::Mesh triangle() {
    core::Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    mesh.indices = {0, 1, 2};
    mesh.triangleMaterial = {0};
    mesh.materials = {core::Material{"red", glm::vec4(1, 0, 0, 1), -1}};
    return mesh;
}

/** Whether process pid is gone (killed and reaped, not a zombie). */
bool gone(const std::string& pidFile) {
    const std::string text = readFile(pidFile);
    const int pid = std::atoi(text.c_str());
    return pid > 0 && ::kill(pid, 0) != 0 && errno == ESRCH;
}

// ---------------------------------------------------------------------------------------------
// The regression corpus: every input that ever crashed or hung a loader.

std::vector<std::string> corpusFiles() {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(kCrashers))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

class CrasherCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(CrasherCorpus, GivesAnErrorNamingTheFileNeverACrash) {
    const std::string path = (kCrashers / GetParam()).string();
    const core::Result<core::Mesh> mesh = core::loadMesh(path);
    if (mesh.ok()) {
        EXPECT_TRUE(mesh->validate().ok()); // a valid model is fine too
        return;
    }
    EXPECT_EQ(mesh.error().rfind(path + ": ", 0), 0u) << mesh.error();
    EXPECT_EQ(mesh.error().find('\n'), std::string::npos) << mesh.error();
    std::printf("[ corpus   ] %s\n", mesh.error().c_str());
}

INSTANTIATE_TEST_SUITE_P(Files, CrasherCorpus, ::testing::ValuesIn(corpusFiles()),
                         [](const auto& row) {
                             std::string name = row.param;
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c)))
                                     c = '_';
                             return name;
                         });

// ---------------------------------------------------------------------------------------------
// The importer's processor time follows what the load reads (import_budget.h).

TEST(ImportBudget, ASmallFileGetsAFewSeconds) {
    TempDir dir;
    const std::string model = dir.file("small.obj");
    writeFile(model, kTriangleObj);
    const double seconds = core::detail::importSeconds(model, {});
    EXPECT_GE(seconds, core::detail::kImportBaseSeconds);
    EXPECT_LT(seconds, core::detail::kImportBaseSeconds + 0.01);
    EXPECT_DOUBLE_EQ(core::detail::importWallSeconds(seconds), 3.0 * seconds + 10.0);
    core::LoadLimits given;
    given.maxSeconds = 7.0;
    EXPECT_EQ(core::detail::importSeconds(model, given), 7.0);
}

TEST(ImportBudget, AnObjCountsItsMtlAndTheMapsFoundInTheModelsFolder) {
    TempDir dir;
    const std::string model = dir.file("model/m.obj");
    const std::string obj = "mtllib m.mtl\n" + kTriangleObj;
    const std::string mtl = "newmtl a\nmap_Kd -bm 1 tex.png\nbump missing.png\n"
                            "map_Ks ../outside.png\nnorm tex.png\n";
    writeFile(model, obj);
    writeFile(dir.file("model/m.mtl"), mtl);
    writeFile(dir.file("model/tex.png"), std::string(1 << 20, 'x'));
    writeFile(dir.file("outside.png"), std::string(1 << 20, 'x')); // outside: not read
    const core::detail::ImportInput input = core::detail::estimateImportInput(model);
    EXPECT_EQ(input.bytes, obj.size() + mtl.size() + (1u << 20));
    EXPECT_EQ(input.images, 1u); // tex.png once
    EXPECT_DOUBLE_EQ(core::detail::importSeconds(model, {}),
                     core::detail::kImportBaseSeconds +
                         core::detail::kImportSecondsPerMiB * double(input.bytes) / (1 << 20) +
                         core::detail::kImportSecondsPerImage);
}

TEST(ImportBudget, AGltfCountsItsBuffersAndImages) {
    TempDir dir;
    const std::string model = dir.file("a b.gltf");
    const std::string gltf =
        R"({"buffers":[{"uri":"mesh%20data.bin","byteLength":4},{"uri":"data:application/)"
        R"(octet-stream;base64,AAAA"}],"images":[{"uri" : "tex\/base.png"},)"
        R"({"uri":"data:image/png;base64,AAAA"},{"bufferView":0,"mimeType":"image/png"},)"
        R"({"uri":"/etc/passwd"}]})";
    writeFile(model, gltf);
    writeFile(dir.file("mesh data.bin"), std::string(3000, 'b'));
    writeFile(dir.file("tex/base.png"), std::string(500, 'p'));
    const core::detail::ImportInput input = core::detail::estimateImportInput(model);
    EXPECT_EQ(input.bytes, gltf.size() + 3000 + 500);
    EXPECT_EQ(input.images, 3u); // the file, the data: image and the one in a buffer view
    EXPECT_EQ(core::detail::estimateImportInput(model, core::detail::ImportKind::Image).images, 1u);
}

TEST(Importer, AFileOnWhichAssimpSpinsIsStoppedByItsProcessorTimeInSeconds) {
    // The first 242 bytes of the corpus's second hanging PLY keep Assimp (5.2.5) busy for ever
    // just as the whole file does.
    TempDir dir;
    const std::string model = dir.file("hang.ply");
    writeFile(model, readFile(kCrashers / "ply-assimp-hang-2.ply").substr(0, 242));
    EXPECT_LT(core::detail::importSeconds(model, {}), 2.01);
    const core::Result<core::Mesh> mesh = core::loadMesh(model);
    ASSERT_FALSE(mesh.ok());
    EXPECT_EQ(mesh.error(),
              model + ": the importer stopped: it used more than 2 seconds of processor time");
}

TEST(Importer, TheOffFileThatCrashesAssimpStopsTheImporterNotTheCaller) {
    const std::string path = (kCrashers / "off-assimp-segv.off").string();
    ASSERT_EQ(fs::file_size(path), 98u);
    const core::Result<core::Mesh> mesh = core::loadMesh(path);
    ASSERT_FALSE(mesh.ok());
    EXPECT_EQ(mesh.error().rfind(path + ": the importer stopped: ", 0), 0u) << mesh.error();
}

// ---------------------------------------------------------------------------------------------
// Importers that misbehave

struct Misbehaviour {
    std::string name;
    std::string body;     // the script after #!/bin/sh
    std::string expected; // the message after "FILE: "
};

void PrintTo(const Misbehaviour& m, std::ostream* os) {
    *os << m.name;
}

std::vector<Misbehaviour> misbehaviours() {
    using core::importer::Tag;
    return {
        {"segv", "kill -SEGV $$\n", "the importer stopped: it crashed (segmentation fault)"},
        {"bus", "kill -BUS $$\n", "the importer stopped: it crashed (bus error)"},
        {"abort", "kill -ABRT $$\n", "the importer stopped: it aborted"},
        {"cpu", "kill -XCPU $$\n",
         "the importer stopped: it used more than 2 seconds of processor time"},
        {"status", "exit 3\n", "the importer stopped: it exited with status 3"},
        {"silent", "exit 0\n",
         "the importer stopped: its output ended before the answer was complete"},
        {"garbage", "printf 'Segmentation fault (core dumped)'\n",
         "the importer stopped: it wrote something that is not a frame"},
        {"huge", "printf '" + octal(header(Tag::Positions, 1ull << 62)) + "'\n",
         "the importer stopped: it sent more data than the limits allow"},
        {"truncated",
         "printf '" +
             octal(header(Tag::MeshBegin, sizeof(core::importer::MeshHeader)) + "0123456789") +
             "'\n",
         "the importer stopped: its output ended before the answer was complete"},
        {"unknown-frame", "printf '" + octal(header(static_cast<Tag>(99), 0)) + "'\n",
         "the importer stopped: it sent a frame of an unknown kind"},
        {"array-first", "printf '" + octal(header(Tag::Positions, 0)) + "'\n",
         "the importer stopped: it sent an array outside a mesh"},
        {"own-error", "printf '" + octal(header(Tag::Error, 17) + "cannot read\nthis.") + "'\n",
         "cannot read this"},
    };
}

class MisbehavingImporter : public ::testing::TestWithParam<Misbehaviour> {};

TEST_P(MisbehavingImporter, GivesOneErrorNamingTheFile) {
    TempDir dir;
    const std::string model = dir.file("model.obj");
    writeFile(model, kTriangleObj);
    ImporterOverride importer(script(dir, "importer", GetParam().body));
    const core::Result<core::Mesh> mesh = core::loadMesh(model);
    ASSERT_FALSE(mesh.ok());
    EXPECT_EQ(mesh.error(), model + ": " + GetParam().expected);
}

INSTANTIATE_TEST_SUITE_P(All, MisbehavingImporter, ::testing::ValuesIn(misbehaviours()),
                         [](const auto& row) {
                             std::string name = row.param.name;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

TEST(Importer, AFakeImportersFramesLoad) {
    // The stand-in works: the frames of a real mesh, sent by a script, give that mesh.
    TempDir dir;
    const std::string model = dir.file("model.obj");
    writeFile(model, kTriangleObj);
    writeFrames(dir.file("frames"), triangle());
    ImporterOverride importer(script(dir, "importer", "exec cat '" + dir.file("frames") + "'\n"));
    const core::Result<core::Mesh> mesh = core::loadMesh(model);
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    EXPECT_EQ(mesh->positions, triangle().positions);
    EXPECT_EQ(mesh->materials[0].name, "red");
}

/** Reads frames from a descriptor, as the application reads the importer's output. */
class DescriptorSource final : public core::importer::FrameSource {
public:
    explicit DescriptorSource(int fd) : m_fd(fd) {}
    bool read(void* data, std::size_t size) override {
        auto* p = static_cast<char*>(data);
        while (size > 0) {
            const ssize_t n = ::read(m_fd, p, size);
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0)
                return false;
            p += n;
            size -= std::size_t(n);
        }
        return true;
    }

private:
    int m_fd;
};

/** A mesh whose arrays are large enough to be lent to a pipe (64 KiB and more). */
core::Mesh largeMesh() {
    core::Mesh mesh = triangle();
    for (int k = 0; k < 20000; ++k) {
        const float x = float(k);
        mesh.positions.push_back({x, 0.5f * x, 0.25f});
        mesh.normals.push_back({0, 0, 1});
    }
    for (std::uint32_t t = 0; t + 2 < std::uint32_t(mesh.positions.size()); t += 3) {
        mesh.indices.insert(mesh.indices.end(), {t, t + 1, t + 2});
        mesh.triangleMaterial.push_back(0);
    }
    return mesh;
}

TEST(Importer, LentFramesArriveWholeThroughAPipeAndAreWrittenToAFile) {
    const core::Mesh mesh = largeMesh();
    ASSERT_GE(mesh.positions.size() * sizeof(glm::vec3), std::size_t(64) << 10);

    // Through a pipe (the importer's standard output): lent, read while written.
    int fds[2];
    ASSERT_EQ(::pipe2(fds, O_CLOEXEC), 0);
    core::importer::FrameWriter piped(fds[1]);
    piped.lendUntilExit();
    bool pipedOk = false;
    std::thread writer([&] {
        pipedOk = piped.mesh(mesh);
        ::close(fds[1]);
    });
    DescriptorSource fromPipe(fds[0]);
    const core::importer::Received viaPipe = core::importer::readFrames(fromPipe, {}, {});
    writer.join();
    ::close(fds[0]);
    EXPECT_TRUE(pipedOk);
    EXPECT_TRUE(piped.lending()); // the pipe took the pages by reference
    ASSERT_TRUE(viaPipe.mesh.has_value()) << viaPipe.malformed;
    EXPECT_EQ(viaPipe.mesh->positions, mesh.positions);
    EXPECT_EQ(viaPipe.mesh->normals, mesh.normals);
    EXPECT_EQ(viaPipe.mesh->indices, mesh.indices);
    EXPECT_EQ(viaPipe.mesh->triangleMaterial, mesh.triangleMaterial);

    // To a file, which cannot take pages: written as before.
    TempDir dir;
    const int fd = ::open(dir.file("frames").c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    ASSERT_GE(fd, 0);
    core::importer::FrameWriter filed(fd);
    filed.lendUntilExit();
    EXPECT_TRUE(filed.mesh(mesh));
    EXPECT_FALSE(filed.lending());
    ASSERT_EQ(::lseek(fd, 0, SEEK_SET), 0);
    DescriptorSource fromFile(fd);
    const core::importer::Received viaFile = core::importer::readFrames(fromFile, {}, {});
    ::close(fd);
    ASSERT_TRUE(viaFile.mesh.has_value()) << viaFile.malformed;
    EXPECT_EQ(viaFile.mesh->positions, mesh.positions);
    EXPECT_EQ(viaFile.mesh->indices, mesh.indices);
}

TEST(Importer, ItsOutputIsCheckedAsAFilesMeshIs) {
    TempDir dir;
    const std::string model = dir.file("model.obj");
    writeFile(model, kTriangleObj);

    core::Mesh outOfRange = triangle();
    outOfRange.indices = {0, 1, 7};
    writeFrames(dir.file("out-of-range"), outOfRange);
    core::Mesh notFinite = triangle();
    notFinite.positions[1].x = std::numeric_limits<float>::infinity();
    writeFrames(dir.file("not-finite"), notFinite);
    core::Mesh badMaterial = triangle();
    badMaterial.triangleMaterial = {4};
    writeFrames(dir.file("bad-material"), badMaterial);

    for (const auto& [frames, problem] : std::vector<std::pair<std::string, std::string>>{
             {"out-of-range", "a vertex index is out of range"},
             {"not-finite", "a vertex position is not a finite number"},
             {"bad-material", "a material index is out of range"}}) {
        ImporterOverride importer(
            script(dir, "importer-" + frames, "exec cat '" + dir.file(frames) + "'\n"));
        const core::Result<core::Mesh> mesh = core::loadMesh(model);
        ASSERT_FALSE(mesh.ok()) << frames;
        EXPECT_EQ(mesh.error(), model + ": " + problem);
    }

    // A complete answer followed by more output is refused too.
    writeFrames(dir.file("more"), triangle(), "and more");
    ImporterOverride importer(
        script(dir, "importer-more", "exec cat '" + dir.file("more") + "'\n"));
    const core::Result<core::Mesh> mesh = core::loadMesh(model);
    ASSERT_FALSE(mesh.ok());
    EXPECT_EQ(mesh.error(), model + ": the importer stopped: it sent more after its answer");
}

TEST(Importer, NamedObjectsArriveAndObjectsOutOfOrderAreRefused) {
    TempDir dir;
    const std::string model = dir.file("model.obj");
    writeFile(model, kTriangleObj);
    core::Mesh named = triangle();
    named.objects = {{"Körper", 0}};
    writeFrames(dir.file("named"), named);
    core::Mesh unordered = triangle();
    unordered.objects = {{"a", 0}, {"b", 0}};
    writeFrames(dir.file("unordered"), unordered);

    ImporterOverride good(script(dir, "importer-named", "exec cat '" + dir.file("named") + "'\n"));
    const core::Result<core::Mesh> mesh = core::loadMesh(model);
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    ASSERT_EQ(mesh->objects.size(), 1u);
    EXPECT_EQ(mesh->objects[0].name, "Körper");

    ImporterOverride bad(
        script(dir, "importer-unordered", "exec cat '" + dir.file("unordered") + "'\n"));
    const core::Result<core::Mesh> refused = core::loadMesh(model);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error(), model + ": the importer stopped: it sent malformed objects");
}

TEST(Importer, AHangingImporterIsKilledAtTheDeadline) {
    TempDir dir;
    const std::string model = dir.file("model.obj");
    writeFile(model, kTriangleObj);
    ImporterOverride importer(
        script(dir, "importer", "echo $$ > '" + dir.file("pid") + "'\nexec sleep 600\n"));
    core::LoadLimits limits;
    limits.maxSeconds = 1.0;
    const core::Result<core::Mesh> mesh = core::loadMesh(model, {}, limits);
    ASSERT_FALSE(mesh.ok());
    EXPECT_EQ(mesh.error(), model + ": the importer stopped: it did not finish within 1 second");
    EXPECT_TRUE(gone(dir.file("pid"))) << "the importer was left running or unreaped";
}

TEST(Importer, CancelEndsTheImporter) {
    TempDir dir;
    const std::string model = dir.file("model.obj");
    writeFile(model, kTriangleObj);
    const double half = 0.5;
    const std::string progress = header(core::importer::Tag::Progress, 8) +
                                 std::string(reinterpret_cast<const char*>(&half), sizeof half);
    ImporterOverride importer(script(dir, "importer",
                                     "echo $$ > '" + dir.file("pid") + "'\nprintf '" +
                                         octal(progress) + "'\nexec sleep 600\n"));
    std::vector<double> reports;
    const core::Result<core::Mesh> mesh = core::loadMesh(model, [&](double fraction) {
        reports.push_back(fraction);
        return fraction < 0.5; // cancel when the importer's report arrives
    });
    ASSERT_FALSE(mesh.ok());
    EXPECT_EQ(mesh.error(), model + ": cancelled");
    EXPECT_TRUE(mesh.cancelled());
    ASSERT_FALSE(reports.empty());
    EXPECT_EQ(reports.back(), 0.5);
    EXPECT_TRUE(gone(dir.file("pid"))) << "the importer was left running or unreaped";
}

TEST(Importer, AMissingImporterIsAClearError) {
    TempDir dir;
    const std::string model = dir.file("model.obj");
    writeFile(model, kTriangleObj);
    ImporterOverride importer(dir.file("no-such-importer"));
    const core::Result<core::Mesh> mesh = core::loadMesh(model);
    ASSERT_FALSE(mesh.ok());
    EXPECT_EQ(mesh.error(), model + ": the importer program " + dir.file("no-such-importer") +
                                " (set in LAYERPAINT_IMPORTER) does not exist or cannot be run");
    // Built-in models need no importer.
    EXPECT_TRUE(core::loadMesh("builtin:row").ok());
}

// ---------------------------------------------------------------------------------------------
// The real importer

/** Everything loadMesh() returns, compared field by field. */
void expectSameMesh(const core::Mesh& a, const core::Mesh& b) {
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.normals, b.normals);
    EXPECT_EQ(a.uvs, b.uvs);
    EXPECT_EQ(a.colors, b.colors);
    EXPECT_EQ(a.indices, b.indices);
    EXPECT_EQ(a.triangleMaterial, b.triangleMaterial);
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (std::size_t i = 0; i < a.materials.size(); ++i) {
        EXPECT_EQ(a.materials[i].name, b.materials[i].name);
        EXPECT_EQ(a.materials[i].baseColorFactor, b.materials[i].baseColorFactor);
        EXPECT_EQ(a.materials[i].baseColorTexture, b.materials[i].baseColorTexture);
        const core::Material &ma = a.materials[i], &mb = b.materials[i];
        EXPECT_EQ(ma.metallicFactor, mb.metallicFactor);
        EXPECT_EQ(ma.roughnessFactor, mb.roughnessFactor);
        EXPECT_EQ(ma.normalScale, mb.normalScale);
        EXPECT_EQ(ma.occlusionStrength, mb.occlusionStrength);
        EXPECT_EQ(ma.emissiveFactor, mb.emissiveFactor);
        EXPECT_EQ(ma.emissiveStrength, mb.emissiveStrength);
        EXPECT_EQ(ma.alphaMode, mb.alphaMode);
        EXPECT_EQ(ma.alphaCutoff, mb.alphaCutoff);
        EXPECT_EQ(ma.doubleSided, mb.doubleSided);
        const core::MaterialMap* mapsA[] = {&ma.metallicRoughness, &ma.normal, &ma.occlusion,
                                            &ma.emissive};
        const core::MaterialMap* mapsB[] = {&mb.metallicRoughness, &mb.normal, &mb.occlusion,
                                            &mb.emissive};
        for (std::size_t k = 0; k < 4; ++k) {
            EXPECT_EQ(mapsA[k]->texture, mapsB[k]->texture) << "map " << k;
            EXPECT_EQ(mapsA[k]->uvTransform, mapsB[k]->uvTransform) << "map " << k;
        }
    }
    ASSERT_EQ(a.textureSources.size(), b.textureSources.size());
    for (std::size_t i = 0; i < a.textureSources.size(); ++i) {
        EXPECT_EQ(a.textureSources[i].mimeType, b.textureSources[i].mimeType);
        EXPECT_TRUE(a.textureSources[i].bytes == b.textureSources[i].bytes);
    }
    ASSERT_EQ(a.textures.size(), b.textures.size());
    for (std::size_t i = 0; i < a.textures.size(); ++i) {
        EXPECT_EQ(a.textures[i].width, b.textures[i].width);
        EXPECT_EQ(a.textures[i].height, b.textures[i].height);
        EXPECT_TRUE(a.textures[i].rgba == b.textures[i].rgba);
    }
    EXPECT_EQ(a.warnings, b.warnings);
}

TEST(Importer, FilesLoadAsInProcess) {
    for (const char* rel : {"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb",
                            "glTF2/BoxTextured-glTF/BoxTextured.gltf", "PLY/float-color.ply",
                            "OBJ/spider.obj", "OFF/Wuson.off", "STL/Spider_ascii.stl"}) {
        const std::string path = (kModels / rel).string();
        if (!fs::exists(path))
            GTEST_SKIP() << "assimp test models not installed";
        SCOPED_TRACE(rel);
        std::vector<double> reports;
        const core::Result<core::Mesh> outside = core::loadMesh(path, [&](double f) {
            reports.push_back(f);
            return true;
        });
        const core::Result<core::Mesh> inside = core::loadMeshInProcess(path);
        ASSERT_TRUE(outside.ok()) << outside.error();
        ASSERT_TRUE(inside.ok()) << inside.error();
        expectSameMesh(*outside, *inside);
        ASSERT_FALSE(reports.empty());
        EXPECT_EQ(reports.front(), 0.0);
        EXPECT_EQ(reports.back(), 1.0);
        for (double f : reports)
            EXPECT_TRUE(f >= 0.0 && f <= 1.0) << f;
    }
}

TEST(Importer, TheWholeMaterialCrossesThePipe) {
    // Every factor, map, placement and kept file (tests/data/material, made by
    // scripts/make-material-test-data.py), and a real file with a JPEG normal map.
    for (const std::string& path :
         {std::string(LAYERPAINT_TEST_DATA) + "/material/materials.glb",
          (kModels / "glTF2/ClearCoat-glTF/ClearCoatTest.gltf").string()}) {
        if (!fs::exists(path))
            continue;
        SCOPED_TRACE(path);
        const core::Result<core::Mesh> outside = core::loadMesh(path);
        const core::Result<core::Mesh> inside = core::loadMeshInProcess(path);
        ASSERT_TRUE(outside.ok()) << outside.error();
        ASSERT_TRUE(inside.ok()) << inside.error();
        EXPECT_FALSE(outside->textureSources.empty());
        expectSameMesh(*outside, *inside);
    }
}

TEST(Importer, ErrorsAreTheSameAsInProcess) {
    TempDir dir;
    const std::string broken = dir.file("broken.off");
    writeFile(broken, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
    const core::Result<core::Mesh> outside = core::loadMesh(broken);
    const core::Result<core::Mesh> inside = core::loadMeshInProcess(broken);
    ASSERT_FALSE(outside.ok());
    EXPECT_EQ(outside.error(), inside.error());
}

TEST(Importer, AnImporterStartedAheadServesTheNextLoad) {
    const std::string path = (kModels / "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb").string();
    if (!fs::exists(path))
        GTEST_SKIP() << "assimp test models not installed";
    core::keepImporterReady();
    for (int i = 0; i < 3; ++i) {
        const core::Result<core::Mesh> mesh = core::loadMesh(path);
        ASSERT_TRUE(mesh.ok()) << mesh.error();
        EXPECT_EQ(mesh->triangleCount(), 12u);
    }
    {
        // The one waiting runs the real importer: a different one is started instead.
        TempDir dir;
        const std::string model = dir.file("model.obj");
        writeFile(model, kTriangleObj);
        ImporterOverride importer(script(dir, "importer", "kill -SEGV $$\n"));
        const core::Result<core::Mesh> mesh = core::loadMesh(model);
        ASSERT_FALSE(mesh.ok());
        EXPECT_EQ(mesh.error(), model + ": the importer stopped: it crashed (segmentation fault)");
        core::keepImporterReady(false); // before the script goes
    }
    EXPECT_TRUE(core::loadMesh(path).ok());
}

TEST(Importer, ImageFilesDecodeAsInProcess) {
    const std::string png = (kModels / "glTF2/BoxTextured-glTF/CesiumLogoFlat.png").string();
    if (!fs::exists(png))
        GTEST_SKIP() << "assimp test models not installed";
    const core::Result<core::Image> outside = core::loadImageFile(png);
    const core::Result<core::Image> inside = core::loadImageFileInProcess(png);
    ASSERT_TRUE(outside.ok()) << outside.error();
    ASSERT_TRUE(inside.ok()) << inside.error();
    EXPECT_EQ(outside->width, 211);
    EXPECT_EQ(outside->height, 211);
    EXPECT_TRUE(outside->rgba == inside->rgba);

    TempDir dir;
    const std::string truncated = dir.file("truncated.png");
    writeFile(truncated, readFile(png).substr(0, 300));
    for (const std::string& path : {truncated, dir.file("missing.png")}) {
        const core::Result<core::Image> image = core::loadImageFile(path);
        ASSERT_FALSE(image.ok()) << path;
        EXPECT_EQ(image.error().rfind(path + ": ", 0), 0u) << image.error();
        EXPECT_EQ(image.error(), core::loadImageFileInProcess(path).error());
    }
}

TEST(Importer, TheSandboxAllowsReadingTheModelsFolderOnly) {
    const char* program = std::getenv("LAYERPAINT_IMPORTER");
    ASSERT_NE(program, nullptr) << "ctest sets LAYERPAINT_IMPORTER";
    TempDir modelDir, otherDir;
    writeFile(modelDir.file("model.obj"), kTriangleObj);
    writeFile(otherDir.file("secret.txt"), "not for the importer");
    const std::string command = std::string("'") + program + "' --probe '" +
                                otherDir.file("secret.txt") + "' -- '" +
                                modelDir.file("model.obj") + "' | cat";
    FILE* pipe = ::popen(command.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    char line[512] = {};
    const bool read = std::fgets(line, sizeof line, pipe) != nullptr;
    ::pclose(pipe);
    ASSERT_TRUE(read);
    const std::string report = line;
    std::printf("[ sandbox  ] %s", report.c_str());
    auto has = [&](const std::string& part) { return report.find(part) != std::string::npos; };
    EXPECT_TRUE(has("read-file=allowed"));
    EXPECT_TRUE(has("no-new-privs=1"));
#if defined(__x86_64__) || defined(__aarch64__)
    EXPECT_TRUE(has("seccomp=1"));
    EXPECT_TRUE(has("socket=denied"));
#endif
    if (has("landlock=1")) {
        EXPECT_TRUE(has("read-other=denied"));
        EXPECT_TRUE(has("create-file=denied"));
        EXPECT_FALSE(fs::exists(modelDir.file("probe-created")));
    } else {
        std::printf("[ sandbox  ] no Landlock here: file access is not restricted\n");
    }
}

} // namespace importer_test
