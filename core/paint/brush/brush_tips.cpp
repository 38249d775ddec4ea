// SPDX-License-Identifier: GPL-3.0-or-later
// The built-in brush tips, made in code, and the sampling of a tip for a dab.
#include "core/paint/brush/brush_tips.h"

#include <algorithm>
#include <array>
#include <numbers>

namespace core {

namespace {

constexpr int kBuiltinSide = 128;
constexpr std::array<std::string_view, 9> kNames = {
    "round", "round-soft", "round-hard", "square", "spatter", "chalk", "bristle", "star", "noise"};

float smoothEdge(float inside) { // inside: distance inside the edge, in texels
    return std::clamp(inside + 0.5f, 0.0f, 1.0f);
}

std::uint8_t toByte(float a) {
    return std::uint8_t(std::lround(std::clamp(a, 0.0f, 1.0f) * 255.0f));
}

/** A hash of a lattice point to [0, 1), for value noise. */
float latticeValue(int x, int y, std::uint64_t salt) {
    SplitMix64 r{(std::uint64_t(std::uint32_t(x)) << 32 | std::uint32_t(y)) ^ salt};
    return r.unit();
}

float valueNoise(float x, float y, std::uint64_t salt) {
    const float fx = std::floor(x), fy = std::floor(y);
    const int ix = int(fx), iy = int(fy);
    const float tx = x - fx, ty = y - fy;
    const float sx = tx * tx * (3.0f - 2.0f * tx), sy = ty * ty * (3.0f - 2.0f * ty);
    const float a = latticeValue(ix, iy, salt), b = latticeValue(ix + 1, iy, salt);
    const float c = latticeValue(ix, iy + 1, salt), d = latticeValue(ix + 1, iy + 1, salt);
    return (a + (b - a) * sx) + ((c + (d - c) * sx) - (a + (b - a) * sx)) * sy;
}

/** Fills a tip from f(x, y) with x, y in [-1, 1] (texel centres); f gives 0..1. */
template <typename F> TipImage makeTip(F f) {
    TipImage t;
    t.width = t.height = kBuiltinSide;
    t.alpha.resize(std::size_t(kBuiltinSide) * kBuiltinSide);
    const float half = 0.5f * float(kBuiltinSide);
    for (int y = 0; y < kBuiltinSide; ++y)
        for (int x = 0; x < kBuiltinSide; ++x) {
            const float u = (float(x) + 0.5f - half) / half, v = (float(y) + 0.5f - half) / half;
            t.alpha[std::size_t(y) * kBuiltinSide + std::size_t(x)] = toByte(f(u, v));
        }
    return t;
}

TipImage makeBuiltin(std::string_view name) {
    const float texel = 2.0f / float(kBuiltinSide); // one texel in [-1, 1] units
    if (name == "square")
        return makeTip([&](float u, float v) {
            return smoothEdge((0.68f - std::max(std::fabs(u), std::fabs(v))) / texel);
        });
    if (name == "spatter") {
        // Droplets of several sizes, denser towards the middle.
        struct Drop {
            float x, y, r;
        };
        std::vector<Drop> drops;
        SplitMix64 rng{0x5eed5a77e2ull};
        for (int i = 0; i < 34; ++i) {
            const float a = rng.unit() * 2.0f * std::numbers::pi_v<float>;
            const float d = 0.82f * std::sqrt(rng.unit());
            const float r = 0.03f + 0.14f * rng.unit() * (1.0f - 0.7f * d);
            drops.push_back({d * std::cos(a), d * std::sin(a), r});
        }
        return makeTip([&](float u, float v) {
            float a = 0.0f;
            for (const Drop& p : drops) {
                const float dist = std::hypot(u - p.x, v - p.y);
                a = std::max(a, smoothEdge((p.r - dist) / texel));
            }
            return a;
        });
    }
    if (name == "chalk")
        return makeTip([&](float u, float v) {
            const float d = std::hypot(u, v);
            const float disc = smoothEdge((0.9f - d) / (4.0f * texel));
            const float grain = 0.6f * valueNoise(u * 24.0f, v * 24.0f, 11) +
                                0.4f * valueNoise(u * 7.0f, v * 7.0f, 23);
            return disc * std::clamp((grain - 0.32f) * 2.4f, 0.0f, 1.0f);
        });
    if (name == "bristle") {
        // Hairs across the tip, each with its own strength and length.
        std::array<float, 24> strength{}, length{};
        SplitMix64 rng{0xb215713ull};
        for (std::size_t i = 0; i < strength.size(); ++i) {
            strength[i] = 0.45f + 0.55f * rng.unit();
            length[i] = 0.55f + 0.4f * rng.unit();
        }
        return makeTip([&](float u, float v) {
            const float s = (u + 0.85f) / 1.7f * float(strength.size());
            if (!(s >= 0.0f && s < float(strength.size())))
                return 0.0f;
            const auto i = std::size_t(s);
            const float across = std::fabs(s - float(i) - 0.5f); // 0 mid-hair .. 0.5 between
            const float hair = std::clamp((0.38f - across) * 6.0f, 0.0f, 1.0f);
            const float edge = std::sqrt(std::max(0.0f, 0.85f * 0.85f - u * u)) * length[i];
            return hair * strength[i] * smoothEdge((edge - std::fabs(v)) / (3.0f * texel));
        });
    }
    if (name == "star")
        return makeTip([&](float u, float v) {
            const float d = std::hypot(u, v);
            const float a = std::atan2(v, u) + 0.5f * std::numbers::pi_v<float>;
            const float c = 0.5f + 0.5f * std::cos(5.0f * a);
            const float edge = 0.36f + 0.52f * c * c * c;
            return smoothEdge((edge - d) / texel);
        });
    if (name == "noise")
        return makeTip([&](float u, float v) {
            const float d = std::hypot(u, v);
            const float disc = std::clamp((0.92f - d) / 0.3f, 0.0f, 1.0f);
            const int x = int((u + 1.0f) * 0.5f * kBuiltinSide),
                      y = int((v + 1.0f) * 0.5f * kBuiltinSide);
            return disc * latticeValue(x, y, 0x7015e);
        });
    return {};
}

} // namespace

const char* tipAngleModeName(TipAngleMode mode) {
    switch (mode) {
    case TipAngleMode::Stroke:
        return "stroke";
    case TipAngleMode::Random:
        return "random";
    case TipAngleMode::Fixed:
        break;
    }
    return "fixed";
}

bool tipAngleModeFromName(std::string_view name, TipAngleMode& mode) {
    for (const TipAngleMode m : {TipAngleMode::Fixed, TipAngleMode::Stroke, TipAngleMode::Random})
        if (name == tipAngleModeName(m)) {
            mode = m;
            return true;
        }
    return false;
}

std::span<const std::string_view> builtinTipNames() {
    return kNames;
}

bool isBuiltinTip(std::string_view name) {
    return std::find(kNames.begin(), kNames.end(), name) != kNames.end();
}

TipCharacter tipCharacter(std::string_view name) {
    TipCharacter c;
    if (name == "spatter") {
        c = {0.5f, TipAngleMode::Random, {0.5f, 0.0f, 0.0f, 1.0f}};
    } else if (name == "chalk") {
        c = {0.25f, TipAngleMode::Random, {0.1f, 0.4f, 0.0f, 0.0f}};
    } else if (name == "bristle") {
        c = {0.1f, TipAngleMode::Stroke, {}};
    } else if (name == "star") {
        c = {0.9f, TipAngleMode::Random, {0.3f, 0.0f, 0.0f, 0.5f}};
    } else if (name == "noise") {
        c = {0.3f, TipAngleMode::Random, {0.0f, 0.2f, 0.0f, 0.0f}};
    }
    return c;
}

const TipImage* builtinTipImage(std::string_view name) {
    // Made once, on first use; the round tips (the first three) have none.
    static const std::array<TipImage, kNames.size()> images = [] {
        std::array<TipImage, kNames.size()> a;
        for (std::size_t i = 3; i < kNames.size(); ++i)
            a[i] = makeBuiltin(kNames[i]);
        return a;
    }();
    for (std::size_t i = 3; i < kNames.size(); ++i)
        if (kNames[i] == name)
            return &images[i];
    return nullptr;
}

TipImage tipFromRgba(int width, int height, std::span<const std::uint8_t> rgba) {
    TipImage t;
    if (width <= 0 || height <= 0 || rgba.size() < std::size_t(width) * std::size_t(height) * 4)
        return t;
    // Box-filter down by a whole factor so that the longer side fits kMaxTipSide.
    const int factor = (std::max(width, height) + kMaxTipSide - 1) / kMaxTipSide;
    t.width = (width + factor - 1) / factor;
    t.height = (height + factor - 1) / factor;
    t.alpha.resize(std::size_t(t.width) * std::size_t(t.height));
    for (int y = 0; y < t.height; ++y)
        for (int x = 0; x < t.width; ++x) {
            double sum = 0.0;
            int n = 0;
            for (int sy = y * factor; sy < std::min(height, (y + 1) * factor); ++sy)
                for (int sx = x * factor; sx < std::min(width, (x + 1) * factor); ++sx) {
                    const std::uint8_t* p =
                        &rgba[(std::size_t(sy) * std::size_t(width) + std::size_t(sx)) * 4];
                    const double luma = (0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]) / 255.0;
                    sum += (1.0 - luma) * (p[3] / 255.0);
                    ++n;
                }
            t.alpha[std::size_t(y) * std::size_t(t.width) + std::size_t(x)] =
                std::uint8_t(std::lround(255.0 * sum / double(n)));
        }
    return t;
}

