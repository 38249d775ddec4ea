#version 450 core
// The mesh (or its stand-in while the camera moves) shaded as composite.frag shades the depth
// layers' composite, so nothing changes colour when the view switches between them: base colour
// (factor × sRGB texture × vertex colour) lit by a headlight, written sRGB; with MATERIAL (a
// textured material with a metallic-roughness texture) lit as that material; CHANNEL_BASE,
// CHANNEL_ROUGHNESS and CHANNEL_METALLIC show one channel alone (untextured: roughness 1, metal 0).
in vec3 vViewNormal;
in vec3 vViewPosition;
in vec2 vUv;
in vec4 vColor;

uniform vec4 uBaseColorFactor;
uniform bool uHasTexture;
uniform sampler2D uBaseColorTexture;  // GL_SRGB8_ALPHA8: sampled as linear
uniform sampler2D uMetallicRoughness; // MATERIAL: GL_RGBA8, G roughness, B metallic (glTF)

layout(location = 0) out vec4 fragColor;

vec3 linearToSrgb(vec3 c) {
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

#ifdef MATERIAL
// material_shading.frag, linked in beside this file.
vec3 shadeMaterial(vec3 lit, float headlight, float roughness, float metallic, vec3 n);
#endif

void main() {
    vec4 base = uBaseColorFactor * vColor;
    if (uHasTexture)
        base *= texture(uBaseColorTexture, vUv);
    vec3 n = normalize(vViewNormal);
    vec3 toEye = normalize(-vViewPosition);
    // Two-sided: a back face seen through a hole is lit like its front.
    float nv = dot(n, toEye);
    float diffuse = abs(nv);
    vec3 lit = clamp(base.rgb * (0.25 + 0.75 * diffuse), 0.0, 1.0);
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
#elif defined(MATERIAL)
    vec3 color = linearToSrgb(clamp(
        shadeMaterial(lit, diffuse, roughness, metallic, nv < 0.0 ? -n : n), 0.0, 1.0));
#else
    vec3 color = linearToSrgb(lit);
#endif
    fragColor = vec4(color, 1.0);
}
