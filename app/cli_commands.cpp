// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli_commands.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "core/base/text.h"
#include "core/depth/depth_layers.h"
#include "core/document/document.h"
#include "core/io/gltf/gltf_export.h"
#include "core/io/image/image_write.h"
#include "core/io/mesh_io.h"
#include "core/io/ply_write.h"
#include "core/model/camera.h"
#include "core/model/source_scene.h"
#include "core/paint/targets/layout_target.h"
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

// Messages carry text from files: each is one line, escaped and cut, whatever it quotes.
constexpr std::size_t kMaxMessageChars = 2000;

int fail(const std::string& message) {
    std::cerr << "layerpaint-cli: " << core::printable(message, kMaxMessageChars) << '\n';
    return 1;
}

void warn(const std::vector<std::string>& warnings) {
    for (const std::string& w : warnings)
        std::cerr << "layerpaint-cli: warning: " << core::printable(w, kMaxMessageChars) << '\n';
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

json textureJson(const core::Mesh& mesh, int texture) {
    if (texture < 0)
        return nullptr;
    const core::Image& image = mesh.textures[std::size_t(texture)];
    return {{"width", image.width}, {"height", image.height}};
}

json mapJson(const core::Mesh& mesh, const core::MaterialMap& map) {
    if (map.texture < 0)
        return nullptr;
    json out = textureJson(mesh, map.texture);
    if (map.uvTransform != glm::mat3(1.0f)) {
        json columns = json::array();
        for (int c = 0; c < 3; ++c)
            columns.push_back(
                {map.uvTransform[c][0], map.uvTransform[c][1], map.uvTransform[c][2]});
        out["uv_transform"] = std::move(columns);
    }
    return out;
}

const char* alphaModeName(core::AlphaMode mode) {
    switch (mode) {
    case core::AlphaMode::Mask:
        return "mask";
    case core::AlphaMode::Blend:
        return "blend";
    case core::AlphaMode::Opaque:
        break;
    }
    return "opaque";
}

json materialJson(const core::Mesh& mesh, const core::Material& m) {
    json entry = {
        {"name", m.name},
        {"base_color",
         {m.baseColorFactor.r, m.baseColorFactor.g, m.baseColorFactor.b, m.baseColorFactor.a}},
        {"base_color_texture", textureJson(mesh, m.baseColorTexture)},
        {"metallic", m.metallicFactor},
        {"roughness", m.roughnessFactor},
        {"metallic_roughness_texture", mapJson(mesh, m.metallicRoughness)},
        {"normal_scale", m.normalScale},
        {"normal_texture", mapJson(mesh, m.normal)},
        {"occlusion_strength", m.occlusionStrength},
        {"occlusion_texture", mapJson(mesh, m.occlusion)},
        {"emissive", vec(m.emissiveFactor)},
        {"emissive_strength", m.emissiveStrength},
        {"emissive_texture", mapJson(mesh, m.emissive)},
        {"alpha_mode", alphaModeName(m.alphaMode)},
        {"double_sided", m.doubleSided}};
    if (m.alphaMode == core::AlphaMode::Mask)
        entry["alpha_cutoff"] = m.alphaCutoff;
    return entry;
}
/** Whether saving writes the file's own scene back, and its size; or why not. */
/** The model's named objects: name and triangle count each. */
json objectsJson(const core::Mesh& mesh) {
    json objects = json::array();
    for (std::size_t o = 0; o < mesh.objects.size(); ++o) {
        const std::size_t end =
            o + 1 < mesh.objects.size() ? mesh.objects[o + 1].firstTriangle : mesh.triangleCount();
        objects.push_back(
            {{"name", mesh.objects[o].name}, {"triangles", end - mesh.objects[o].firstTriangle}});
    }
    return objects;
}

json sceneJson(const core::Mesh& mesh) {
    if (!mesh.source)
        return {{"kept", false}, {"why", "the model was not read from a glTF file"}};
    const core::SourceScene& scene = *mesh.source;
    if (!scene.notKept.empty())
        return {{"kept", false}, {"why", scene.notKept}};
    return {{"kept", true},
            {"nodes", scene.json.value("nodes", json::array()).size()},
            {"meshes", scene.json.value("meshes", json::array()).size()},
            {"images", scene.json.value("images", json::array()).size()}};
}
} // namespace

