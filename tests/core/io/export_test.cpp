// SPDX-License-Identifier: GPL-3.0-or-later
// Exports: each format re-imports (through loadMesh, or OpenImageIO for textures) with the same
// geometry and colours; progress runs to 1 and cancels; failures name the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "core/base/color.h"
#include "core/document/document.h"
#include "core/io/export.h"
#include "core/io/mesh_io.h"
#include "core/io/project/project_file.h"
#include "core/model/builtin_models.h"
#include "core/paint/targets/paint_target.h"
#include "tests/core/test_files.h"

namespace fs = std::filesystem;

namespace export_test {

using core_test::TempDir;

/** The trefoil painted with a few strokes into target kind (CPU capture). */
core::Mesh paintedTrefoil(core::PaintTargetKind kind) {
    core::Document doc;
    doc.setMesh(core::makeTrefoil(50, 14), "builtin:trefoil");
    core::PaintTargetOptions options;
    options.kind = kind;
    options.resolution = 512;
    EXPECT_TRUE(doc.setPaintTarget(options).ok());
    doc.camera() = core::Camera::fromOrbit(doc.mesh().bounds(), 30.0f, 20.0f, 1.6f);
    const int width = 240, height = 180;
    core::CpuDepthCapturer capturer;
    capturer.setMesh(doc.mesh());
    EXPECT_TRUE(doc.buildDepthLayers(capturer, doc.camera().view(width, height)).ok());
    const core::DepthStack& stack = doc.depthLayers()->stack;
    core::PaintChanges changes;
    doc.brush().radius = 12.0f;
    for (int y = height / 3; y < 2 * height / 3; y += 15) {
        int first = -1, last = -1;
        for (int x = 0; x < width; ++x)
            if (stack.layerCount(std::size_t(y) * width + std::size_t(x)) > 0) {
                first = first < 0 ? x : first;
                last = x;
            }
        if (first < 0 || last - first < 10)
            continue;
        doc.brush().color = {float(y % 7) / 7.0f, 0.3f, 1.0f - float(y % 5) / 5.0f, 1.0f};
        EXPECT_TRUE(doc.beginStroke({{float(first) + 1.0f, float(y)}, 1.0f}, changes).ok());
        for (int x = first + 3; x < last; x += 3)
            doc.moveStroke({{float(x), float(y)}, 1.0f}, changes);
        doc.endStroke();
    }
    return doc.paintedMesh();
}

core::Result<core::Mesh> load(const std::string& path) {
    core::Result<core::Mesh> mesh = core::loadMesh(path);
    EXPECT_TRUE(mesh.ok()) << mesh.error();
    return mesh;
}

/**
 * Every triangle corner of a and b at the same place: exactly, or within tolerance × the
 * model's size (Assimp's OBJ parser reads decimals to about 7 digits).
 */
void expectSameCorners(const core::Mesh& a, const core::Mesh& b, float tolerance = 0.0f) {
    ASSERT_EQ(a.triangleCount(), b.triangleCount());
    const float limit = tolerance * a.bounds().longestSide();
    std::size_t bad = 0;
    for (std::size_t i = 0; i < a.indices.size(); ++i) {
        const glm::vec3 d = a.positions[a.indices[i]] - b.positions[b.indices[i]];
        bad += std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}) > limit;
    }
    EXPECT_EQ(bad, 0u) << "corners moved";
}

struct Picture {
    int width = 0, height = 0, channels = 0;
    std::string format;
    std::vector<float> pixels; // as stored, normalized to 0..1 for integer formats
};

Picture readImage(const std::string& path) {
    Picture p;
    // The straight alpha as stored (PNG and TIFF readers would associate it).
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    EXPECT_TRUE(in) << OIIO::geterror();
    if (!in)
        return p;
    const OIIO::ImageSpec& spec = in->spec();
    p.width = spec.width;
    p.height = spec.height;
    p.channels = spec.nchannels;
    p.format = spec.format.c_str();
    p.pixels.resize(std::size_t(p.width) * p.height * p.channels);
    EXPECT_TRUE(in->read_image(0, 0, 0, p.channels, OIIO::TypeDesc::FLOAT, p.pixels.data()));
    return p;
}

