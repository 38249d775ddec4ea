// SPDX-License-Identifier: GPL-3.0-or-later
// Meshes captured on the CPU in a view, for the tests of what comes after the capture:
// connectivity (the depth stack and the surface geometry) and painting (depth layers over a
// shared mesh, as paint targets hold it).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "core/depth/cpu_capture.h"
#include "core/depth/depth_layers.h"
#include "core/depth/depth_stack.h"
#include "core/depth/surface_geometry.h"
#include "core/model/camera.h"
#include "core/model/mesh.h"
#include "core/model/mesh_topology.h"

namespace core_test {

/** A mesh, its topology, and its depth stack and surface geometry in view. */
struct CapturedScene {
    std::string name; // says which scene in failure messages
    core::Mesh mesh;
    core::MeshTopology topology;
    core::View view;
    core::DepthStack stack;
    core::SurfaceGeometry geometry;
};

/** Captures mesh in view on the CPU (two threads), culling back faces or not. */
inline CapturedScene captureScene(core::Mesh mesh, const core::View& view, bool cull = true) {
    CapturedScene s;
    s.mesh = std::move(mesh);
    s.topology = core::buildMeshTopology(s.mesh);
    s.view = view;
    s.stack = core::captureDepthLayersCpu(s.mesh, view, {cull, 2});
    s.geometry = core::makeSurfaceGeometry(s.mesh, s.topology, view);
    return s;
}

/**
 * Whether pixel (x, y) of stack is a crossing: a surface on layer 1 more than 0.3 view units in
 * front of one on layer 2 (the built-in trefoil's strands where one passes over another).
 */
inline bool isCrossing(const core::DepthStack& stack, int x, int y) {
    if (x < 0 || y < 0 || x >= stack.width || y >= stack.height)
        return false;
    const std::size_t pixel = std::size_t(y) * std::size_t(stack.width) + std::size_t(x);
    const std::uint32_t front = stack.fragment(pixel, 1);
    const std::uint32_t back = stack.fragment(pixel, 2);
    return front != core::kNone && back != core::kNone &&
           stack.depth[back] - stack.depth[front] > 0.3f;
}

/** A mesh shared as paint targets take it, with its topology and its depth layers in a view. */
struct PaintScene {
    std::shared_ptr<core::Mesh> mesh;
    std::shared_ptr<core::MeshTopology> topology;
    core::DepthLayers layers;
};

/** Checks mesh and builds its depth layers in view with the CPU capturer. */
inline PaintScene paintScene(core::Mesh mesh, const core::View& view) {
    PaintScene scene;
    scene.mesh = std::make_shared<core::Mesh>(std::move(mesh));
    EXPECT_TRUE(scene.mesh->validate().ok());
    scene.topology = std::make_shared<core::MeshTopology>(core::buildMeshTopology(*scene.mesh));
    core::CpuDepthCapturer capturer;
    capturer.setMesh(*scene.mesh);
    auto layers = core::buildDepthLayers(capturer, *scene.mesh, *scene.topology, view, {});
    EXPECT_TRUE(layers.ok()) << layers.error();
    scene.layers = std::move(layers).value();
    return scene;
}

} // namespace core_test
