#version 450 core
// Layer capture, drawn as a triangle soup (glDrawArrays, vertex 3t + k is corner k of triangle t)
// so the triangle id is a flat varying. gl_PrimitiveID would be the obvious source, but llvmpipe
// then routes every triangle through its primitive assembler, which costs about as much as the
// rest of the geometry work together.
layout(location = 0) in vec3 aPosition;

uniform mat4 uView;
uniform mat4 uProj;

// Positive view-space depth. Affine on the triangle, so perspective-correct interpolation gives
// the surface point's depth in float precision at any distance (the z-buffer's does not).
out float vViewDepth;
flat out uint vTriangle;

void main() {
    vec4 viewPosition = uView * vec4(aPosition, 1.0);
    vViewDepth = -viewPosition.z;
    vTriangle = uint(gl_VertexID) / 3u;
    gl_Position = uProj * viewPosition;
}
