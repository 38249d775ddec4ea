#version 450 core
// A screen rectangle (pixels, y down, [x0, y0, x1, y1]) as two triangles, no vertex buffer.
uniform vec4 uRect;
uniform vec2 uViewSize;

void main() {
    const vec2 corners[6] =
        vec2[6](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));
    vec2 pixel = mix(uRect.xy, uRect.zw, corners[gl_VertexID]);
    gl_Position = vec4(pixel.x / uViewSize.x * 2.0 - 1.0, 1.0 - pixel.y / uViewSize.y * 2.0, 0.0,
                       1.0);
}
