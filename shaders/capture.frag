#version 450 core
// Layer capture: appends every fragment to its pixel's linked list (a head per pixel, one global
// node counter). Depth test off, no color output: the framebuffer has no attachments.
in float vViewDepth;
flat in uint vTriangle;

// Pixels are numbered top row first (y = 0 at the top), as in core::LayerStack.
uniform int uWidth;
uniform int uHeight;
uniform uint uCapacity; // nodes that fit; the counter keeps counting past it

layout(std430, binding = 0) coherent buffer Counter {
    uint nodeCount;
};
layout(std430, binding = 1) coherent buffer Heads {
    uint heads[]; // 0xffffffff = empty list
};
// Node i: [3i] depth (float bits), [3i + 1] triangle id, [3i + 2] next node.
layout(std430, binding = 2) writeonly buffer Nodes {
    uint nodes[];
};

void main() {
    uint node = atomicAdd(nodeCount, 1u);
    // Past the capacity the draw only counts; the CPU grows the buffer and draws again.
    if (node >= uCapacity)
        return;
    ivec2 p = ivec2(gl_FragCoord.xy);
    uint pixel = uint(uHeight - 1 - p.y) * uint(uWidth) + uint(p.x);
    uint next = atomicExchange(heads[pixel], node);
    nodes[3u * node] = floatBitsToUint(vViewDepth);
    nodes[3u * node + 1u] = vTriangle;
    nodes[3u * node + 2u] = next;
}
