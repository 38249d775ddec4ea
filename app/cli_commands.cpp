// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli_commands.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "core/depth/depth_layers.h"
#include "core/document/document.h"
#include "core/io/gltf/gltf_export.h"
#include "core/io/image/image_write.h"
#include "core/io/mesh_io.h"
#include "core/io/ply_write.h"
#include "core/model/camera.h"
#include "render/gl_context.h"
#include "render/gl_depth_capturer.h"
#include "render/gpu_connectivity.h"

namespace cli {

namespace {
using nlohmann::json;

json vec(const glm::vec3& v) {
    return {v.x, v.y, v.z};
}

core::Result<glm::mat4> readMatrix(const json& value, const std::string& file, const char* key) {
    if (!value.contains(key) || !value[key].is_array() || value[key].size() != 16)
        return core::Error{file + ": \"" + std::string(key) + "\" must be an array of 16 numbers"};
    glm::mat4 m;
    float* out = glm::value_ptr(m);
    for (int i = 0; i < 16; ++i) {
        const json& x = value[key][std::size_t(i)];
        if (!x.is_number() || !std::isfinite(x.get<double>()))
            return core::Error{file + ": \"" + std::string(key) + "\" has a non-finite entry"};
        out[i] = x.get<float>();
    }
    return m;
}

} // namespace

core::Result<std::unique_ptr<core::DepthCapturer>>
makeCapturer(bool cpu, std::unique_ptr<render::HeadlessContext>& context) {
    if (cpu)
        return std::unique_ptr<core::DepthCapturer>(std::make_unique<core::CpuDepthCapturer>());
    auto created = render::HeadlessContext::create();
    if (!created)
        return core::Error{created.error() + " (use --cpu to capture without OpenGL)"};
    context = std::move(created).value();
    auto gl = std::make_unique<render::GlDepthCapturer>();
    if (const core::Status s = gl->initialize(); !s)
        return s.takeError();
    return std::unique_ptr<core::DepthCapturer>(std::move(gl));
}

void applyTargetArgs(const std::string& target, int resolution, core::PaintTargetOptions& options) {
    if (target == "texture")
        options.kind = core::PaintTargetKind::Texture;
    else if (target == "vertex-colors")
        options.kind = core::PaintTargetKind::VertexColors;
    if (resolution > 0)
        options.resolution = resolution;
}

int fail(const std::string& message) {
    std::cerr << "layerpaint-cli: " << message << '\n';
    return 1;
}

core::Result<core::View> makeView(const CameraArgs& args, const core::Mesh& mesh,
                                  const core::Camera* fallback) {
    const auto size = core::parseViewSize(args.size);
    if (!size)
        return core::Error{"--size " + size.error(), core::ErrorKind::BadInput};
    const auto [width, height] = *size;
    if (args.cameraFile.empty()) {
        auto camera = makeCamera(args, mesh, fallback);
        if (!camera)
            return camera.takeError();
        return camera->view(width, height);
    }
    std::ifstream in(args.cameraFile);
    if (!in)
        return core::Error{args.cameraFile + ": cannot be opened"};
    const json value = json::parse(in, nullptr, false);
    if (value.is_discarded() || !value.is_object())
        return core::Error{args.cameraFile + ": not a JSON object"};
    auto view = readMatrix(value, args.cameraFile, "view");
    auto proj = readMatrix(value, args.cameraFile, "proj");
    if (!view)
        return view.takeError();
    if (!proj)
        return proj.takeError();
    core::View v;
    v.view = *view;
    v.proj = *proj;
    v.width = width;
    v.height = height;
    return v;
}

core::Result<core::Camera> makeCamera(const CameraArgs& args, const core::Mesh& mesh,
                                      const core::Camera* fallback) {
    if (args.orbit.empty() && fallback)
        return *fallback;
    core::Camera camera;
    camera.frame(mesh.bounds());
    camera.orbit(30.0f, 20.0f);
    if (!args.orbit.empty()) {
        auto orbit = core::parseOrbitCamera(args.orbit, mesh.bounds());
        if (!orbit)
            return core::Error{"--orbit " + orbit.error(), core::ErrorKind::BadInput};
        camera = *orbit;
    }
    return camera;
}

std::string jsonText(const json& value, int indent) {
    return value.dump(indent, ' ', false, json::error_handler_t::replace);
}

namespace {

/** Writes the flattened triangles in triangle-id order as binary little-endian PLY. */
core::Status writePly(const std::string& path, const core::Mesh& mesh) {
    core::PlyContents contents;
    contents.comment = "LayerPaint flattened mesh";
    contents.normals = false;
    contents.uvs = false;
    const std::string bytes = core::encodePly(mesh, contents);
    return core::writeFileAtomically(path, bytes.data(), bytes.size(), false);
}

core::Status writeJson(const std::string& path, const json& value) {
    std::ofstream out(path);
    out << jsonText(value, 1) << '\n';
    out.close();
    if (!out)
        return core::Error{path + ": write failed"};
    return {};
}

/** Writes the per-layer images of docs/architecture.md §4 for layer (1-based). */
core::Status writeLayerImages(const std::filesystem::path& dir, const core::DepthLayers& layers,
                              std::uint32_t layer) {
    const core::DepthStack& stack = layers.stack;
    const std::size_t pixels = stack.pixelCount();
    std::vector<float> depth(pixels, 0.0f);
    std::vector<std::uint32_t> triangle(pixels, 0), region(pixels, 0);
    std::vector<std::uint8_t> links(pixels * 4, 0);
    for (std::size_t p = 0; p < pixels; ++p) {
        const std::uint32_t f = stack.fragment(p, layer);
        if (f == core::kNone)
            continue;
        depth[p] = stack.depth[f];
        triangle[p] = stack.triangle[f] + 1;
        region[p] = layers.segmentation.region[f] + 1;
        for (int d = 0; d < 4; ++d)
            links[4 * p + std::size_t(d)] = layers.connectivity.link(f, d);
    }
    const std::string n = std::to_string(layer);
    const int w = stack.width, h = stack.height;
    for (const core::Status& s : {core::writeImage((dir / ("depth_" + n + ".exr")).string(), w, h,
                                                   1, core::PixelType::Float32, depth.data()),
                                  core::writeImage((dir / ("tri_" + n + ".tif")).string(), w, h, 1,
                                                   core::PixelType::UInt32, triangle.data()),
                                  core::writeImage((dir / ("conn_" + n + ".png")).string(), w, h, 4,
                                                   core::PixelType::UInt8, links.data()),
                                  core::writeImage((dir / ("region_" + n + ".tif")).string(), w, h,
                                                   1, core::PixelType::UInt32, region.data())})
        if (!s)
            return s;
    return {};
}

json regionsJson(const core::RegionGraph& graph) {
    json regions = json::array();
    for (const core::Region& r : graph.regions) {
        json neighbours = json::array();
        for (const core::RegionLink& link : graph.neighborsOf(r.id))
            neighbours.push_back({{"id", link.region}, {"links", link.links}});
        regions.push_back({{"id", r.id},
                           {"layer", r.layer},
                           {"pixels", r.pixels},
                           {"bbox", {r.minX, r.minY, r.maxX, r.maxY}},
                           {"neighbours", neighbours}});
    }
    return regions;
}
} // namespace

int runInfo(const std::string& model) {
    auto mesh = core::loadMesh(model);
    if (!mesh)
        return fail(mesh.error());
    const core::Bounds bounds = mesh->bounds();
    json materials = json::array();
    for (const core::Material& m : mesh->materials) {
        json entry = {
            {"name", m.name},
            {"base_color",
             {m.baseColorFactor.r, m.baseColorFactor.g, m.baseColorFactor.b, m.baseColorFactor.a}},
            {"base_color_texture", nullptr}};
        if (m.baseColorTexture >= 0) {
            const core::Image& image = mesh->textures[std::size_t(m.baseColorTexture)];
            entry["base_color_texture"] = {{"width", image.width}, {"height", image.height}};
        }
        materials.push_back(std::move(entry));
    }
    const json out = {
        {"file", model},
        {"vertices", mesh->vertexCount()},
        {"triangles", mesh->triangleCount()},
        {"bounds", {{"min", vec(bounds.min)}, {"max", vec(bounds.max)}}},
        {"has_uvs", mesh->hasUvs()},
        {"has_vertex_colors", mesh->hasColors()},
        {"materials", materials},
        {"warnings", mesh->warnings},
    };
    std::cout << jsonText(out, 2) << '\n';
    return 0;
}

/**
 * visible.tif: per pixel the layer (uint32, 0 = none) of the visible fragment in the region order
 * after the script's operations (the initial order without a script), looked up as the Document
 * does for the GUI, whose drawing matches it (tested). Operations that turn the camera leave the
 * map of the view they end in.
 */
core::Status writeVisible(const std::filesystem::path& dir, const DepthLayersArgs& args,
                          const core::Mesh& mesh, core::DepthCapturer& capturer,
                          core::ConnectivityEngine* engine, const core::DepthLayerOptions& options,
                          core::DepthLayers layers, core::View view) {
    core::Document doc;
    doc.setMesh(mesh, args.model);
    doc.setDepthLayerOptions(options);
    doc.setConnectivityEngine(engine);
    doc.adoptLayers(std::move(layers), doc.meshSerial());
    if (!args.script.empty()) {
        auto script = core::readScript(args.script);
        if (!script)
            return script.takeError();
        if (const core::Status s = replayScript(*script, args.script, doc, capturer, view); !s)
            return s;
    }
    if (!doc.depthLayers())
        if (const core::Status s = doc.buildDepthLayers(capturer, view); !s)
            return s;
    const core::DepthStack& stack = doc.depthLayers()->stack;
    std::vector<std::uint32_t> visible(stack.pixelCount(), 0);
    for (std::size_t p = 0; p < visible.size(); ++p) {
        const std::uint32_t f = doc.visibleFragment(p);
        visible[p] = f == core::kNone ? 0 : f - stack.offsets[p] + 1;
    }
    return core::writeImage((dir / "visible.tif").string(), stack.width, stack.height, 1,
                            core::PixelType::UInt32, visible.data());
}

int runDepthLayers(const DepthLayersArgs& args) {
    if (!args.script.empty())
        if (auto script = core::readScript(args.script); !script)
            return fail(script.error()); // before any work
    auto mesh = core::loadMesh(args.model);
    if (!mesh)
        return fail(mesh.error());
    auto view = makeView(args.camera, *mesh);
    if (!view)
        return fail(view.error());
    std::error_code ec;
    std::filesystem::create_directories(args.outDir, ec);
    if (ec)
        return fail(args.outDir + ": " + ec.message());

    std::unique_ptr<render::HeadlessContext> context;
    std::unique_ptr<render::GlConnectivityEngine> engine;
    const auto backend = render::parseConnectivityBackend(args.connectivity);
    if (args.cpuCapture && backend == render::ConnectivityBackend::Gpu)
        return fail("--connectivity gpu needs OpenGL: drop --cpu");
    auto made = makeCapturer(args.cpuCapture, context);
    if (!made)
        return fail(made.error());
    std::unique_ptr<core::DepthCapturer> capturer = std::move(made).value();
    if (!args.cpuCapture)
        engine = std::make_unique<render::GlConnectivityEngine>(
            backend.value_or(render::ConnectivityBackend::Auto));
    capturer->setMesh(*mesh);

    core::DepthLayerOptions options;
    if (args.threshold) {
        if (!(*args.threshold > 0.0f) || !std::isfinite(*args.threshold))
            return fail("--threshold must be a positive number");
        options.threshold = *args.threshold;
    }
    options.test = args.plainTest ? core::ConnectionTest::Plain : core::ConnectionTest::Surface;
    options.cullBackFaces = !args.twoSided;
    const core::MeshTopology topology = core::buildMeshTopology(*mesh);
    auto layers = core::buildDepthLayers(*capturer, *mesh, topology, *view, options, engine.get());
    if (!layers)
        return fail(args.model + ": " + layers.error());

    const std::filesystem::path dir(args.outDir);
    const std::vector<std::uint32_t> perLayer = layers->stack.fragmentsPerLayer();
    for (std::uint32_t layer = 1; layer <= perLayer.size(); ++layer)
        if (const core::Status s = writeLayerImages(dir, *layers, layer); !s)
            return fail(s.error());
    if (const core::Status s =
            writeJson((dir / "regions.json").string(), regionsJson(layers->segmentation.graph));
        !s)
        return fail(s.error());
    if (const core::Status s = writePly((dir / "mesh.ply").string(), *mesh); !s)
        return fail(s.error());

    // How well each connection test follows the mesh (docs/architecture.md §3 step 2's two
    // properties).
    json quality;
    for (const core::ConnectionTest test :
         {core::ConnectionTest::Plain, core::ConnectionTest::Surface}) {
        core::ConnectivityOptions connectivity;
        connectivity.test = test;
        connectivity.threshold = options.threshold;
        connectivity.unitScale = core::unitScale(*mesh);
        const core::ConnectivityQuality q = core::measureConnectivity(
            layers->stack,
            core::computeConnectivity(layers->stack, connectivity, &layers->geometry), topology);
        quality[test == core::ConnectionTest::Plain ? "plain" : "surface"] = {
            {"same_triangle_pairs", q.sameTrianglePairs},
            {"same_triangle_disconnected_share", q.sameTriangleDisconnectedShare()},
            {"adjacent_triangle_pairs", q.adjacentTrianglePairs},
            {"adjacent_triangle_disconnected_share", q.adjacentTriangleDisconnectedShare()},
            {"connected_pairs", q.connectedPairs},
            {"cross_component_share", q.crossComponentShare()}};
    }

    const core::DepthLayerTimings& t = layers->timings;
    const json summary = {
        {"model", args.model},
        {"width", view->width},
        {"height", view->height},
        {"triangles", mesh->triangleCount()},
        {"test", args.plainTest ? "plain" : "surface"},
        {"threshold", options.threshold},
        {"two_sided", args.twoSided},
        {"capture", args.cpuCapture ? "cpu" : "gl"},
        {"connectivity_engine",
         engine ? render::connectivityBackendName(engine->backend()) : "cpu"},
        {"layers", perLayer.size()},
        {"fragments", layers->stack.fragmentCount()},
        {"fragments_per_layer", perLayer},
        {"regions", layers->segmentation.graph.regions.size()},
        {"links_truncated", layers->connectivity.truncated},
        {"connectivity_quality", quality},
        {"view", std::vector<float>(glm::value_ptr(view->view), glm::value_ptr(view->view) + 16)},
        {"proj", std::vector<float>(glm::value_ptr(view->proj), glm::value_ptr(view->proj) + 16)},
        {"timings_ms",
         {{"capture_gpu", t.capture.gpuMs},
          {"capture_resolve", t.capture.resolveMs},
          {"connectivity", t.connectivityMs},
          {"surface_planes", t.surfaceMs},
          {"segmentation", t.segmentationMs - t.graphMs},
          {"graph", t.graphMs},
          {"build_layers", t.totalMs()}}},
    };
    if (const core::Status s = writeVisible(dir, args, *mesh, *capturer, engine.get(), options,
                                            std::move(layers).value(), *view);
        !s)
        return fail(s.error());
    if (const core::Status s = writeJson((dir / "summary.json").string(), summary); !s)
        return fail(s.error());
    std::cout << jsonText(summary, 1) << '\n';
    return 0;
}

} // namespace cli