int runInfo(const std::string& model) {
    auto mesh = core::loadMesh(model);
    if (!mesh)
        return fail(mesh.error());
    const core::Bounds bounds = mesh->bounds();
    // What a texture target paints each material into (the default 2048² only where it has no
    // base colour texture of its own).
    const std::vector<core::PageSize> pageSizes = core::texturePageSizes(*mesh, {});
    json materials = json::array();
    for (std::size_t i = 0; i < mesh->materials.size(); ++i) {
        json entry = materialJson(*mesh, mesh->materials[i]);
        entry["paint_texture"] = {{"width", pageSizes[i].width}, {"height", pageSizes[i].height}};
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
        {"objects", objectsJson(*mesh)},
        {"scene", sceneJson(*mesh)},
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

namespace {

/** What `layers` works with: the model, its view, the capturer and the depth layers built. */
struct DepthLayersRun {
    const DepthLayersArgs& args;
    core::Mesh mesh;
    core::View view;
    std::unique_ptr<render::HeadlessContext> context; // outlives the capturer
    std::unique_ptr<render::GlConnectivityEngine> engine;
    std::unique_ptr<core::DepthCapturer> capturer;
    core::DepthLayerOptions options;
    core::DepthLayers layers;
};

/** The script checked, the model and its view, the output folder; an Error to fail with. */
core::Status loadModelAndView(DepthLayersRun& run) {
    const DepthLayersArgs& args = run.args;
    if (!args.script.empty())
        if (auto script = core::readScript(args.script); !script)
            return script.takeError(); // before any work
    auto mesh = core::loadMesh(args.model);
    if (!mesh)
        return mesh.takeError();
    run.mesh = std::move(mesh).value();
    auto view = makeView(args.camera, run.mesh);
    if (!view)
        return view.takeError();
    run.view = *view;
    std::error_code ec;
    std::filesystem::create_directories(args.outDir, ec);
    if (ec)
        return core::Error{args.outDir + ": " + ec.message()};
    return {};
}

/** The capturer (GL or CPU) and, with OpenGL, the connectivity engine; an Error to fail with. */
core::Status makeCapturerAndEngine(DepthLayersRun& run) {
    const DepthLayersArgs& args = run.args;
    const auto backend = render::parseConnectivityBackend(args.connectivity);
    if (args.cpuCapture && backend == render::ConnectivityBackend::Gpu)
        return core::Error{"--connectivity gpu needs OpenGL: drop --cpu"};
    auto made = makeCapturer(args.cpuCapture, run.context);
    if (!made)
        return made.takeError();
    run.capturer = std::move(made).value();
    if (!args.cpuCapture)
        run.engine = std::make_unique<render::GlConnectivityEngine>(
            backend.value_or(render::ConnectivityBackend::Auto));
    run.capturer->setMesh(run.mesh);
    return {};
}

/** The segmentation options of the command line; an Error for a bad --threshold. */
core::Status readDepthLayerOptions(DepthLayersRun& run) {
    const DepthLayersArgs& args = run.args;
    if (args.threshold) {
        if (!(*args.threshold > 0.0f) || !std::isfinite(*args.threshold))
            return core::Error{"--threshold must be a positive number"};
        run.options.threshold = *args.threshold;
    }
    run.options.test = args.plainTest ? core::ConnectionTest::Plain : core::ConnectionTest::Surface;
    run.options.cullBackFaces = !args.twoSided;
    return {};
}

/** Each depth layer's images, regions.json and mesh.ply. */
core::Status writeLayerFiles(const DepthLayersRun& run, const std::filesystem::path& dir) {
    const std::vector<std::uint32_t> perLayer = run.layers.stack.fragmentsPerLayer();
    for (std::uint32_t layer = 1; layer <= perLayer.size(); ++layer)
        if (const core::Status s = writeLayerImages(dir, run.layers, layer); !s)
            return s;
    if (const core::Status s =
            writeJson((dir / "regions.json").string(), regionsJson(run.layers.segmentation.graph));
        !s)
        return s;
    return writePly((dir / "mesh.ply").string(), run.mesh);
}

/**
 * How well each connection test follows the mesh (docs/architecture.md §3 step 2's two
 * properties).
 */
json connectivityQuality(const DepthLayersRun& run, const core::MeshTopology& topology) {
    json quality;
    for (const core::ConnectionTest test :
         {core::ConnectionTest::Plain, core::ConnectionTest::Surface}) {
        core::ConnectivityOptions connectivity;
        connectivity.test = test;
        connectivity.threshold = run.options.threshold;
        connectivity.unitScale = core::unitScale(run.mesh);
        const core::DepthStack& stack = run.layers.stack;
        const core::ConnectivityQuality q = core::measureConnectivity(
            stack, core::computeConnectivity(stack, connectivity, &run.layers.geometry), topology);
        quality[test == core::ConnectionTest::Plain ? "plain" : "surface"] = {
            {"same_triangle_pairs", q.sameTrianglePairs},
            {"same_triangle_disconnected_share", q.sameTriangleDisconnectedShare()},
            {"adjacent_triangle_pairs", q.adjacentTrianglePairs},
            {"adjacent_triangle_disconnected_share", q.adjacentTriangleDisconnectedShare()},
            {"connected_pairs", q.connectedPairs},
            {"cross_component_share", q.crossComponentShare()}};
    }
    return quality;
}

/** summary.json: the view, the options, the counts, quality and the timings. */
json depthLayersSummary(const DepthLayersRun& run, const json& quality) {
    const DepthLayersArgs& args = run.args;
    const core::DepthLayers& layers = run.layers;
    const core::View& view = run.view;
    const std::vector<std::uint32_t> perLayer = layers.stack.fragmentsPerLayer();
    const core::DepthLayerTimings& t = layers.timings;
    return {
        {"model", args.model},
        {"width", view.width},
        {"height", view.height},
        {"triangles", run.mesh.triangleCount()},
        {"test", args.plainTest ? "plain" : "surface"},
        {"threshold", run.options.threshold},
        {"two_sided", args.twoSided},
        {"capture", args.cpuCapture ? "cpu" : "gl"},
        {"connectivity_engine",
         run.engine ? render::connectivityBackendName(run.engine->backend()) : "cpu"},
        {"layers", perLayer.size()},
        {"fragments", layers.stack.fragmentCount()},
        {"fragments_per_layer", perLayer},
        {"regions", layers.segmentation.graph.regions.size()},
        {"links_truncated", layers.connectivity.truncated},
        {"connectivity_quality", quality},
        {"view", std::vector<float>(glm::value_ptr(view.view), glm::value_ptr(view.view) + 16)},
        {"proj", std::vector<float>(glm::value_ptr(view.proj), glm::value_ptr(view.proj) + 16)},
        {"timings_ms",
         {{"capture_gpu", t.capture.gpuMs},
          {"capture_resolve", t.capture.resolveMs},
          {"connectivity", t.connectivityMs},
          {"surface_planes", t.surfaceMs},
          {"segmentation", t.segmentationMs - t.graphMs},
          {"graph", t.graphMs},
          {"build_layers", t.totalMs()}}},
    };
}

} // namespace

int runDepthLayers(const DepthLayersArgs& args) {
    DepthLayersRun run{args};
    if (const core::Status s = loadModelAndView(run); !s)
        return fail(s.error());
    if (const core::Status s = makeCapturerAndEngine(run); !s)
        return fail(s.error());
    if (const core::Status s = readDepthLayerOptions(run); !s)
        return fail(s.error());
    const core::MeshTopology topology = core::buildMeshTopology(run.mesh);
    auto layers = core::buildDepthLayers(*run.capturer, run.mesh, topology, run.view, run.options,
                                         run.engine.get());
    if (!layers)
        return fail(args.model + ": " + layers.error());
    run.layers = std::move(layers).value();

    const std::filesystem::path dir(args.outDir);
    if (const core::Status s = writeLayerFiles(run, dir); !s)
        return fail(s.error());
    const json summary = depthLayersSummary(run, connectivityQuality(run, topology));
    if (const core::Status s = writeVisible(dir, args, run.mesh, *run.capturer, run.engine.get(),
                                            run.options, std::move(run.layers), run.view);
        !s)
        return fail(s.error());
    if (const core::Status s = writeJson((dir / "summary.json").string(), summary); !s)
        return fail(s.error());
    std::cout << jsonText(summary, 1) << '\n';
    return 0;
}

} // namespace cli
