#version 450 core
// draw_layers, once per capture or mesh: shades every captured fragment where its pixel's ray
// meets its triangle, as mesh.frag shades that surface, into the Shading buffer. The shading
// does not depend on the region order, so a pop-up only picks again (composite.frag). The
// compositor inserts the defines: TEXTURED (uv and texture LOD), UVS, COLORS (vertex colours),
// TANGENTS (the view-space tangent, for normal maps), BLEND (some material blends by its alpha).
layout(local_size_x = 64) in;

const uint kNone = 0xffffffffu;

uniform uint uFragmentCount;
uniform uint uWidth;
// A mesh too large for one storage block is split into parts of consecutive triangles (see
// render::compositor::MeshPart): this pass runs once per part, with the part's triangles
// [uTriangleFirst, uTriangleFirst + uTriangleCount), numbered from 0 and indexing the part's own
// vertices, at bindings 6-10. Fragments of other parts' triangles are left alone; those of
// triangles the mesh lacks (uMeshTriangles and beyond) are shaded grey by the first part.
uniform uint uTriangleFirst;
uniform uint uTriangleCount;
uniform uint uMeshTriangles;
uniform uint uFirstPart;
uniform mat4 uView;
// View-space pixel rays (core::PixelRays): origin + depth * direction, affine in the pixel.
uniform vec3 uRayOrigin0;
uniform vec3 uRayOriginDx;
uniform vec3 uRayOriginDy;
uniform vec3 uRayDirection0;
uniform vec3 uRayDirectionDx;
uniform vec3 uRayDirectionDy;

// Bindings shared with composite.frag.
layout(std430, binding = 1) readonly buffer FragmentTriangles {
    uint fragmentTriangle[];
};
layout(std430, binding = 2) readonly buffer FragmentDepths {
    float fragmentDepth[];
};
layout(std430, binding = 6) readonly buffer Triangles {
    uvec4 triangles[];
};
layout(std430, binding = 7) readonly buffer Positions {
    float positions[];
};
// Unit normals, octahedral-encoded as 2 × snorm16: one load a vertex instead of three.
layout(std430, binding = 8) readonly buffer Normals {
    uint normals[];
};
layout(std430, binding = 9) readonly buffer Uvs {
    vec2 uvs[];
};
layout(std430, binding = 10) readonly buffer Colors {
    vec4 colors[];
};
struct Material {
    vec4 baseColorFactor; // linear
    int texturePass;      // the pass sampling its base color texture, -1 for none
    int textureWidth;
    int textureHeight;
    int blend; // glTF's alphaMode BLEND
};
layout(std430, binding = 11) readonly buffer Materials {
    Material materials[];
};
// The pixel (y * width + x, rows top first) of each fragment.
layout(std430, binding = 13) readonly buffer FragmentPixels {
    uint fragmentPixel[];
};
// A fragment's shading in four buffers of one word a fragment (a storage block holds as many
// fragments as the fragment arrays then): Color: lit base colour, sRGB rgb in bytes 0-2 and in
// byte 3 the texture pass + 1 (0: untextured); Uv: fract(uv) as 2 × unorm16; Light: bits 0-15
// the texture LOD × 1024 + 32768, bits 16-23 the headlight term |n · v|, bits 24-31 255 or, for
// a blending material, factor × vertex colour alpha × 254 (the texture's alpha is the composing
// pass's); Normal: the view-space
// unit normal turned towards the viewer, octahedral as 2 × snorm16 (the material's lights).
layout(std430, binding = 14) writeonly buffer ShadingColor {
    uint shadingColor[];
};
layout(std430, binding = 15) writeonly buffer ShadingUv {
    uint shadingUv[];
};
layout(std430, binding = 16) writeonly buffer ShadingLight {
    uint shadingLight[];
};
layout(std430, binding = 17) writeonly buffer ShadingNormal {
    uint shadingNormal[];
};
#ifdef TANGENTS
// Per vertex (a mesh array like 6-10): the tangent octahedral as the normals, bit 0 the sign of
// its bitangent (set: negative). Per fragment: the view-space tangent turned as the normal is
// (facing the viewer), the same encoding.
layout(std430, binding = 18) readonly buffer Tangents {
    uint tangents[];
};
layout(std430, binding = 19) writeonly buffer ShadingTangent {
    uint shadingTangent[];
};
#endif

