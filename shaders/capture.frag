#version 450 core
// Layer capture: appends every fragment, with its pixel, to a list of nodes (atomic counters).
// Depth test off, no color output: the framebuffer has no attachments. The CPU sorts the list
// by pixel and each pixel front to back; a per-pixel linked list (an atomic exchange on a head
// per pixel) would spare it the sort by pixel, but costs llvmpipe more than that sort.
in float vViewDepth;
flat in uint vTriangle;

// Pixels are numbered top row first (y = 0 at the top), as in core::DepthStack.
uniform int uWidth;
uniform int uHeight;
// The nodes are split into ranges, each with its own counter (16 words apart, a cache line
// each): a fragment takes a node of range (x / 64) & uRangeMask. llvmpipe's threads rasterize
// neighbouring 64-pixel tiles at once, so they seldom count on the same cache line.
uniform uint uRangeMask;
uniform uint uRangeStart[8];
uniform uint uRangeCapacity[8]; // nodes that fit; the counter keeps counting past it

layout(std430, binding = 0) coherent buffer Counter {
    uint nodeCount[];
};
// Node i (of any range): [3i] depth (float bits), [3i + 1] triangle id, [3i + 2] pixel. The
// nodes lie in NODE_CHUNKS buffers (bindings 1, 2, ...) of 2^uChunkShift nodes each, so no one
// storage block caps the list: node i is entry i & (2^uChunkShift - 1) of chunk i >> uChunkShift.
#ifndef NODE_CHUNKS
#define NODE_CHUNKS 1
#endif
uniform uint uChunkShift;
#define NODE_CHUNK(k)                                                                              \
    layout(std430, binding = 1 + k) writeonly buffer Nodes##k {                                    \
        uint nodes##k[];                                                                           \
    };
#define STORE_CHUNK(k)                                                                             \
    else if (chunk == uint(k)) {                                                                   \
        nodes##k[i] = depth;                                                                       \
        nodes##k[i + 1u] = triangle;                                                               \
        nodes##k[i + 2u] = pixel;                                                                  \
    }
NODE_CHUNK(0)
#if NODE_CHUNKS > 1
NODE_CHUNK(1)
#endif
#if NODE_CHUNKS > 2
NODE_CHUNK(2)
#endif
#if NODE_CHUNKS > 3
NODE_CHUNK(3)
#endif
#if NODE_CHUNKS > 4
NODE_CHUNK(4)
#endif
#if NODE_CHUNKS > 5
NODE_CHUNK(5)
#endif
#if NODE_CHUNKS > 6
NODE_CHUNK(6)
#endif
#if NODE_CHUNKS > 7
NODE_CHUNK(7)
#endif

void storeNode(uint node, uint depth, uint triangle, uint pixel) {
#if NODE_CHUNKS == 1
    uint i = 3u * node;
    nodes0[i] = depth;
    nodes0[i + 1u] = triangle;
    nodes0[i + 2u] = pixel;
#else
    uint chunk = node >> uChunkShift;
    uint i = 3u * (node & ((1u << uChunkShift) - 1u));
    if (false) {
    }
    STORE_CHUNK(0)
    STORE_CHUNK(1)
#if NODE_CHUNKS > 2
    STORE_CHUNK(2)
#endif
#if NODE_CHUNKS > 3
    STORE_CHUNK(3)
#endif
#if NODE_CHUNKS > 4
    STORE_CHUNK(4)
#endif
#if NODE_CHUNKS > 5
    STORE_CHUNK(5)
#endif
#if NODE_CHUNKS > 6
    STORE_CHUNK(6)
#endif
#if NODE_CHUNKS > 7
    STORE_CHUNK(7)
#endif
#endif
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    uint range = (uint(p.x) >> 6) & uRangeMask;
    uint local = atomicAdd(nodeCount[16u * range], 1u);
    // Past its capacity a range only counts; the CPU grows the buffers and draws again.
    if (local >= uRangeCapacity[range])
        return;
    uint node = uRangeStart[range] + local;
    uint pixel = uint(uHeight - 1 - p.y) * uint(uWidth) + uint(p.x);
    storeNode(node, floatBitsToUint(vViewDepth), vTriangle, pixel);
}
