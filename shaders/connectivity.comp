#version 450 core
// Pixel-level connectivity (docs/architecture.md §3 step 2): the GPU twin of core::computeConnectivity,
// which must give the same bytes. One invocation per fragment, not per pixel: llvmpipe caps the
// loop iterations of an invocation (it stopped after some 32 thousand), which a pixel of 255
// layers looping over a neighbour's 255 would exceed. Every decision mirrors
// core/connectivity.cpp, with these rules so that the floats match bit for bit:
// - every float result is `precise` (no fused multiply-add, no reordering) and is written in the
//   reference's evaluation order (glm::dot(a, b) is (a.x*b.x + a.y*b.y) + a.z*b.z);
// - a pair is always scored with the reference's orientation, the left or upper pixel as side a,
//   whichever pixel's invocation asks;
// - NaN is never produced on purpose: the reference's "NaN plane depth" is an explicit flag, and
//   NaN tests look at the bits, which no compiler rewrites.
layout(local_size_x = 64) in;

// The core::DepthStack: fragments of pixel p are [offsets[p], offsets[p + 1]).
layout(std430, binding = 0) readonly buffer Offsets {
    uint offsets[];
};
layout(std430, binding = 1) readonly buffer Depths {
    float depths[];
};
layout(std430, binding = 2) readonly buffer FragmentTriangles {
    uint fragmentTriangles[];
};
// core::SurfaceTriangle by triangle id, as stored on the CPU: plane, welded corners, component.
struct Triangle {
    vec4 plane;
    uvec4 topology; // corners (xyz) and component (w)
};
layout(std430, binding = 3) readonly buffer Triangles {
    Triangle triangles[];
};
// Per fragment, core::Connectivity::links as one little-endian word: right, left, up, down.
layout(std430, binding = 4) writeonly buffer Links {
    uint links[];
};
// Per fragment: its pixel (filled on the CPU while checking the offsets).
layout(std430, binding = 5) readonly buffer FragmentPixels {
    uint fragmentPixels[];
};

uniform ivec2 uSize;
uniform uint uFragmentCount;
uniform uint uRowInvocations; // invocations per row of work groups (the dispatch is 2D if large)
uniform uint uTriangleCount; // 0 for the Plain test: no triangle is known
// The Linker's limits, computed on the CPU exactly as the reference computes them.
uniform float uLimit;
uniform float uContactLimit;
uniform float uCreaseCos;
uniform float uSmoothCos;
uniform float uMinRayCosine2; // kMinRayCosine * kMinRayCosine
uniform float uFail;          // +infinity
// core::PixelRays
uniform vec3 uOrigin0;
uniform vec3 uOriginDx;
uniform vec3 uOriginDy;
uniform vec3 uDirection0;
uniform vec3 uDirectionDx;
uniform vec3 uDirectionDy;

// Keep in step with core/connectivity.cpp.
const uint kNone = 0xffffffffu;
const uint kMaxLinkedLayers = 255u;
const float kArcSlack = 1.5;
const float kFacetSlack = 2.5;
const float kFacetCosine = 0.8660254;

bool isNan(float value) {
    return (floatBitsToUint(value) & 0x7fffffffu) > 0x7f800000u;
}

struct Ray {
    vec3 origin;
    vec3 direction;
    float length2;
};

Ray rayAt(float px, float py) {
    precise vec3 direction = uDirection0 + px * uDirectionDx + py * uDirectionDy;
    precise vec3 origin = uOrigin0 + px * uOriginDx + py * uOriginDy;
    precise float length2 =
        direction.x * direction.x + direction.y * direction.y + direction.z * direction.z;
    return Ray(origin, direction, length2);
}

/** Depth at which ray meets plane; false where the reference gives NaN (grazing, degenerate). */
bool planeDepth(vec4 plane, Ray ray, out float depth) {
    precise float denom =
        plane.x * ray.direction.x + plane.y * ray.direction.y + plane.z * ray.direction.z;
    precise float square = denom * denom;
    precise float least = uMinRayCosine2 * ray.length2;
    depth = 0.0;
    if (!(square >= least))
        return false;
    precise float numerator =
        plane.w + plane.x * ray.origin.x + plane.y * ray.origin.y + plane.z * ray.origin.z;
    precise float result = -numerator / denom;
    depth = result;
    return !isNan(result);
}

/** One fragment with what the test needs; midDepth is its plane's depth on the pair's mid ray. */
struct Fragment {
    float depth;
    uint triangle;
    bool known; // triangle < uTriangleCount (the reference's info != nullptr)
    vec4 plane;
    uvec4 topology;
    bool midValid; // false where the reference's midDepth is NaN
    float midDepth;
};

