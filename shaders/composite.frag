#version 450 core
// draw_layers: the view drawn from the captured per-pixel fragment lists instead of the mesh,
// from fragment shading that composite_shade.comp computed once per capture. The compositor
// inserts the defines of the features a draw needs:
// - RESOLVE picks each pixel's visible fragment by region rank (SINGLE_LAYER: layer uLayer)
//   into Visible, with BOUNDARIES whether it ends its region there. Only draws after the
//   order, the picked layer or the capture changed do this; others read Visible.
// - TRANSPARENCY (popped-up regions seen through, the paper's exploded view): RESOLVE also
//   keeps, where the visible fragment is not on layer 1, the next one in the order ("under") in
//   the second half of Visible. UNDER passes draw those opaque; the normal passes then blend
//   the visible fragment over them with uOpacity.
// - BLEND (with TRANSPARENCY; only in the lit Material view): a fragment of a material whose
//   alphaMode is BLEND keeps the next one in the order under it too, on any layer, and is drawn
//   over it with its alpha (factor × vertex colour × texture), as glTF viewers draw it over
//   what lies behind; the fragment under is drawn opaque.
// - the picture: shaded colour, texture (TEXTURED, one pass per texture and maps; MATERIAL: the
//   pass has a metallic-roughness texture and lights the surface with it; NORMAL_MAP,
//   OCCLUSION_MAP, EMISSIVE, EMISSIVE_MAP: its maps, as mesh.frag draws them), one channel alone
//   (CHANNEL_BASE, CHANNEL_ROUGHNESS, CHANNEL_METALLIC), SEGMENTATION colours
//   (SHADE_SEGMENTATION: lit lightly), BOUNDARIES and HIGHLIGHT overlays, so repainting the
//   texture or the overlays costs no picking.
// llvmpipe executes both sides of every branch, uniform or not, which is why features are
// compiled in only when used instead of being switched by uniforms.

const uint kNone = 0xffffffffu;
const uint kUnranked = 0xfffffffeu; // a fragment without a region: behind every ranked one

uniform int uWidth;
uniform int uHeight;

// Storage bindings are shared with composite_shade.comp, which reads the mesh (1, 2, 6-11, 13).
// core::DepthStack: pixel p's fragments are [offsets[p], offsets[p + 1]), front to back.
layout(std430, binding = 0) readonly buffer Offsets {
    uint offsets[];
};
layout(std430, binding = 3) readonly buffer FragmentRegions {
    uint fragmentRegion[];
};
// core::Connectivity: byte d (right, left, up, down) = the linked neighbour's layer, 0 = none.
layout(std430, binding = 4) readonly buffer FragmentLinks {
    uint fragmentLinks[];
};
// [region] its rank (kNone = hidden), then [uRegionCount + layer - 1] the lowest rank of any
// region deeper than that layer: once a pixel's best rank is below it, the rest cannot win.
layout(std430, binding = 5) readonly buffer Ranks {
    uint ranks[];
};
// Per pixel (rows top first): the visible fragment in bits 0-30 (kNoFragment: background) and
// in bit 31 whether it ends its region there (BOUNDARIES); then, at uWidth * uHeight + pixel,
// the under fragment (TRANSPARENCY; kNoFragment where the visible one is opaque).
layout(std430, binding = 12) buffer Visible {
    uint visible[];
};
const uint kNoFragment = 0x7fffffffu;
const uint kBoundaryBit = 0x80000000u;
// composite_shade.comp's output, a word a fragment in each of four buffers.
layout(std430, binding = 14) readonly buffer ShadingColor {
    uint shadingColor[];
};
layout(std430, binding = 15) readonly buffer ShadingUv {
    uint shadingUv[];
};
layout(std430, binding = 16) readonly buffer ShadingLight {
    uint shadingLight[];
};
layout(std430, binding = 17) readonly buffer ShadingNormal {
    uint shadingNormal[];
};

uniform float uOpacity; // TRANSPARENCY: of popped-up fragments drawn over an under one