core::Image gradient(int width, int height, bool opaque) {
    core::Image img;
    img.width = width;
    img.height = height;
    img.rgba.resize(std::size_t(width) * height * 4);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            std::uint8_t* p = &img.rgba[(std::size_t(y) * width + x) * 4];
            p[0] = std::uint8_t(x);
            p[1] = std::uint8_t(y * 3);
            p[2] = std::uint8_t((x * y) >> 3);
            p[3] = opaque ? 255 : std::uint8_t(255 - (x ^ y));
        }
    return img;
}

TEST(Export, GlbRoundTrip) {
    TempDir dir;
    const core::Mesh painted = paintedTrefoil(core::PaintTargetKind::Texture);
    const std::string path = dir.file("knot.glb");
    core::Result<std::vector<std::string>> files =
        core::exportMesh(path, core::ExportFormat::Glb, painted);
    ASSERT_TRUE(files.ok()) << files.error();
    EXPECT_EQ(*files, std::vector<std::string>{path});
    EXPECT_FALSE(fs::exists(path + ".bak"));
    core::Result<core::Mesh> back = load(path);
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(back->positions, painted.positions);
    EXPECT_EQ(back->indices, painted.indices);
    EXPECT_EQ(back->uvs, painted.uvs);
    ASSERT_EQ(back->textures.size(), 1u);
    EXPECT_TRUE(back->textures[0].rgba == painted.textures[0].rgba);
    // An export is a plain model: no LayerPaint state.
    core::Result<core::Project> project = core::loadProject(path);
    ASSERT_TRUE(project.ok());
    EXPECT_FALSE(project->state.has_value());
}

TEST(Export, ObjWithTextureRoundTrip) {
    TempDir dir;
    const core::Mesh painted = paintedTrefoil(core::PaintTargetKind::Texture);
    const std::string path = dir.file("my knot.obj");
    core::Result<std::vector<std::string>> files =
        core::exportMesh(path, core::ExportFormat::Obj, painted);
    ASSERT_TRUE(files.ok()) << files.error();
    EXPECT_EQ(*files,
              (std::vector<std::string>{dir.file("my_knot_1.png"), dir.file("my_knot.mtl"), path}));
    core::Result<core::Mesh> back = load(path);
    ASSERT_TRUE(back.ok());
    expectSameCorners(painted, *back, 1e-6f);
    ASSERT_TRUE(back->hasUvs());
    std::size_t badUv = 0, badNormal = 0;
    for (std::size_t i = 0; i < painted.indices.size(); ++i) {
        const glm::vec2 d = painted.uvs[painted.indices[i]] - back->uvs[back->indices[i]];
        badUv += std::abs(d.x) > 1e-6f || std::abs(d.y) > 1e-6f;
        const glm::vec3 n = painted.normals[painted.indices[i]] - back->normals[back->indices[i]];
        badNormal += std::abs(n.x) > 1e-5f || std::abs(n.y) > 1e-5f || std::abs(n.z) > 1e-5f;
    }
    EXPECT_EQ(badUv, 0u);
    EXPECT_EQ(badNormal, 0u);
    ASSERT_EQ(back->textures.size(), 1u);
    EXPECT_TRUE(back->textures[0].rgba == painted.textures[0].rgba) << "the texture changed";
    for (std::size_t t = 0; t < back->triangleCount(); t += 101) {
        const core::Material& m = back->materials[back->triangleMaterial[t]];
        EXPECT_EQ(m.baseColorTexture, 0);
        EXPECT_EQ(m.baseColorFactor, glm::vec4(1.0f));
    }
}