Fragment loadFragment(uint f) {
    Fragment fragment;
    fragment.depth = depths[f];
    fragment.triangle = fragmentTriangles[f];
    fragment.known = fragment.triangle < uTriangleCount;
    fragment.plane = vec4(0.0);
    fragment.topology = uvec4(kNone);
    if (fragment.known) {
        fragment.plane = triangles[fragment.triangle].plane;
        fragment.topology = triangles[fragment.triangle].topology;
    }
    fragment.midValid = false;
    fragment.midDepth = 0.0;
    return fragment;
}

void setMidDepth(inout Fragment fragment, Ray mid) {
    fragment.midValid = fragment.known && planeDepth(fragment.plane, mid, fragment.midDepth);
}

bool shareCorner(uvec4 a, uvec4 b) {
    if (a.x == kNone || b.x == kNone)
        return false;
    return any(equal(a.xxx, b.xyz)) || any(equal(a.yyy, b.xyz)) || any(equal(a.zzz, b.xyz));
}

float dot3(vec4 plane, vec3 point) {
    precise float result = plane.x * point.x + plane.y * point.y + plane.z * point.z;
    return result;
}

float arcError(Fragment a, Fragment b, Ray rayP, Ray rayQ, float cosine, float slack) {
    precise vec3 pointA = rayP.origin + a.depth * rayP.direction;
    precise vec3 pointB = rayQ.origin + b.depth * rayQ.direction;
    precise vec3 chordVector = pointB - pointA;
    precise float chord2 = chordVector.x * chordVector.x + chordVector.y * chordVector.y +
                           chordVector.z * chordVector.z;
    precise float chord = sqrt(chord2);
    precise float half2 = 0.5 * (1.0 - cosine);
    precise float sinHalf = sqrt(0.0 < half2 ? half2 : 0.0); // std::max(0.0f, half2)
    precise float bound = slack * chord * sinHalf + uLimit;
    precise float fromA = abs(dot3(a.plane, pointB) + a.plane.w);
    precise float fromB = abs(dot3(b.plane, pointA) + b.plane.w);
    if (fromA <= bound && fromB <= bound)
        return fromA < fromB ? fromB : fromA; // std::max
    return uFail;
}

/**
 * Error of joining a (at P, the left or upper pixel) with b (at Q); uFail when the test fails.
 * The reference's branches, merged so that arcError() is evaluated at one place: llvmpipe runs
 * every branch that any of its 8 lanes takes.
 */
float score(Fragment a, Fragment b, Ray rayP, Ray rayQ) {
    const bool known = a.known && b.known;
    if (known && a.triangle == b.triangle)
        return -1.0; // same plane: exact at any slope
    const bool sameParts = a.topology.w == b.topology.w;
    precise float cosine = dot3(a.plane, b.plane.xyz);
    bool arc = false;
    float slack = kArcSlack;
    if (known && a.midValid && b.midValid) { // neither grazing
        precise float error = abs(a.midDepth - b.midDepth);
        if (!sameParts)
            return error < uContactLimit ? error : uFail;
        if (error < uLimit)
            return error;
        const bool corner = shareCorner(a.topology, b.topology);
        const bool crease = corner && cosine >= uCreaseCos;
        const bool facet = corner && cosine >= kFacetCosine;
        const bool smoothSurface = cosine >= uSmoothCos;
        bool cross = false;
        if (crease || smoothSurface) {
            float bAtP, aAtQ;
            const bool validBAtP = planeDepth(b.plane, rayP, bAtP);
            const bool validAAtQ = planeDepth(a.plane, rayQ, aAtQ);
            precise float change = (a.depth - bAtP) * (aAtQ - b.depth);
            cross = validBAtP && validAAtQ && bAtP > 0.0 && aAtQ > 0.0 && !isNan(change) &&
                    change <= 0.0;
        }
        if (crease && cross)
            return 0.0; // the crease through the shared corner is between them
        // The reference tries the arc for smooth && cross && !facet and the facet test for
        // facet: never both.
        arc = facet || (smoothSurface && cross);
        slack = facet ? kFacetSlack : kArcSlack;
    } else {
        // Plain test: grazing, degenerate or unknown triangles.
        precise float error = abs(a.depth - b.depth);
        const bool differentParts = known && !sameParts;
        if (error < (differentParts ? uContactLimit : uLimit))
            return error;
        // Seen edge-on, one mesh part may still continue smoothly (a silhouette pixel).
        arc = known && !differentParts && cosine >= uSmoothCos && a.plane != vec4(0.0) &&
              b.plane != vec4(0.0);
    }
    return arc ? arcError(a, b, rayP, rayQ, cosine, slack) : uFail;
}

