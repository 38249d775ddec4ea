#version 450 core
// draw_layers: one square per tile of the view that holds fragments; the rest of the view is
// only cleared to the background, so empty pixels cost no shading.
layout(location = 0) in uint aTile; // x | y << 16, tiles counted from the top-left

uniform int uWidth;
uniform int uHeight;
uniform int uTileSize;

void main() {
    const ivec2 corners[6] =
        ivec2[6](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(0, 1), ivec2(1, 0), ivec2(1, 1));
    ivec2 corner = (ivec2(aTile & 0xffffu, aTile >> 16) + corners[gl_VertexID]) * uTileSize;
    // Stack rows run down, window rows up.
    vec2 window = vec2(min(corner.x, uWidth), uHeight - min(corner.y, uHeight));
    gl_Position = vec4(window / vec2(uWidth, uHeight) * 2.0 - 1.0, 0.0, 1.0);
}