TEST(Export, ObjBakesFactorsAndKeepsVertexColours) {
    // Two quads: one textured with a tinting factor, one with a plain factor; vertex colours.
    core::Mesh mesh;
    for (int q = 0; q < 2; ++q) {
        const auto base = std::uint32_t(mesh.positions.size());
        for (int c = 0; c < 4; ++c) {
            const float x = float(c == 1 || c == 2) + float(q) * 2.0f, y = float(c >= 2);
            mesh.positions.push_back({x, y, 0.0f});
            mesh.normals.push_back({0, 0, 1});
            mesh.uvs.push_back({x * 0.25f, y * 0.5f});
            mesh.colors.push_back({0.2f * float(c + 1), 0.5f, 1.0f - 0.2f * float(c), 1.0f});
        }
        mesh.indices.insert(mesh.indices.end(),
                            {base, base + 1, base + 2, base, base + 2, base + 3});
        mesh.triangleMaterial.insert(mesh.triangleMaterial.end(),
                                     {std::uint32_t(q), std::uint32_t(q)});
    }
    mesh.materials = {core::Material{"tinted one", {0.5f, 1.0f, 0.25f, 1.0f}, 0},
                      core::Material{"plain", {0.1f, 0.2f, 0.3f, 0.75f}, -1}};
    mesh.textures = {gradient(16, 8, true)};
    ASSERT_TRUE(mesh.validate().ok());
    TempDir dir;
    const std::string path = dir.file("quads.obj");
    ASSERT_TRUE(core::exportMesh(path, core::ExportFormat::Obj, mesh).ok());
    core::Result<core::Mesh> back = load(path);
    ASSERT_TRUE(back.ok());
    expectSameCorners(mesh, *back, 1e-6f);
    ASSERT_TRUE(back->hasColors());
    for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
        const glm::vec4 a = mesh.colors[mesh.indices[i]], b = back->colors[back->indices[i]];
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(a[k], b[k], 1e-5f) << "corner " << i << " channel " << k;
    }
    const core::Material& tinted = back->materials[back->triangleMaterial[0]];
    const core::Material& plain = back->materials[back->triangleMaterial[2]];
    ASSERT_GE(tinted.baseColorTexture, 0);
    EXPECT_EQ(tinted.baseColorFactor, glm::vec4(1.0f)); // baked into the texture
    const core::Image& baked = back->textures[std::size_t(tinted.baseColorTexture)];
    for (std::size_t i = 0; i < baked.rgba.size(); i += 4) {
        EXPECT_EQ(baked.rgba[i],
                  core::linearToSrgb(core::srgbToLinear(mesh.textures[0].rgba[i]) * 0.5f));
        EXPECT_EQ(baked.rgba[i + 1], mesh.textures[0].rgba[i + 1]);
    }
    EXPECT_EQ(plain.baseColorTexture, -1);
    EXPECT_NEAR(plain.baseColorFactor.r, 0.1f, 1e-6f);
    EXPECT_NEAR(plain.baseColorFactor.b, 0.3f, 1e-6f);
    EXPECT_NEAR(plain.baseColorFactor.a, 0.75f, 1e-6f);
}

TEST(Export, PlyWithVertexColoursRoundTrip) {
    TempDir dir;
    const core::Mesh painted = paintedTrefoil(core::PaintTargetKind::VertexColors);
    ASSERT_TRUE(painted.hasColors());
    const std::string path = dir.file("knot.ply");
    ASSERT_TRUE(core::exportMesh(path, core::ExportFormat::Ply, painted).ok());
    core::Result<core::Mesh> back = load(path);
    ASSERT_TRUE(back.ok());
    expectSameCorners(painted, *back);
    ASSERT_TRUE(back->hasColors());
    std::size_t bad = 0, paintedCorners = 0;
    for (std::size_t i = 0; i < painted.indices.size(); ++i) {
        const glm::vec4 a = painted.colors[painted.indices[i]], b = back->colors[back->indices[i]];
        for (int k = 0; k < 3; ++k)
            bad += core::linearToSrgb(a[k]) != core::linearToSrgb(b[k]);
        bad += std::abs(a.a - b.a) > 0.5f / 255.0f;
        paintedCorners += a != glm::vec4(1.0f);
    }
    EXPECT_EQ(bad, 0u) << "colours differ";
    EXPECT_GT(paintedCorners, 100u);
}