vec3 linearToSrgb(vec3 c) {
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

uint octEncode(vec3 n) {
    n /= abs(n.x) + abs(n.y) + abs(n.z);
    vec2 e = n.z >= 0.0 ? n.xy
                        : (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
    return packSnorm2x16(e);
}

vec3 position(uint i) {
    return vec3(positions[3u * i], positions[3u * i + 1u], positions[3u * i + 2u]);
}
vec3 octDecode(uint word) {
    vec2 e = unpackSnorm2x16(word);
    vec3 v = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    if (v.z < 0.0)
        v.xy = (1.0 - abs(v.yx)) * vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0);
    return normalize(v);
}
vec3 normalAt(uint i) {
    return octDecode(normals[i]);
}

// Barycentrics (of a, a + e1, a + e2) where the ray o + s d meets the triangle's plane; false
// when the ray grazes the plane too closely for a stable answer.
bool intersectPlane(vec3 o, vec3 d, vec3 a, vec3 e1, vec3 e2, out vec3 bary) {
    vec3 pv = cross(d, e2);
    float det = dot(e1, pv);
    if (!(abs(det) > 1e-3 * length(d) * length(cross(e1, e2)))) {
        bary = vec3(1.0 / 3.0);
        return false;
    }
    vec3 s = o - a;
    float u = dot(s, pv) / det;
    float v = dot(d, cross(s, e1)) / det;
    bary = vec3(1.0 - u - v, u, v);
    return true;
}

// Barycentrics of the point nearest p in the triangle's plane (for grazing rays).
vec3 projectToTriangle(vec3 p, vec3 a, vec3 e1, vec3 e2) {
    vec3 q = p - a;
    float d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2);
    float d20 = dot(q, e1), d21 = dot(q, e2);
    float denominator = d00 * d11 - d01 * d01;
    if (!(abs(denominator) > 0.0))
        return vec3(1.0 / 3.0);
    float v = (d11 * d20 - d01 * d21) / denominator;
    float w = (d00 * d21 - d01 * d20) / denominator;
    return vec3(1.0 - v - w, v, w);
}

