// SPDX-License-Identifier: GPL-3.0-or-later
// The CPU side of the capture: the resolve, which sorts the GPU's fragment list straight from
// the mapped node buffers into a DepthStack, by band of pixels, each band by pixel and each
// pixel front to back (the GPU side is in depth_capture.cpp).
#include <algorithm>
#include <cstring>
#include <functional>
#include <new>

#include "render/depth_capture_impl.h"

namespace render {

namespace {
// The resolve sorts the nodes by band of 2^kBandShift pixels (about 8 rows of a 1920-pixel view),
// then each band by pixel: a band's counts and fragments stay in a core's cache.
constexpr unsigned kBandShift = 14;
constexpr std::size_t kBandPixels = std::size_t(1) << kBandShift;
// The passes over the list take it in slices of at least kSliceNodes nodes, at most kMaxSlices.
constexpr std::size_t kSliceNodes = std::size_t(1) << 16;
constexpr int kMaxSlices = 32;

// Float bits to an unsigned key with the same order (negative depths included), and back.
std::uint32_t sortableDepth(std::uint32_t bits) {
    return (bits & 0x80000000u) ? ~bits : bits | 0x80000000u;
}
std::uint32_t depthBits(std::uint32_t key) {
    return (key & 0x80000000u) ? key & 0x7fffffffu : ~key;
}

/** Sorts key[begin, end): by insertion when short (most pixels hold a few fragments). */
void sortKeys(std::uint64_t* key, std::size_t begin, std::size_t end) {
    if (end - begin > 16) {
        std::sort(key + begin, key + end);
        return;
    }
    for (std::size_t j = begin + 1; j < end; ++j) {
        const std::uint64_t k = key[j];
        std::size_t to = j;
        for (; to > begin && key[to - 1] > k; --to)
            key[to] = key[to - 1];
        key[to] = k;
    }
}
} // namespace

/**
 * One resolve: the ranges' nodes read as one list, in slices for the passes over the list and in
 * bands of pixels for the sort. Pass 1 counts each slice's nodes per band, the counts become
 * cursors, pass 2 scatters the nodes into their bands and pass 3 sorts each band.
 */
struct DepthCapture::Impl::Resolve {
    Impl& d;
    core::DepthStack& stack;
    std::size_t written = 0; // the ranges' nodes as one list
    std::size_t pixels = 0;
    std::size_t bandCount = 0;
    int slices = 1;
    // Where each band's fragments begin in the stack; [bandCount] is the total.
    std::vector<std::size_t> bandBegin;

    Resolve(Impl& impl, core::DepthStack& out) : d(impl), stack(out) {
        for (const NodeRange& range : d.ranges)
            written += range.written;
        pixels = std::size_t(stack.width) * std::size_t(stack.height);
        bandCount = (pixels + kBandPixels - 1) >> kBandShift;
        slices = int(std::clamp<std::size_t>(written / kSliceNodes, 1, kMaxSlices));
    }

    std::size_t sliceFirst(int s) const { return written * std::size_t(s) / std::size_t(slices); }

    /** Calls visit(words) for the nodes [first, last) of the list in order, chunk by chunk. */
    template <typename Visit> void forNodes(std::size_t first, std::size_t last, Visit&& visit) {
        const unsigned shift = d.chunkShift;
        const std::size_t mask = d.chunkNodes() - 1;
        const std::uint32_t* const* chunkWords = d.nodeData.data();
        std::size_t rangeBegins = 0;
        for (const NodeRange& range : d.ranges) {
            std::size_t node = range.first + std::max(first, rangeBegins) - rangeBegins;
            const std::size_t end =
                range.first + std::min(last, rangeBegins + range.written) - rangeBegins;
            rangeBegins += range.written;
            while (node < end) {
                const std::size_t chunkEnd = std::min(end, ((node >> shift) + 1) << shift);
                const std::uint32_t* words = chunkWords[node >> shift] + (node & mask) * 3;
                for (; node < chunkEnd; ++node, words += 3)
                    visit(words);
            }
        }
    }

    /** The working memory kept between captures, sized for this one. */
    void prepare() {
        stack.offsets.resize(pixels + 1);
        if (d.bands.size() < bandCount)
            d.bands.resize(bandCount);
        d.sliceCounts.assign(std::size_t(slices) * bandCount, 0);
        bandBegin.assign(bandCount + 1, 0);
    }

    /**
     * Pass 1, per slice of the list: its nodes in each band. A node naming no pixel of the view
     * (only a corrupt list has one) is left out here and below.
     */
    void countSlice(int s) {
        std::uint32_t* counts = d.sliceCounts.data() + std::size_t(s) * bandCount;
        forNodes(sliceFirst(s), sliceFirst(s + 1), [&](const std::uint32_t* words) {
            if (words[2] < pixels)
                ++counts[words[2] >> kBandShift];
        });
    }

    /**
     * Where each band's fragments begin, and each slice's within the band: the counts become
     * cursors. Returns the fragments of the view.
     */
    std::size_t placeSlices() {
        std::size_t total = 0;
        for (std::size_t b = 0; b < bandCount; ++b) {
            bandBegin[b] = total;
            for (int s = 0; s < slices; ++s) {
                std::uint32_t& count = d.sliceCounts[std::size_t(s) * bandCount + b];
                const std::uint32_t nodesHere = count;
                count = std::uint32_t(total);
                total += nodesHere;
            }
        }
        bandBegin[bandCount] = total;
        return total;
    }