#ifdef BLEND
// Whether fragment f's material blends (composite_shade.comp: Light's byte 3 below 255), and its
// alpha before the texture's.
bool blends(uint f) {
    return (shadingLight[f] >> 24) != 0xffu;
}
float blendAlpha(uint f) {
    return float(shadingLight[f] >> 24) / 254.0;
}
#endif

// Pixel centres in DepthStack coordinates (y down).
vec2 pixelCentre() {
    return vec2(gl_FragCoord.x, float(uHeight) - gl_FragCoord.y);
}

vec3 linearToSrgb(vec3 c) {
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

#ifdef RESOLVE

uniform uint uLayer; // SINGLE_LAYER, 1-based
uniform uint uRegionCount;
uniform uint uMaxLayers;

/**
 * The visible fragment of a pixel, kNone for none: the one of lowest region rank (front-most
 * on ties), skipping hidden regions; with SINGLE_LAYER the layer-uLayer one. With TRANSPARENCY
 * under gets the next one in rank where the visible one is popped up (not on layer 1, which is
 * opaque) or, with BLEND, where its material blends.
 */
uint pickFragment(uint first, uint end, out uint under) {
    under = kNone;
#ifdef SINGLE_LAYER
    return uLayer >= 1u && uLayer <= end - first ? first + uLayer - 1u : kNone;
#else
    uint chosen = kNone;
    uint best = kNone;
    uint second = kNone;
    for (uint f = first; f < end; ++f) {
        uint region = fragmentRegion[f];
        uint rank = region < uRegionCount ? ranks[region] : kUnranked;
        if (rank < best) {
            second = best;
            under = chosen;
            best = rank;
            chosen = f;
        } else if (rank < second) {
            second = rank;
            under = f;
        }
        uint layer = f - first + 1u;
        if (layer <= uMaxLayers) {
            // Nothing deeper can beat what is kept: stop.
            uint cutoff = ranks[uRegionCount + layer - 1u];
#if defined(BLEND)
            if (second < cutoff)
                break;
#elif defined(TRANSPARENCY)
            if ((chosen == first ? best : second) < cutoff)
                break;
#else
            if (best < cutoff)
                break;
#endif
        }
    }
    bool seeThrough = chosen != first && uOpacity < 1.0;
#ifdef BLEND
    seeThrough = seeThrough || (chosen != kNone && blends(chosen));
#endif
    if (!seeThrough)
        under = kNone;
    return chosen;
#endif
}

#ifdef BOUNDARIES
// Whether fragment f (on layer, at pix) ends its region towards a neighbour that shows a surface:
// no same-layer link either way, as segmentDepthLayers() joins fragments (the paper's Figure 3 lines).
bool onBoundary(uint f, uint layer, ivec2 pix) {
    const ivec2 steps[4] = ivec2[4](ivec2(1, 0), ivec2(-1, 0), ivec2(0, -1), ivec2(0, 1));
    uint links = fragmentLinks[f];
    for (int d = 0; d < 4; ++d) {
        ivec2 q = pix + steps[d];
        if (q.x < 0 || q.y < 0 || q.x >= uWidth || q.y >= uHeight)
            continue;
        uint neighbour = uint(q.y) * uint(uWidth) + uint(q.x);
        uint first = offsets[neighbour];
        uint count = offsets[neighbour + 1u] - first;
        if (count == 0u || ((links >> (8 * d)) & 0xffu) == layer)
            continue;
        // Right/left and up/down are pairs: d ^ 1 is the direction back.
        uint back = layer <= count ? fragmentLinks[first + layer - 1u] >> (8 * (d ^ 1)) : 0u;
        if ((back & 0xffu) == layer)
            continue;
        return true;
    }
    return false;
}
#endif

/**
 * Visible's words for a pixel: its visible fragment and whether it ends its region there, and
 * the under fragment.
 */
uvec2 resolvePixel(uint pixel, ivec2 pix) {
    uint first = offsets[pixel];
    uint under;
    uint chosen = pickFragment(first, offsets[pixel + 1u], under);
    uint word = chosen == kNone ? kNoFragment : chosen;
#ifdef BOUNDARIES
    if (chosen != kNone && onBoundary(chosen, chosen - first + 1u, pix))
        word |= kBoundaryBit;
#endif
#ifdef TRANSPARENCY
    return uvec2(word, under == kNone ? kNoFragment : under);
#else
    return uvec2(word, kNoFragment);
#endif
}

#endif

#ifdef NORMAL_MAP
layout(std430, binding = 2) readonly buffer FragmentDepths {
    float fragmentDepth[];
};
layout(std430, binding = 19) readonly buffer ShadingTangent {
    uint shadingTangent[];
};
uniform sampler2D uNormalMap; // linear
uniform mat3 uNormalTransform;
uniform mat2 uNormalAxes;
uniform float uNormalScale;
uniform float uNormalLodBias;
// View-space pixel rays, as composite_shade.comp has them: the direction to the viewer.
uniform vec3 uRayOrigin0;
uniform vec3 uRayOriginDx;
uniform vec3 uRayOriginDy;
uniform vec3 uRayDirection0;
uniform vec3 uRayDirectionDx;
uniform vec3 uRayDirectionDy;
#endif
#ifdef OCCLUSION_MAP
uniform sampler2D uOcclusionMap; // linear, red
uniform mat3 uOcclusionTransform;
uniform float uOcclusionStrength;
uniform float uOcclusionLodBias;
#endif
#ifdef EMISSIVE
uniform vec3 uEmission; // linear
#endif
#ifdef EMISSIVE_MAP
uniform sampler2D uEmissiveMap; // GL_SRGB8_ALPHA8: sampled as linear
uniform mat3 uEmissiveTransform;
uniform float uEmissiveLodBias;
#endif

layout(location = 0) out vec4 fragColor;

uniform vec4 uBackground; // sRGB
uniform uint uHighlight;  // HIGHLIGHT: region id
uniform ivec4 uHighlightBox; // HIGHLIGHT: its pixels' bounding box, min x, min y, max x, max y
uniform int uPass;        // TEXTURED: the pass; its texture is uTexture
uniform sampler2D uTexture; // GL_SRGB8_ALPHA8: sampled as linear
uniform sampler2D uMetallicRoughness; // MATERIAL: GL_RGBA8, G roughness, B metallic (glTF)

vec3 srgbToLinear(vec3 c) {
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(vec3(0.04045), c));
}