void main() {
    uint f = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u +
             gl_LocalInvocationIndex;
    if (f >= uFragmentCount)
        return;
    uint t = fragmentTriangle[f];
    uint local = t - uTriangleFirst; // wraps below the part
    bool inPart = local < uTriangleCount;
    if (!inPart && !(uFirstPart != 0u && t >= uMeshTriangles))
        return;
    uint pixel = fragmentPixel[f];
    vec2 px = vec2(float(pixel % uWidth) + 0.5, float(pixel / uWidth) + 0.5);

    uvec4 triangle = inPart ? triangles[local] : uvec4(0u, 0u, 0u, kNone);
    vec4 base = vec4(0.5, 0.5, 0.5, 1.0); // a triangle the mesh lacks: plain grey
    float diffuse = 1.0;
    uint slot = 0u;
    uint uvWord = 0u;
    uint lodWord = 32768u;
    vec3 facing = vec3(0.0, 0.0, 1.0);
    uint tangentWord = 0u;
    uint alphaByte = 255u;
    if (triangle.w != kNone) {
        // Member by member: each field read is a load per fragment on llvmpipe.
        base = materials[triangle.w].baseColorFactor;
        vec3 o = uRayOrigin0 + px.x * uRayOriginDx + px.y * uRayOriginDy;
        vec3 d = uRayDirection0 + px.x * uRayDirectionDx + px.y * uRayDirectionDy;
        vec3 a = (uView * vec4(position(triangle.x), 1.0)).xyz;
        vec3 e1 = (uView * vec4(position(triangle.y), 1.0)).xyz - a;
        vec3 e2 = (uView * vec4(position(triangle.z), 1.0)).xyz - a;
        vec3 bary;
        if (!intersectPlane(o, d, a, e1, e2, bary))
            bary = projectToTriangle(o + fragmentDepth[f] * d, a, e1, e2);
        // A pixel centre just outside its triangle (rasterization snaps) takes the edge.
        vec3 rawBary = bary;
        vec3 clamped = max(bary, vec3(0.0));
        float sum = clamped.x + clamped.y + clamped.z;
        bary = sum > 0.0 ? clamped / sum : vec3(1.0 / 3.0);
        vec3 viewPosition = a + bary.y * e1 + bary.z * e2;
        vec3 n = mat3(uView) * (bary.x * normalAt(triangle.x) + bary.y * normalAt(triangle.y) +
                                bary.z * normalAt(triangle.z));
        if (!(dot(n, n) > 1e-24))
            n = cross(e1, e2);
        // Two-sided headlight, as mesh.frag.
        float nv = dot(normalize(n), normalize(-viewPosition));
        diffuse = abs(nv);
        facing = nv < 0.0 ? -normalize(n) : normalize(n);
#ifdef TANGENTS
        // As mesh.vert passes it on and mesh.frag turns it for a back face.
        vec3 tangent = mat3(uView) * (bary.x * octDecode(tangents[triangle.x]) +
                                      bary.y * octDecode(tangents[triangle.y]) +
                                      bary.z * octDecode(tangents[triangle.z]));
        uint negative = tangents[triangle.x] & 1u;
        if (nv < 0.0) {
            tangent = -tangent;
            negative ^= 1u;
        }
        if (dot(tangent, tangent) > 1e-24)
            tangentWord = (octEncode(tangent) & ~1u) | negative;
#endif
#ifdef COLORS
        base *= bary.x * colors[triangle.x] + bary.y * colors[triangle.y] +
                bary.z * colors[triangle.z];
#endif
#ifdef BLEND
        if (materials[triangle.w].blend != 0)
            alphaByte = uint(clamp(base.a, 0.0, 1.0) * 254.0 + 0.5);
#endif
#ifdef TEXTURED
        int texturePass = materials[triangle.w].texturePass;
        if (texturePass >= 0) {
            slot = uint(texturePass) + 1u;
            // Without uvs every point samples uv (0, 0), as mesh.vert feeds it.
#ifdef UVS
            vec2 uv0 = uvs[triangle.x], uv1 = uvs[triangle.y], uv2 = uvs[triangle.z];
            vec2 uv = bary.x * uv0 + bary.y * uv1 + bary.z * uv2;
            uvWord = packUnorm2x16(fract(uv));
            // The LOD from the same plane one pixel over, as GL derives it from screen
            // derivatives (which a full-screen pass lacks where neighbours differ).
            vec3 bx, by;
            if (intersectPlane(o + uRayOriginDx, d + uRayDirectionDx, a, e1, e2, bx) &&
                intersectPlane(o - uRayOriginDy, d - uRayDirectionDy, a, e1, e2, by)) {
                vec2 size = vec2(materials[triangle.w].textureWidth,
                                 materials[triangle.w].textureHeight);
                vec2 dx = ((bx.x - rawBary.x) * uv0 + (bx.y - rawBary.y) * uv1 +
                           (bx.z - rawBary.z) * uv2) * size;
                vec2 dy = ((by.x - rawBary.x) * uv0 + (by.y - rawBary.y) * uv1 +
                           (by.z - rawBary.z) * uv2) * size;
                float rho = max(length(dx), length(dy));
                float lod = rho > 0.0 ? log2(rho) : -32.0;
                lodWord = uint(clamp(lod * 1024.0 + 32768.0, 0.0, 65535.0) + 0.5);
            }
#endif
        }
#endif
    }
    vec3 lit = clamp(base.rgb * (0.25 + 0.75 * diffuse), 0.0, 1.0);
    shadingColor[f] = (packUnorm4x8(vec4(linearToSrgb(lit), 0.0)) & 0xffffffu) | (slot << 24);
    shadingUv[f] = uvWord;
    shadingLight[f] = lodWord | (uint(diffuse * 255.0 + 0.5) << 16) | (alphaByte << 24);
    shadingNormal[f] = octEncode(facing);
#ifdef TANGENTS
    shadingTangent[f] = tangentWord;
#endif
}