/** The reference's better(): lower score, then the candidate's own layer, then shallower. */
bool better(float s, uint candidate, float bestScore, uint best, uint self) {
    if (s != bestScore)
        return s < bestScore;
    const uint rankCandidate = candidate == self ? 0u : candidate;
    const uint rankBest = best == self ? 0u : best;
    return rankCandidate < rankBest;
}

/**
 * The layer (1-based, 0 for none) of the neighbour pixel's fragment that fragment `self` on layer
 * selfLayer links to: the best of the first `count` from `first`. selfIsA: self's pixel is the
 * pair's P (the neighbour is right or below).
 */
uint choose(Fragment self, uint selfLayer, bool selfIsA, uint first, uint count, Ray rayP,
            Ray rayQ, Ray rayM) {
    setMidDepth(self, rayM);
    float bestScore = uFail;
    uint best = 0u;
    for (uint j = 0u; j < count; ++j) {
        Fragment other = loadFragment(first + j);
        setMidDepth(other, rayM);
        const float s = selfIsA ? score(self, other, rayP, rayQ) : score(other, self, rayP, rayQ);
        if (s != uFail && better(s, j + 1u, bestScore, best, selfLayer)) {
            bestScore = s;
            best = j + 1u;
        }
    }
    return best;
}

void main() {
    const uint f = gl_GlobalInvocationID.y * uRowInvocations + gl_GlobalInvocationID.x;
    if (f >= uFragmentCount)
        return;
    const uint p = fragmentPixels[f];
    const uint layer = f - offsets[p] + 1u;
    // Fragments past kMaxLinkedLayers stay unlinked.
    if (layer > kMaxLinkedLayers) {
        links[f] = 0u;
        return;
    }
    const ivec2 pixel = ivec2(int(p % uint(uSize.x)), int(p / uint(uSize.x)));

    // Neighbours in link order: right, left, up, down; a pixel outside the view has none.
    const ivec2 steps[4] = ivec2[4](ivec2(1, 0), ivec2(-1, 0), ivec2(0, -1), ivec2(0, 1));
    uint neighbourFirst[4];
    uint neighbourCount[4];
    for (int d = 0; d < 4; ++d) {
        const ivec2 q = pixel + steps[d];
        neighbourFirst[d] = 0u;
        neighbourCount[d] = 0u;
        if (q.x >= 0 && q.y >= 0 && q.x < uSize.x && q.y < uSize.y) {
            const uint n = uint(q.y) * uint(uSize.x) + uint(q.x);
            neighbourFirst[d] = offsets[n];
            neighbourCount[d] = min(offsets[n + 1u] - offsets[n], kMaxLinkedLayers);
        }
    }

    // Each pair's rays as the reference forms them from its P (the left or upper pixel): P's
    // centre, P + (dx, dy) and P + 0.5 (dx, dy). (Four calls rather than a loop over the
    // directions: llvmpipe ran the loop about 20% slower.)
    const float cx = float(pixel.x) + 0.5, cy = float(pixel.y) + 0.5;
    const Ray centre = rayAt(cx, cy);
    const Fragment self = loadFragment(f);
    uint word = 0u;
    if (neighbourCount[0] > 0u)
        word |= choose(self, layer, true, neighbourFirst[0], neighbourCount[0], centre,
                       rayAt(cx + 1.0, cy), rayAt(cx + 0.5, cy));
    if (neighbourCount[1] > 0u) {
        const float lx = float(pixel.x - 1) + 0.5;
        word |= choose(self, layer, false, neighbourFirst[1], neighbourCount[1], rayAt(lx, cy),
                       centre, rayAt(lx + 0.5, cy))
                << 8;
    }
    if (neighbourCount[2] > 0u) {
        const float uy = float(pixel.y - 1) + 0.5;
        word |= choose(self, layer, false, neighbourFirst[2], neighbourCount[2], rayAt(cx, uy),
                       centre, rayAt(cx, uy + 0.5))
                << 16;
    }
    if (neighbourCount[3] > 0u)
        word |= choose(self, layer, true, neighbourFirst[3], neighbourCount[3], centre,
                       rayAt(cx, cy + 1.0), rayAt(cx, cy + 0.5))
                << 24;
    links[f] = word;
}