TEST(Export, PlyTakesColoursFromTheTexture) {
    TempDir dir;
    const core::Mesh painted = paintedTrefoil(core::PaintTargetKind::Texture);
    ASSERT_FALSE(painted.hasColors());
    const std::string path = dir.file("knot.ply");
    ASSERT_TRUE(core::exportMesh(path, core::ExportFormat::Ply, painted).ok());
    core::Result<core::Mesh> back = load(path);
    ASSERT_TRUE(back.ok());
    expectSameCorners(painted, *back);
    ASSERT_TRUE(back->hasColors());
    std::size_t bad = 0, coloured = 0;
    for (std::size_t i = 0; i < painted.indices.size(); ++i) {
        const std::uint32_t v = painted.indices[i];
        const glm::vec4 expected = core::sampleTexture(painted.textures[0], painted.uvs[v]);
        const glm::vec4 got = back->colors[back->indices[i]];
        for (int k = 0; k < 3; ++k)
            bad += core::linearToSrgb(expected[k]) != core::linearToSrgb(got[k]);
        for (int k = 0; k < 2; ++k)
            bad += std::abs(painted.uvs[v][k] - back->uvs[back->indices[i]][k]) > 1e-6f;
        coloured += core::linearToSrgb(got.g) != core::linearToSrgb(got.r);
    }
    EXPECT_EQ(bad, 0u);
    EXPECT_GT(coloured, 100u) << "the paint does not show in the vertex colours";

    // sampleTexture itself: texel centres give the texel, corners blend, UVs repeat.
    const core::Image img = gradient(4, 2, true);
    const glm::vec4 centre = core::sampleTexture(img, {1.5f / 4.0f, 0.5f / 2.0f});
    EXPECT_EQ(core::linearToSrgb(centre.r), img.rgba[4]);
    EXPECT_EQ(core::linearToSrgb(centre.g), img.rgba[5]);
    const glm::vec4 wrapped = core::sampleTexture(img, {1.0f + 1.5f / 4.0f, -1.0f + 0.5f / 2.0f});
    EXPECT_NEAR(wrapped.r, centre.r, 1e-6f);
}

TEST(Export, TextureFormatsRoundTrip) {
    TempDir dir;
    for (const bool opaque : {true, false}) {
        const core::Image page = gradient(64, 32, opaque);
        for (const core::ExportFormat format :
             {core::ExportFormat::Png8, core::ExportFormat::Png16, core::ExportFormat::Tiff,
              core::ExportFormat::Exr}) {
            SCOPED_TRACE(std::string(core::exportFormatName(format)) +
                         (opaque ? " opaque" : " with alpha"));
            const std::string path =
                dir.file(std::string("page_") + core::exportFormatName(format) +
                         (opaque ? "_o" : "_a") + core::exportExtension(format));
            const core::Status s = core::exportTexture(path, format, page);
            ASSERT_TRUE(s.ok()) << s.error();
            const Picture p = readImage(path);
            ASSERT_EQ(p.width, 64);
            ASSERT_EQ(p.height, 32);
            ASSERT_EQ(p.channels, opaque ? 3 : 4);
            EXPECT_EQ(p.format, format == core::ExportFormat::Png16 ? "uint16"
                                : format == core::ExportFormat::Exr ? "half"
                                                                    : "uint8");
            std::size_t bad = 0;
            for (std::size_t px = 0; px < std::size_t(64 * 32); ++px) {
                const float alpha = opaque ? 1.0f : p.pixels[px * 4 + 3];
                for (int c = 0; c < p.channels; ++c) {
                    const std::uint8_t want = page.rgba[px * 4 + std::size_t(c)];
                    float v = p.pixels[px * std::size_t(p.channels) + std::size_t(c)];
                    std::uint8_t got = 0;
                    if (format == core::ExportFormat::Exr) {
                        // EXR stores linear colour associated with alpha.
                        if (c < 3)
                            got = core::linearToSrgb(alpha > 0.0f ? v / alpha : 0.0f);
                        else
                            got = std::uint8_t(std::lround(v * 255.0f));
                        if (c < 3 && alpha < 16.0f / 255.0f)
                            continue; // nothing of the colour is left to compare
                    } else {
                        got = std::uint8_t(std::lround(v * 255.0f));
                        if (format == core::ExportFormat::Png16)
                            bad += std::lround(v * 65535.0f) != long(want) * 257;
                    }
                    bad += got != want;
                }
            }
            EXPECT_EQ(bad, 0u);
        }
    }
}

