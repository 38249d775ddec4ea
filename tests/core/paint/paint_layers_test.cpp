// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/paint/paint_layers/paint_layers.h"

namespace paint_layers_test {

using core::BlendMode;
using core::PaintChannel;
using core::PaintLayerKind;
using core::PaintLayerSettings;
using core::PaintLayerStack;

constexpr int kW = 100, kH = 70; // two tiles across and down, the edge ones partial

core::PaintLayerStack makeStack(bool material = true) {
    std::vector<std::uint8_t> color(std::size_t(kW) * kH * 4), mr(std::size_t(kW) * kH * 4);
    for (std::size_t i = 0; i < color.size(); i += 4) {
        color[i] = 100, color[i + 1] = 150, color[i + 2] = 200, color[i + 3] = 255;
        mr[i] = 255, mr[i + 1] = 200, mr[i + 2] = 30, mr[i + 3] = 255;
    }
    std::vector<std::vector<std::uint8_t>> mrPages;
    if (material)
        mrPages.push_back(mr);
    return PaintLayerStack({{kW, kH}}, {color}, mrPages);
}

PaintLayerSettings settings(const char* name, BlendMode mode = BlendMode::Normal,
                            float opacity = 1.0f) {
    PaintLayerSettings s;
    s.name = name;
    s.blend = mode;
    s.opacity = opacity;
    return s;
}

void put(core::TiledPlane& plane, int x, int y, std::initializer_list<std::uint8_t> bytes) {
    std::uint8_t* t = plane.writableTexel(0, x, y);
    for (std::uint8_t b : bytes)
        *t++ = b;
}

const std::uint8_t* composite(const PaintLayerStack& s, int x, int y) {
    return s.compositeBaseColor(0).data() + (std::size_t(y) * kW + std::size_t(x)) * 4;
}
const std::uint8_t* compositeMr(const PaintLayerStack& s, int x, int y) {
    return s.compositeMetallicRoughness(0).data() + (std::size_t(y) * kW + std::size_t(x)) * 4;
}

int byteOf(float v) {
    return int(std::lround(v * 255.0f));
}

TEST(PaintLayerStack, CompositeFollowsTheBlendFormulaWithOpacityAndCoverage) {
    PaintLayerStack s = makeStack();
    s.add(settings("multiply", BlendMode::Multiply, 0.5f), 0);
    put(*s.channelPlane(0, PaintChannel::BaseColor), 80, 66, {128, 64, 255, 255});
    s.add(settings("screen", BlendMode::Screen), 1);
    put(*s.channelPlane(1, PaintChannel::BaseColor), 80, 66, {40, 40, 40, 102}); // 40 % covers
    s.updateAll();

    const float base[3] = {100 / 255.f, 150 / 255.f, 200 / 255.f};
    const float mul[3] = {128 / 255.f, 64 / 255.f, 1.0f};
    const std::uint8_t* c = composite(s, 80, 66);
    for (int k = 0; k < 3; ++k) {
        float v = base[k] + 0.5f * (core::blend(BlendMode::Multiply, base[k], mul[k]) - base[k]);
        v += (102 / 255.f) * (core::blend(BlendMode::Screen, v, 40 / 255.f) - v);
        EXPECT_NEAR(c[k], byteOf(v), 1) << k;
    }
    EXPECT_EQ(c[3], 255);
    // Elsewhere (other tiles too) the base shows unchanged.
    EXPECT_EQ(composite(s, 0, 0)[0], 100);
    EXPECT_EQ(composite(s, 99, 69)[2], 200);
    EXPECT_EQ(compositeMr(s, 80, 66)[1], 200);
    EXPECT_EQ(compositeMr(s, 80, 66)[2], 30);
}

TEST(PaintLayerStack, MasksHiddenLayersAndFillLayers) {
    PaintLayerStack s = makeStack();
    PaintLayerSettings fill = settings("rough");
    fill.kind = PaintLayerKind::Fill;
    fill.fill.roughness = 0.2f;
    s.add(fill, 0);
    put(s.maskPlane(0), 10, 10, {0});   // hidden there
    put(s.maskPlane(0), 11, 10, {128}); // half
    s.updateAll();
    EXPECT_EQ(compositeMr(s, 50, 50)[1], byteOf(0.2f)); // everywhere else: the fill value
    EXPECT_EQ(compositeMr(s, 10, 10)[1], 200);          // masked: the base
    EXPECT_NEAR(compositeMr(s, 11, 10)[1], byteOf(200 / 255.f + 128 / 255.f * (0.2f - 200 / 255.f)),
                1);
    EXPECT_EQ(compositeMr(s, 50, 50)[2], 30); // metallic left alone
    EXPECT_EQ(composite(s, 50, 50)[0], 100);  // so is the base colour

    PaintLayerSettings hidden = s.layer(0).settings;
    hidden.visible = false;
    s.setSettings(0, hidden);
    s.updateAll();
    EXPECT_EQ(compositeMr(s, 50, 50)[1], 200);
}

TEST(PaintLayerStack, VertexColourStacksHaveBaseColourOnly) {
    PaintLayerStack s = makeStack(false);
    s.add(settings("a"), 0);
    EXPECT_FALSE(s.hasMaterialChannels());
    EXPECT_EQ(s.channelPlane(0, PaintChannel::Roughness), nullptr);
    EXPECT_NE(s.channelPlane(0, PaintChannel::BaseColor), nullptr);
    EXPECT_TRUE(s.compositeMetallicRoughness(0).empty());
}

/**
 * Merges an upper layer (mode, opacity 0.6, a mask) into a normal lower one whose coverage is
 * lowerCoverage(x) and returns the largest composite difference it made.
 */
int mergeDownChange(BlendMode mode, std::uint8_t (*lowerCoverage)(int)) {
    PaintLayerStack s = makeStack();
    s.add(settings("lower"), 0);
    s.add(settings("upper", mode, 0.6f), 1);
    for (int x = 0; x < 90; ++x) {
        put(*s.channelPlane(0, PaintChannel::BaseColor), x, 5,
            {std::uint8_t(2 * x), 200, 10, lowerCoverage(x)});
        put(*s.channelPlane(0, PaintChannel::Metallic), x, 5, {100, lowerCoverage(x)});
        // A normal upper layer also reaches past the lower one.
        const int shift = mode == BlendMode::Normal ? 5 : 0;
        put(*s.channelPlane(1, PaintChannel::BaseColor), x + shift, 5, {90, 255, 128, 200});
        put(*s.channelPlane(1, PaintChannel::Metallic), x, 5, {255, std::uint8_t(x * 2)});
    }
    put(s.maskPlane(1), 30, 5, {60});
    s.updateAll();
    const std::vector<std::uint8_t> before = s.compositeBaseColor(0);
    const std::vector<std::uint8_t> beforeMr = s.compositeMetallicRoughness(0);
    const std::uint64_t lowerId = s.layer(0).id;

    EXPECT_TRUE(s.mergeDown(1));
    EXPECT_EQ(s.size(), 1u);
    EXPECT_EQ(s.layer(0).id, lowerId);
    EXPECT_EQ(s.layer(0).settings.name, "lower");
    EXPECT_EQ(s.layer(0).mask, nullptr);
    EXPECT_FALSE(s.mergeDown(0));
    s.updateAll();
    const std::vector<std::uint8_t>& after = s.compositeBaseColor(0);
    const std::vector<std::uint8_t>& afterMr = s.compositeMetallicRoughness(0);
    int worst = 0;
    for (std::size_t i = 0; i < before.size(); ++i) {
        worst = std::max(worst, std::abs(int(before[i]) - int(after[i])));
        worst = std::max(worst, std::abs(int(beforeMr[i]) - int(afterMr[i])));
    }
    return worst;
}

TEST(PaintLayerStack, MergeDownKeepsTheCompositeOverANormalLayer) {
    auto partial = [](int x) { return std::uint8_t(255 - 2 * x); };
    auto opaque = [](int) { return std::uint8_t(255); };
    // A normal upper layer merges exactly (up to 8-bit rounding) over any lower coverage; any
    // mode does where the lower layer covers fully. (Where the lower layer is partly
    // transparent, a multiply would also darken what is under it, which one layer cannot hold:
    // the merged layer keeps the multiply of the lower layer's own colour, as painters do.)
    EXPECT_LE(mergeDownChange(BlendMode::Normal, partial), 2);
    EXPECT_LE(mergeDownChange(BlendMode::Multiply, opaque), 2);
    EXPECT_LE(mergeDownChange(BlendMode::SoftLight, opaque), 2);
}

TEST(PaintLayerStack, FlattenGivesTheSameCompositeAndDropsHiddenLayers) {
    PaintLayerStack s = makeStack();
    s.add(settings("a", BlendMode::Overlay, 0.7f), 0);
    s.add(settings("b", BlendMode::Difference), 1);
    s.add(settings("hidden"), 2);
    for (int x = 0; x < kW; x += 3) {
        put(*s.channelPlane(0, PaintChannel::BaseColor), x, x % kH, {250, 10, 90, 255});
        put(*s.channelPlane(1, PaintChannel::BaseColor), x, (x + 1) % kH, {30, 60, 90, 128});
        put(*s.channelPlane(1, PaintChannel::Roughness), x, x % kH, {10, 255});
        put(*s.channelPlane(2, PaintChannel::BaseColor), x, x % kH, {0, 0, 0, 255});
    }
    PaintLayerSettings hidden = s.layer(2).settings;
    hidden.visible = false;
    s.setSettings(2, hidden);
    s.updateAll();
    const std::vector<std::uint8_t> before = s.compositeBaseColor(0);
    const std::vector<std::uint8_t> beforeMr = s.compositeMetallicRoughness(0);
    s.flatten("flat");
    ASSERT_EQ(s.size(), 1u);
    EXPECT_EQ(s.layer(0).settings.name, "flat");
    s.updateAll();
    EXPECT_EQ(s.compositeBaseColor(0), before);
    EXPECT_EQ(s.compositeMetallicRoughness(0), beforeMr);
}

TEST(PaintLayerStack, LayerOperationsKeepIdsAndOrder) {
    PaintLayerStack s = makeStack();
    s.add(settings("a"), 0);
    s.add(settings("b"), 1);
    put(*s.channelPlane(1, PaintChannel::BaseColor), 3, 3, {1, 2, 3, 255});
    const std::size_t copy = s.duplicate(1);
    EXPECT_EQ(copy, 2u);
    EXPECT_EQ(s.layer(2).settings.name, "b copy");
    EXPECT_NE(s.layer(2).id, s.layer(1).id);
    EXPECT_EQ(s.layer(2).channels[0]->texel(0, 3, 3)[2], 3);
    // The copy is independent.
    put(*s.channelPlane(2, PaintChannel::BaseColor), 3, 3, {9, 9, 9, 255});
    EXPECT_EQ(s.layer(1).channels[0]->texel(0, 3, 3)[0], 1);

    const std::uint64_t idA = s.layer(0).id;
    s.move(0, 2);
    EXPECT_EQ(s.layer(2).id, idA);
    EXPECT_EQ(s.indexOf(idA), 2u);
    std::unique_ptr<core::PaintLayer> taken = s.take(2);
    EXPECT_EQ(s.size(), 2u);
    EXPECT_FALSE(s.indexOf(idA).has_value());
    s.insert(std::move(taken), 0);
    EXPECT_EQ(s.indexOf(idA), 0u);
    // A new layer never reuses an id that is in the stack.
    const std::size_t added = s.add(settings("c"), 3);
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_NE(s.layer(added).id, s.layer(i).id);
}

TEST(PaintLayerStack, MemoryGrowsWithWhatIsPaintedNotWithLayers) {
    constexpr int kSize = 4096;
    PaintLayerStack s({{kSize, kSize}}, {}, {{}});
    for (int l = 0; l < 8; ++l) {
        s.add(settings("layer"), std::size_t(l));
        // A few strokes: three diagonal bands of dabs, about 1,000 px long each.
        for (int stroke = 0; stroke < 3; ++stroke)
            for (int t = 0; t < 1000; t += 8)
                put(*s.channelPlane(std::size_t(l), PaintChannel::BaseColor),
                    (500 * l + 300 * stroke + t) % kSize, (700 * stroke + t + 97 * l) % kSize,
                    {255, 0, 0, 255});
        put(*s.channelPlane(std::size_t(l), PaintChannel::Roughness), 2000, 2000 + l, {10, 255});
    }
    const std::size_t oneLayer = std::size_t(kSize) * kSize * 4;
    EXPECT_GT(s.layerBytes(), 0u);
    EXPECT_LT(s.layerBytes(), oneLayer * 3 / 2);
    EXPECT_LT(s.layerBytes(), oneLayer / 4); // in fact far less
}

TEST(PaintTexel, SourceOverLockTransparencyAndErase) {
    const float red[3] = {1.0f, 0.0f, 0.0f};
    std::uint8_t start[4] = {0, 0, 255, 0}, out[4];
    core::paintTexel(out, start, 3, red, 0.5f, false);
    EXPECT_EQ(out[0], 255); // a transparent start takes the paint's colour
    EXPECT_EQ(out[2], 0);
    EXPECT_EQ(out[3], 128);

    const std::uint8_t half[4] = {0, 0, 255, 128};
    core::paintTexel(out, half, 3, red, 0.5f, false);
    EXPECT_EQ(out[3], byteOf(0.5f + (128 / 255.f) * 0.5f));
    EXPECT_GT(out[0], 128); // more red than blue: the new paint is on top
    EXPECT_LT(out[2], 128);

    core::paintTexel(out, start, 3, red, 1.0f, true); // locked, nothing there: nothing changes
    EXPECT_EQ(std::vector<std::uint8_t>(out, out + 4), std::vector<std::uint8_t>(start, start + 4));
    core::paintTexel(out, half, 3, red, 0.5f, true); // locked: colour moves, coverage stays
    EXPECT_EQ(out[3], 128);
    EXPECT_EQ(out[0], 128);
    EXPECT_EQ(out[2], 128);

    const std::uint8_t rough[2] = {40, 200};
    std::uint8_t erased[2];
    core::eraseTexel(erased, rough, 1, 0.25f);
    EXPECT_EQ(erased[0], 40);
    EXPECT_EQ(erased[1], 150);
}

// A texel that held nothing at the stroke's start takes emptyTexelByte() where it is known,
// without the arithmetic: the bytes must be those of the arithmetic, for every brush value a
// colour byte gives, values on and near a byte's rounding boundary (roughness 0.3, 0.5) and
// coverages from the least the short cut takes to 1.
TEST(PaintTexel, EmptyTexelBytesAreThoseOfTheArithmetic) {
    std::vector<float> values = {0.0f, 1.0f, 0.5f, 0.25f, 0.3f, 0.7f, 0.125f, 1e-20f, 0x1p-60f};
    for (int k = 0; k <= 255; ++k) {
        values.push_back(float(k) / 255.0f);
        // Half way between two bytes, and a step either side of it.
        const float boundary = (float(k) + 0.5f) / 255.0f;
        values.push_back(boundary);
        values.push_back(std::nextafter(boundary, 0.0f));
        values.push_back(std::nextafter(boundary, 1.0f));
    }
    std::vector<float> coverages = {1.0f,
                                    std::nextafter(1.0f, 0.0f),
                                    0.5f,
                                    core::kEmptyTexelMinCoverage,
                                    std::nextafter(core::kEmptyTexelMinCoverage, 1.0f),
                                    1e-10f};
    std::uint32_t seed = 12345u;
    for (int i = 0; i < 4000; ++i) {
        seed = seed * 1664525u + 1013904223u;
        coverages.push_back(float(seed >> 8) / float(1u << 24) + 1e-7f);
    }
    int known = 0;
    const std::uint8_t empty[2] = {77, 0};
    for (const float value : values) {
        const std::int16_t byte = core::emptyTexelByte(value);
        known += byte >= 0 ? 1 : 0;
        for (const float a : coverages) {
            std::uint8_t plain[2], fast[2];
            core::paintTexel(plain, empty, 1, &value, a, false);
            core::paintTexel(fast, empty, 1, &value, a, false, &byte);
            ASSERT_EQ(plain[0], fast[0]) << "value " << value << " coverage " << a;
            ASSERT_EQ(plain[1], fast[1]);
        }
    }
    // The colour bytes, 0, 1 and powers of two are known; values on a boundary are not.
    EXPECT_GT(known, 256);
    EXPECT_EQ(core::emptyTexelByte(0.5f), 128);
    EXPECT_EQ(core::emptyTexelByte(200.0f / 255.0f), 200);
    EXPECT_EQ(core::emptyTexelByte(std::nextafter(128.5f / 255.0f, 1.0f)), -1);
    EXPECT_EQ(core::emptyTexelByte(-0.1f), -1);

    // A texel that held paint takes the arithmetic whatever empty says.
    const std::uint8_t painted[2] = {77, 40};
    const float value = 0.5f;
    const std::int16_t wrong = 3;
    std::uint8_t plain[2], fast[2];
    core::paintTexel(plain, painted, 1, &value, 0.4f, false);
    core::paintTexel(fast, painted, 1, &value, 0.4f, false, &wrong);
    EXPECT_EQ(plain[0], fast[0]);
    EXPECT_EQ(plain[1], fast[1]);
}

#if defined(__SSE2__)
// The composite's four-lane byte conversions give toByte() and fromByte() of each lane: every
// byte, values at, beside and between every rounding boundary, out of range, and 2M random ones.
TEST(LayerBytes, FourLanesAreThoseOfOne) {
    using core::layer_bytes::fromByte;
    using core::layer_bytes::toByte;
    for (int b = 0; b < 256; b += 4) {
        const std::uint8_t bytes[4] = {std::uint8_t(b), std::uint8_t(b + 1), std::uint8_t(b + 2),
                                       std::uint8_t(b + 3)};
        alignas(16) float lanes[4];
        _mm_store_ps(lanes, core::layer_bytes::fromBytes4(bytes));
        for (int k = 0; k < 4; ++k)
            ASSERT_EQ(lanes[k], fromByte(bytes[k]));
    }
    std::vector<float> values = {-1.0f, -0.0f, 0.0f, 1.0f, 1.5f, 1e-30f, 2.0f, 1e30f};
    for (int k = 0; k <= 255; ++k)
        for (const float at : {float(k) / 255.0f, (float(k) + 0.5f) / 255.0f}) {
            float below = at, above = at;
            for (int step = 0; step < 4; ++step) {
                below = std::nextafter(below, -1.0f);
                above = std::nextafter(above, 2.0f);
                values.insert(values.end(), {below, above});
            }
            values.push_back(at);
        }
    std::uint32_t seed = 99u;
    for (int i = 0; i < 2000000; ++i) {
        seed = seed * 1664525u + 1013904223u;
        values.push_back(float(seed >> 8) / float(1u << 24) * 1.2f - 0.1f);
    }
    while (values.size() % 4 != 0)
        values.push_back(0.5f);
    for (std::size_t i = 0; i < values.size(); i += 4) {
        alignas(16) std::int32_t bytes[4];
        _mm_store_si128(reinterpret_cast<__m128i*>(bytes),
                        core::layer_bytes::toBytes4(_mm_loadu_ps(&values[i])));
        for (std::size_t k = 0; k < 4; ++k)
            ASSERT_EQ(bytes[k], toByte(values[i + k])) << "value " << values[i + k];
    }
}
#endif

// paintTexel() takes a short cut at full coverage; its bytes are those of the source-over
// arithmetic (written out here) for every start byte and coverage byte, and values on and beside
// every rounding boundary.
/** Source-over of value with coverage a over a component c0 of coverage a0 (bytes), written out. */
std::pair<std::uint8_t, std::uint8_t> sourceOver(std::uint8_t c0, std::uint8_t a0Byte, float value,
                                                 float a) {
    using core::layer_bytes::fromByte;
    using core::layer_bytes::toByte;
    const float a0 = fromByte(a0Byte);
    const float out = a + a0 * (1.0f - a);
    const float premultiplied = a * value + (1.0f - a) * a0 * fromByte(c0);
    return std::pair(toByte(out > 0.0f ? premultiplied / out : 0.0f), toByte(out));
}

/** Brush values: 0, 1, a tiny one, every byte's value, and on and beside every rounding boundary.
 */
std::vector<float> boundaryValues() {
    std::vector<float> values = {0.0f, 1.0f, 1e-20f};
    for (int k = 0; k <= 255; ++k) {
        const float boundary = (float(k) + 0.5f) / 255.0f;
        values.insert(values.end(), {float(k) / 255.0f, boundary, std::nextafter(boundary, 0.0f),
                                     std::nextafter(boundary, 1.0f)});
    }
    return values;
}

TEST(PaintTexel, FullCoverageBytesAreThoseOfTheArithmetic) {
    const auto arithmetic = [](const std::uint8_t start[2], float value, float a) {
        return sourceOver(start[0], start[1], value, a);
    };
    const std::vector<float> values = boundaryValues();
    int checked = 0;
    for (int colour = 0; colour <= 255; colour += 5)
        for (int cover = 0; cover <= 255; ++cover) {
            const std::uint8_t start[2] = {std::uint8_t(colour), std::uint8_t(cover)};
            for (const float value : values)
                for (const float a : {1.0f, std::nextafter(1.0f, 0.0f), 0.5f}) {
                    std::uint8_t texel[2];
                    core::paintTexel(texel, start, 1, &value, a, false);
                    const auto [c, alpha] = arithmetic(start, value, a);
                    ASSERT_EQ(texel[0], c) << "value " << value << " start " << colour << ", "
                                           << cover << " coverage " << a;
                    ASSERT_EQ(texel[1], alpha);
                    ++checked;
                }
        }
    EXPECT_GT(checked, 1000000);
}

// A colour texel and a pair of one-component texels (roughness and metallic) are painted in
// lanes where the build has them: the bytes are those of the arithmetic written out, component
// by component, for every coverage byte, values on and beside every rounding boundary and
// coverages 0, 1, 1 - ulp and between. A texel not given is not written.
TEST(PaintTexel, LanesAreThoseOfTheArithmetic) {
    const std::vector<float> values = boundaryValues();
    const std::size_t n = values.size();
    long checked = 0;
    for (int colour = 0; colour <= 255; colour += 15)
        for (int cover = 0; cover <= 255; ++cover)
            for (std::size_t i = 0; i < n; ++i)
                for (const float a : {1.0f, std::nextafter(1.0f, 0.0f), 0.5f, 0.123f, 0.0f}) {
                    const float value[3] = {values[i], values[(i + 7) % n], values[(i + 13) % n]};
                    const std::uint8_t start[4] = {std::uint8_t(colour), std::uint8_t(255 - colour),
                                                   std::uint8_t(colour / 3), std::uint8_t(cover)};
                    std::uint8_t texel[4];
                    core::paintTexelOf<3>(texel, start, value, a, false);
                    for (int k = 0; k < 3; ++k)
                        ASSERT_EQ(texel[k], sourceOver(start[k], start[3], value[k], a).first)
                            << "component " << k << " value " << value[k] << " start "
                            << int(start[k]) << ", " << cover << " coverage " << a;
                    ASSERT_EQ(texel[3], sourceOver(0, start[3], 0.0f, a).second);

                    const std::uint8_t first[2] = {std::uint8_t(colour), std::uint8_t(cover)};
                    const std::uint8_t second[2] = {std::uint8_t(255 - colour),
                                                    std::uint8_t(255 - cover)};
                    std::uint8_t one[2], other[2];
                    core::paintTexelPair(one, other, first, second, value, a, false);
                    ASSERT_EQ(std::pair(one[0], one[1]),
                              sourceOver(first[0], first[1], value[0], a));
                    ASSERT_EQ(std::pair(other[0], other[1]),
                              sourceOver(second[0], second[1], value[1], a));
                    ++checked;
                }
    EXPECT_GT(checked, 10000000);

    std::uint8_t kept[2] = {1, 2};
    const std::uint8_t start[2] = {100, 100};
    const float value[2] = {0.5f, 0.5f};
    core::paintTexelPair(nullptr, kept, start, start, value, 0.5f, false);
    EXPECT_EQ(std::pair(kept[0], kept[1]), sourceOver(100, 100, 0.5f, 0.5f));
    kept[0] = kept[1] = 7;
    core::paintTexelPair(kept, nullptr, start, start, value, 0.5f, true); // locked: colour moves
    EXPECT_EQ(kept[1], 100);
}

} // namespace paint_layers_test
