// SPDX-License-Identifier: GPL-3.0-or-later
// The two project versions the save-crash test and its helper write: the same small trefoil with
// a 512² texture of noise (so encoding and writing take a while) that differs per version.
#pragma once

#include <cstdint>
#include <string>

#include "core/io/project/project_file.h"
#include "core/model/builtin_models.h"
#include "core/model/mesh.h"

namespace save_crash {

struct Version {
    core::Mesh mesh;
    core::ProjectState state;
};

inline Version makeVersion(int which) {
    Version v;
    v.mesh = core::makeTrefoil(40, 12);
    core::Image page;
    page.width = page.height = 512;
    page.rgba.resize(std::size_t(page.width) * std::size_t(page.height) * 4);
    std::uint32_t x = 0x9E3779B9u * std::uint32_t(which + 1);
    for (std::size_t i = 0; i < page.rgba.size(); i += 4) {
        x = x * 1664525u + 1013904223u; // a fixed LCG: both processes make the same bytes
        page.rgba[i] = std::uint8_t(x >> 24);
        page.rgba[i + 1] = std::uint8_t(x >> 16);
        page.rgba[i + 2] = std::uint8_t(which * 100);
        page.rgba[i + 3] = 255;
    }
    v.mesh.textures = {std::move(page)};
    for (core::Material& m : v.mesh.materials) {
        m.baseColorTexture = 0;
        m.baseColorFactor = glm::vec4(1.0f);
    }
    v.state.source = which == 0 ? "version A" : "version B";
    v.state.brush.radius = which == 0 ? 10.0f : 20.0f;
    return v;
}

} // namespace save_crash