TEST(Export, SeveralPagesAndVertexColourModels) {
    TempDir dir;
    const std::vector<core::Image> pages = {gradient(8, 8, true), gradient(16, 4, true)};
    core::Result<std::vector<std::string>> files =
        core::exportTextures(dir.file("paint.tif"), core::ExportFormat::Tiff, pages);
    ASSERT_TRUE(files.ok()) << files.error();
    EXPECT_EQ(*files, (std::vector<std::string>{dir.file("paint.tif"), dir.file("paint_2.tif")}));
    EXPECT_EQ(readImage(dir.file("paint_2.tif")).width, 16);
    core::Result<std::vector<std::string>> none =
        core::exportTextures(dir.file("none.png"), core::ExportFormat::Png8, {});
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.error().find("vertex colours"), std::string::npos) << none.error();
}

TEST(Export, ProgressRunsToTheEndAndCancels) {
    TempDir dir;
    const core::Mesh painted = paintedTrefoil(core::PaintTargetKind::Texture);
    for (const core::ExportFormat format : {core::ExportFormat::Glb, core::ExportFormat::Obj,
                                            core::ExportFormat::Ply, core::ExportFormat::Png16}) {
        SCOPED_TRACE(core::exportFormatName(format));
        const std::string path = dir.file(std::string("p") + core::exportExtension(format));
        std::vector<double> seen;
        const core::ProgressFn record = [&](double f) {
            seen.push_back(f);
            return true;
        };
        const bool ok = core::isTextureFormat(format)
                            ? core::exportTexture(path, format, painted.textures[0], record).ok()
                            : core::exportMesh(path, format, painted, record).ok();
        ASSERT_TRUE(ok);
        ASSERT_GE(seen.size(), 2u);
        EXPECT_EQ(seen.front(), 0.0);
        EXPECT_EQ(seen.back(), 1.0);
        EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));

        const std::string cancelledPath =
            dir.file(std::string("c") + core::exportExtension(format));
        int calls = 0;
        const core::ProgressFn cancel = [&](double) { return ++calls < 2; };
        const core::Error error =
            core::isTextureFormat(format)
                ? core::exportTexture(cancelledPath, format, painted.textures[0], cancel)
                      .takeError()
                : core::exportMesh(cancelledPath, format, painted, cancel).takeError();
        EXPECT_EQ(error.message, cancelledPath + ": cancelled");
        EXPECT_EQ(error.kind, core::ErrorKind::Cancelled);
        EXPECT_FALSE(fs::exists(cancelledPath));
    }
}

TEST(Export, FailuresNameTheFile) {
    TempDir dir;
    const core::Mesh mesh = core::makeTrefoil(20, 8);
    const std::string missing = dir.file("no/such/folder/model.obj");
    core::Result<std::vector<std::string>> r =
        core::exportMesh(missing, core::ExportFormat::Obj, mesh);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().find(dir.file("no/such/folder/")), std::string::npos) << r.error();
    r = core::exportMesh(dir.file("m.png"), core::ExportFormat::Png8, mesh);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().find("not a model"), std::string::npos);
    r = core::exportMesh(dir.file("bad.ply"), core::ExportFormat::Ply, core::Mesh{});
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().rfind(dir.file("bad.ply") + ": ", 0), 0u) << r.error();
    const core::Status s =
        core::exportTexture(dir.file("empty.png"), core::ExportFormat::Png8, core::Image{});
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().rfind(dir.file("empty.png") + ": ", 0), 0u) << s.error();
    EXPECT_TRUE(core::parseExportFormat("png16") == core::ExportFormat::Png16);
    EXPECT_FALSE(core::parseExportFormat("bmp").has_value());
}

} // namespace export_test