// The same formula as render::regionColor() (depth_compositor.cpp): keep the two in step.
vec3 regionColor(uint region) {
    uint h = region * 0x9e3779b9u;
    float hue = float(h >> 8) / 16777216.0;
    uint m = region;
    m ^= m >> 16;
    m *= 0x7feb352du;
    m ^= m >> 15;
    m *= 0x846ca68bu;
    m ^= m >> 16;
    float saturation = 0.5 + 0.2 * float(m % 3u);
    float value = 0.75 + 0.125 * float((m >> 8) % 3u);
    vec3 k = clamp(abs(fract(vec3(hue) + vec3(1.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0) - 1.0,
                   0.0, 1.0);
    return value * mix(vec3(1.0), k, saturation);
}

vec3 decodeNormal(uint word) {
    vec2 e = unpackSnorm2x16(word);
    vec3 v = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    if (v.z < 0.0)
        v.xy = (1.0 - abs(v.yx)) * vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0);
    return normalize(v);
}

// material_shading.frag, linked in beside this file (the mesh renderer shades with it too).
vec3 shadeMaterial(vec3 lit, float ambient, float headlight, float roughness, float metallic,
                   vec3 n);
vec3 mappedNormal(vec3 n, vec4 tangent, vec3 texel, float scale, mat2 axes);
float occludedAmbient(float occlusion, float strength);

vec2 mapUv(mat3 transform, vec2 uv) {
    return (transform * vec3(uv, 1.0)).xy;
}

#if defined(NORMAL_MAP) || defined(OCCLUSION_MAP) || defined(EMISSIVE)
#define SURFACE_MAPS
#endif

#ifdef NORMAL_MAP
// The fragment's normal turned by the normal map, and the headlight on it (as mesh.frag: the
// direction to the viewer from the point the pixel's ray meets).
vec3 mappedFragmentNormal(uint f, vec3 n, vec2 uv, float lod, out float headlight) {
    uint word = shadingTangent[f];
    vec4 tangent = vec4(decodeNormal(word), (word & 1u) != 0u ? -1.0 : 1.0);
    vec3 texel = textureLod(uNormalMap, mapUv(uNormalTransform, uv), lod + uNormalLodBias).rgb;
    vec3 mapped = mappedNormal(n, tangent, texel, uNormalScale, uNormalAxes);
    vec2 px = pixelCentre();
    vec3 o = uRayOrigin0 + px.x * uRayOriginDx + px.y * uRayOriginDy;
    vec3 d = uRayDirection0 + px.x * uRayDirectionDx + px.y * uRayDirectionDy;
    headlight = max(dot(mapped, normalize(-(o + fragmentDepth[f] * d))), 0.0);
    return mapped;
}
#endif

void main() {
    ivec2 pix = ivec2(pixelCentre());
    uint pixel = uint(pix.y) * uint(uWidth) + uint(pix.x);
    uint pixels = uint(uWidth) * uint(uHeight);
#ifdef RESOLVE
    uvec2 words = resolvePixel(pixel, pix);
    visible[pixel] = words.x;
    visible[pixels + pixel] = words.y;
#else
    uvec2 words = uvec2(visible[pixel], kNoFragment);
#if defined(TRANSPARENCY) || defined(UNDER)
    words.y = visible[pixels + pixel];
#endif
#endif
#ifdef UNDER
    // The fragment behind a see-through one, drawn first and opaque; nothing elsewhere.
    uint word = words.y;
    if (word == kNoFragment)
        discard;
#else
    uint word = words.x;
#endif
    uint chosen = word & kNoFragment;
    float alpha = 1.0;
#if defined(TRANSPARENCY) && !defined(UNDER)
    bool poppedUp = words.y != kNoFragment;
#ifdef BLEND
    poppedUp = poppedUp && chosen != offsets[pixel];
    if (chosen != kNoFragment && blends(chosen))
        alpha = blendAlpha(chosen);
#endif
    if (poppedUp)
        alpha *= uOpacity;
#endif

    vec4 color = uBackground;
    uint region = kNone;
    if (chosen != kNoFragment) {
        uint shade = shadingColor[chosen];
#if defined(SEGMENTATION) || defined(HIGHLIGHT)
        region = fragmentRegion[chosen];
#endif
#ifdef SEGMENTATION
        vec3 c = region == kNone ? vec3(0.5) : regionColor(region);
#ifdef SHADE_SEGMENTATION
        // Light shading keeps the shape readable without drowning the hue.
        c *= 0.6 + 0.4 * float((shadingLight[chosen] >> 16) & 0xffu) / 255.0;
#endif
        color = vec4(c, 1.0);
#else
        color = vec4(unpackUnorm4x8(shade).rgb, 1.0);
        // Untextured fragments and those without metallic-roughness: roughness 1, metal 0.
        float roughness = 1.0;
        float metallic = 0.0;
        bool textured = false;
        vec3 lit = srgbToLinear(color.rgb); // the base colour lit by the headlight
        float headlight = float((shadingLight[chosen] >> 16) & 0xffu) / 255.0;
        float ambient = 0.25;
        vec3 normal = vec3(0.0, 0.0, 1.0);
#if defined(MATERIAL) || defined(NORMAL_MAP)
        normal = decodeNormal(shadingNormal[chosen]);
#endif
        vec3 emission = vec3(0.0);
#ifdef TEXTURED
        // The first pass takes the untextured pixels too, later passes only their texture's.
        uint slot = shade >> 24;
        if (slot == 0u ? uPass != 0 : int(slot) - 1 != uPass)
            discard;
        if (slot != 0u) {
            textured = true;
            vec2 uv = unpackUnorm2x16(shadingUv[chosen]);
            float lod = (float(shadingLight[chosen] & 0xffffu) - 32768.0) / 1024.0;
            vec4 texel = textureLod(uTexture, uv, lod);
            lit *= texel.rgb;
#if defined(BLEND) && !defined(UNDER)
            if (blends(chosen))
                alpha *= texel.a;
#endif
#ifdef MATERIAL
            vec2 mr = textureLod(uMetallicRoughness, uv, lod).gb;
            roughness = mr.x;
            metallic = mr.y;
#endif
#ifdef SURFACE_MAPS
            // The maps as mesh.frag applies them: the albedo lit again with the turned normal
            // and the occluded ambient, the emission added after lighting.
            float shadedLight = float((shadingLight[chosen] >> 16) & 0xffu) / 255.0;
            headlight = shadedLight;
#ifdef NORMAL_MAP
            normal = mappedFragmentNormal(chosen, normal, uv, lod, headlight);
#endif
#ifdef OCCLUSION_MAP
            ambient = occludedAmbient(
                textureLod(uOcclusionMap, mapUv(uOcclusionTransform, uv), lod + uOcclusionLodBias)
                    .r,
                uOcclusionStrength);
#endif
            lit = clamp(lit / (0.25 + 0.75 * shadedLight) * (ambient + 0.75 * headlight), 0.0,
                        1.0);
#ifdef EMISSIVE
            emission = uEmission;
#ifdef EMISSIVE_MAP
            emission *= textureLod(uEmissiveMap, mapUv(uEmissiveTransform, uv),
                                   lod + uEmissiveLodBias)
                            .rgb;
#endif
#endif
#endif
        }
#endif
#if defined(CHANNEL_ROUGHNESS)
        color.rgb = vec3(roughness);
#elif defined(CHANNEL_METALLIC)
        color.rgb = vec3(metallic);
#elif defined(CHANNEL_BASE)
        color.rgb = linearToSrgb(clamp(lit / (0.25 + 0.75 * headlight), 0.0, 1.0));
#else
        if (textured) {
#ifdef MATERIAL
            lit = shadeMaterial(lit, ambient, headlight, roughness, metallic, normal);
#endif
            color.rgb = linearToSrgb(clamp(lit + emission, 0.0, 1.0));
        }
#endif
#endif
#ifdef BOUNDARIES
        if ((word & kBoundaryBit) != 0u)
            color.rgb = mix(color.rgb, vec3(0.02), 0.8);
#endif
    }
#ifdef TEXTURED
    else if (uPass != 0)
        discard; // the first pass drew the background
#endif

#ifdef HIGHLIGHT
    // The region tinted where shown, striped where something else covers it.
    const vec3 kHighlight = vec3(1.0, 0.78, 0.15);
    bool behind = false;
    // Outside the region's box the loop ends at once, which llvmpipe skips (unlike an if).
    bool inBox = all(greaterThanEqual(pix, uHighlightBox.xy)) &&
                 all(lessThanEqual(pix, uHighlightBox.zw));
    uint end = inBox ? offsets[pixel + 1u] : 0u;
    for (uint f = inBox ? offsets[pixel] : 0u; f < end; ++f)
        behind = behind || (fragmentRegion[f] == uHighlight && f != chosen);
    if (region == uHighlight)
        color.rgb = mix(color.rgb, kHighlight, 0.5);
    else if (behind && ((pix.x + pix.y) & 4) == 0)
        color = vec4(mix(color.rgb, kHighlight, 0.45), 1.0);
#endif
    fragColor = vec4(color.rgb, color.a * alpha);
}
