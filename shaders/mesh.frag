#version 450 core
// The mesh (or its stand-in while the camera moves) shaded as composite.frag shades the depth
// layers' composite, so nothing changes colour when the view switches between them: base colour
// (factor × sRGB texture × vertex colour) lit by a headlight, written sRGB; with MATERIAL (a
// textured material with a metallic-roughness texture) lit as that material; CHANNEL_BASE,
// CHANNEL_ROUGHNESS and CHANNEL_METALLIC show one channel alone (untextured: roughness 1, metal 0).
// A textured material's maps (render::SurfaceMaps) in the lit view: NORMAL_MAP, OCCLUSION_MAP,
// EMISSIVE (EMISSIVE_MAP). ALPHA_MASK: glTF's alphaMode MASK, no surface where the base colour's
// alpha is below uAlphaCutoff (the depth-layer capture drops those fragments alike). uBlend
// (glTF's BLEND, in the lit view): the base colour's alpha is written for blending.
in vec3 vViewNormal;
in vec3 vViewPosition;
in vec2 vUv;
in vec4 vColor;
#ifdef NORMAL_MAP
in vec4 vTangent;
uniform sampler2D uNormalMap; // linear
uniform mat3 uNormalTransform;
uniform mat2 uNormalAxes;
uniform float uNormalScale;
#endif
#ifdef OCCLUSION_MAP
uniform sampler2D uOcclusionMap; // linear, red
uniform mat3 uOcclusionTransform;
uniform float uOcclusionStrength;
#endif
#ifdef EMISSIVE
uniform vec3 uEmission; // linear
#endif
#ifdef EMISSIVE_MAP
uniform sampler2D uEmissiveMap; // GL_SRGB8_ALPHA8: sampled as linear
uniform mat3 uEmissiveTransform;
#endif

#ifdef ALPHA_MASK
uniform float uAlphaCutoff;
#endif
uniform vec4 uBaseColorFactor;
uniform bool uHasTexture;
uniform bool uBlend;
uniform sampler2D uBaseColorTexture;  // GL_SRGB8_ALPHA8: sampled as linear
uniform sampler2D uMetallicRoughness; // MATERIAL: GL_RGBA8, G roughness, B metallic (glTF)

layout(location = 0) out vec4 fragColor;

vec3 linearToSrgb(vec3 c) {
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

// material_shading.frag, linked in beside this file.
vec3 shadeMaterial(vec3 lit, float ambient, float headlight, float roughness, float metallic,
                   vec3 n);
vec3 mappedNormal(vec3 n, vec4 tangent, vec3 texel, float scale, mat2 axes);
float occludedAmbient(float occlusion, float strength);

vec2 mapUv(mat3 transform) {
    return (transform * vec3(vUv, 1.0)).xy;
}

void main() {
    vec4 base = uBaseColorFactor * vColor;
    if (uHasTexture)
        base *= texture(uBaseColorTexture, vUv);
#ifdef ALPHA_MASK
    if (base.a < uAlphaCutoff)
        discard;
#endif
    vec3 n = normalize(vViewNormal);
    vec3 toEye = normalize(-vViewPosition);
    // Two-sided: a back face seen through a hole is lit like its front.
    float nv = dot(n, toEye);
    float diffuse = abs(nv);
    vec3 facing = nv < 0.0 ? -n : n;
    float ambient = 0.25;
#ifdef NORMAL_MAP
    // The back face's frame is the front's turned over: tangent and bitangent sign flip too.
    vec4 tangent = nv < 0.0 ? -vTangent : vTangent;
    facing = mappedNormal(facing, tangent, texture(uNormalMap, mapUv(uNormalTransform)).rgb,
                          uNormalScale, uNormalAxes);
    diffuse = max(dot(facing, toEye), 0.0);
#endif
#ifdef OCCLUSION_MAP
    ambient = occludedAmbient(texture(uOcclusionMap, mapUv(uOcclusionTransform)).r,
                              uOcclusionStrength);
#endif
    vec3 lit = clamp(base.rgb * (ambient + 0.75 * diffuse), 0.0, 1.0);
    float roughness = 1.0;
    float metallic = 0.0;
#ifdef MATERIAL
    vec2 mr = texture(uMetallicRoughness, vUv).gb;
    roughness = mr.x;
    metallic = mr.y;
#endif
#if defined(CHANNEL_ROUGHNESS)
    vec3 color = vec3(roughness);
#elif defined(CHANNEL_METALLIC)
    vec3 color = vec3(metallic);
#elif defined(CHANNEL_BASE)
    vec3 color = linearToSrgb(clamp(base.rgb, 0.0, 1.0));
#else
#ifdef MATERIAL
    vec3 shaded = shadeMaterial(lit, ambient, diffuse, roughness, metallic, facing);
#else
    vec3 shaded = lit;
#endif
#ifdef EMISSIVE
    vec3 emission = uEmission;
#ifdef EMISSIVE_MAP
    emission *= texture(uEmissiveMap, mapUv(uEmissiveTransform)).rgb;
#endif
    shaded += emission;
#endif
    vec3 color = linearToSrgb(clamp(shaded, 0.0, 1.0));
#endif
    fragColor = vec4(color, uBlend ? clamp(base.a, 0.0, 1.0) : 1.0);
}
