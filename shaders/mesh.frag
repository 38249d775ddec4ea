#version 450 core
// Unlit base color (factor × sRGB texture × vertex color) lit by a headlight, written sRGB.
in vec3 vViewNormal;
in vec3 vViewPosition;
in vec2 vUv;
in vec4 vColor;

uniform vec4 uBaseColorFactor;
uniform bool uHasTexture;
uniform sampler2D uBaseColorTexture; // GL_SRGB8_ALPHA8: sampled as linear

layout(location = 0) out vec4 fragColor;

vec3 linearToSrgb(vec3 c) {
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main() {
    vec4 base = uBaseColorFactor * vColor;
    if (uHasTexture)
        base *= texture(uBaseColorTexture, vUv);
    vec3 n = normalize(vViewNormal);
    vec3 toEye = normalize(-vViewPosition);
    // Two-sided: a back face seen through a hole is lit like its front.
    float diffuse = abs(dot(n, toEye));
    vec3 lit = base.rgb * (0.25 + 0.75 * diffuse);
    fragColor = vec4(linearToSrgb(clamp(lit, 0.0, 1.0)), 1.0);
}
