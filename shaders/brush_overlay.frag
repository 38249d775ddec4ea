#version 450 core
// Over the view, blended: the paintable (red) and trackable (blue) maps of the last dab (the
// paper's Figure 4) from a view-sized texture, or the brush outline, a ring of radius uRadius.
uniform vec2 uViewSize;
uniform bool uRing;
uniform vec2 uCenter; // pixels, y down
uniform float uRadius;
uniform sampler2D uMaps; // RGBA8, straight alpha, rows top first (uploaded as is: y flipped)

layout(location = 0) out vec4 fragColor;

void main() {
    vec2 pixel = vec2(gl_FragCoord.x, uViewSize.y - gl_FragCoord.y);
    if (uRing) {
        // A light line inside a dark one reads on any surface colour.
        float d = length(pixel - uCenter) - uRadius;
        float dark = 1.0 - smoothstep(0.5, 1.5, abs(d - 0.75));
        float light = 1.0 - smoothstep(0.5, 1.5, abs(d + 0.75));
        float alpha = max(dark, light) * 0.9;
        if (alpha <= 0.0)
            discard;
        fragColor = vec4(vec3(light > dark ? 1.0 : 0.0), alpha);
    } else {
        vec4 texel = texelFetch(uMaps, ivec2(pixel), 0);
        if (texel.a <= 0.0)
            discard;
        fragColor = texel;
    }
}