    /**
     * Pass 2, per slice: the nodes into their band's range of the stack, unsorted, with their
     * pixel within the band.
     */
    void scatterSlice(int s) {
        std::uint32_t* cursors = d.sliceCounts.data() + std::size_t(s) * bandCount;
        float* depth = stack.depth.data();
        std::uint32_t* triangle = stack.triangle.data();
        std::uint16_t* pixelOf = d.pixelInBand.data();
        forNodes(sliceFirst(s), sliceFirst(s + 1), [&](const std::uint32_t* words) {
            const std::uint32_t pixel = words[2];
            if (pixel >= pixels)
                return;
            const std::uint32_t at = cursors[pixel >> kBandShift]++;
            std::memcpy(&depth[at], &words[0], sizeof(float));
            triangle[at] = words[1];
            pixelOf[at] = std::uint16_t(pixel & (kBandPixels - 1));
        });
    }

    void sortBand(int b);
    /** Fragments on each layer over the bands: [k - 1] for layer k. */
    std::vector<std::uint32_t> fragmentsPerLayer() const {
        std::vector<std::uint32_t> perLayer;
        for (std::size_t b = 0; b < bandCount; ++b) {
            const Band& band = d.bands[b];
            if (perLayer.size() < band.perLayer.size())
                perLayer.resize(band.perLayer.size(), 0);
            for (std::size_t k = 0; k < band.perLayer.size(); ++k)
                perLayer[k] += band.perLayer[k];
        }
        return perLayer;
    }
};

/**
 * Pass 3, per band: a counting sort by pixel, then each pixel's fragments front to back (ties by
 * triangle id), written back in place; the band's offsets.
 */
void DepthCapture::Impl::Resolve::sortBand(int b) {
    Band& band = d.bands[std::size_t(b)];
    band.perLayer.clear();
    const std::size_t first = bandBegin[std::size_t(b)], last = bandBegin[std::size_t(b) + 1];
    const std::size_t firstPixel = std::size_t(b) << kBandShift;
    const std::size_t bandPixels = std::min(kBandPixels, pixels - firstPixel);
    std::uint32_t* offsets = stack.offsets.data() + firstPixel;
    if (first == last) {
        std::fill(offsets, offsets + bandPixels, std::uint32_t(first));
        return;
    }
    thread_local std::vector<std::uint32_t> ends;
    thread_local std::vector<std::uint16_t> occupied; // the pixels with fragments
    thread_local std::vector<std::uint64_t> keys;
    ends.assign(bandPixels, 0);
    occupied.resize(bandPixels);
    const std::uint16_t* pixelOf = d.pixelInBand.data() + first;
    const std::size_t count = last - first;
    for (std::size_t k = 0; k < count; ++k)
        ++ends[pixelOf[k]];
    std::uint32_t at = 0;
    std::size_t used = 0;
    for (std::size_t i = 0; i < bandPixels; ++i) {
        // Eight empty pixels at a time: around a model most of a view's pixels are empty.
        if (std::uint64_t w[4]; i + 8 <= bandPixels) {
            std::memcpy(w, &ends[i], sizeof w);
            if ((w[0] | w[1] | w[2] | w[3]) == 0) {
                std::fill_n(offsets + i, 8, std::uint32_t(first) + at);
                i += 7;
                continue;
            }
        }
        const std::uint32_t n = ends[i];
        offsets[i] = std::uint32_t(first) + at;
        ends[i] = at; // the pixel's next free place
        occupied[used] = std::uint16_t(i);
        used += n != 0;
        at += n;
    }
    keys.resize(count);
    const float* depth = stack.depth.data() + first;
    const std::uint32_t* triangle = stack.triangle.data() + first;
    for (std::size_t k = 0; k < count; ++k) {
        std::uint32_t bits;
        std::memcpy(&bits, &depth[k], sizeof bits);
        keys[ends[pixelOf[k]]++] = std::uint64_t(sortableDepth(bits)) << 32 | triangle[k];
    }
    std::uint64_t* const key = keys.data();
    for (std::size_t u = 0; u < used; ++u) {
        const std::size_t i = occupied[u];
        const std::size_t begin = offsets[i] - first, end = ends[i], n = end - begin;
        sortKeys(key, begin, end);
        if (band.perLayer.size() < n)
            band.perLayer.resize(n, 0);
        for (std::size_t k = 0; k < n; ++k)
            ++band.perLayer[k];
    }
    float* outDepth = stack.depth.data() + first;
    std::uint32_t* outTriangle = stack.triangle.data() + first;
    for (std::size_t k = 0; k < count; ++k) {
        const std::uint32_t bits = depthBits(std::uint32_t(key[k] >> 32));
        std::memcpy(&outDepth[k], &bits, sizeof(float));
        outTriangle[k] = std::uint32_t(key[k]);
    }
}

core::Result<core::DepthStack> DepthCapture::Impl::resolve(const core::View& view,
                                                           Timings* timings) {
    core::DepthStack stack;
    stack.width = view.width;
    stack.height = view.height;
    Resolve pass(*this, stack);
    const core::Error outOfMemory{"layer capture: out of memory for the layer stack"};
    // Every allocation is in here: running out of memory is an error, not an abort.
    try {
        pass.prepare();
        if (!pool->run(pass.slices, [&pass](int s) { pass.countSlice(s); }))
            return outOfMemory;
        const std::size_t total = pass.placeSlices();
        stack.depth.resize(total);
        stack.triangle.resize(total);
        pixelInBand.resize(total);
        if (!pool->run(pass.slices, [&pass](int s) { pass.scatterSlice(s); }) ||
            !pool->run(int(pass.bandCount), [&pass](int b) { pass.sortBand(b); }))
            return outOfMemory;
        stack.offsets.back() = std::uint32_t(total);
        if (timings) {
            timings->fragments = total;
            timings->fragmentsPerLayer = pass.fragmentsPerLayer();
        }
    } catch (const std::bad_alloc&) {
        return outOfMemory;
    }
    return stack;
}

} // namespace render