void TipSampler::setup(const TipImage* image, float hardness, float radius, float angle) {
    m_image = image && image->width > 0 && image->height > 0 ? image : nullptr;
    m_hardness = hardness;
    m_radius = radius;
    if (!m_image)
        return;
    m_cos = std::cos(angle);
    m_sin = std::sin(angle);
    m_halfW = 0.5f * float(m_image->width);
    m_halfH = 0.5f * float(m_image->height);
    m_scaleX = radius > 0.0f ? m_halfW / radius : 0.0f;
    m_scaleY = radius > 0.0f ? m_halfH / radius : 0.0f;
}

float TipSampler::sample(float x, float y) const {
    const int w = m_image->width, h = m_image->height;
    const float fx = std::floor(x), fy = std::floor(y);
    const int x0 = int(fx), y0 = int(fy);
    const float tx = x - fx, ty = y - fy;
    const std::uint8_t* a = m_image->alpha.data();
    // Texels outside the image are empty.
    auto at = [&](int xi, int yi) -> float {
        return xi >= 0 && yi >= 0 && xi < w && yi < h
                   ? float(a[std::size_t(yi) * std::size_t(w) + std::size_t(xi)])
                   : 0.0f;
    };
    const float top = at(x0, y0) + (at(x0 + 1, y0) - at(x0, y0)) * tx;
    const float bottom = at(x0, y0 + 1) + (at(x0 + 1, y0 + 1) - at(x0, y0 + 1)) * tx;
    return (top + (bottom - top) * ty) * (1.0f / 255.0f);
}

} // namespace core
