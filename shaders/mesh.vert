#version 450 core
// Shaded mesh: positions in model (file) coordinates.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
layout(location = 3) in vec4 aColor;
#ifdef NORMAL_MAP
layout(location = 4) in vec4 aTangent; // core::computeTangents(): xyz, w the bitangent's sign
#endif

uniform mat4 uView;
uniform mat4 uProj;

out vec3 vViewNormal;
out vec3 vViewPosition;
out vec2 vUv;
out vec4 vColor;
#ifdef NORMAL_MAP
out vec4 vTangent;
#endif

void main() {
    vec4 viewPosition = uView * vec4(aPosition, 1.0);
    vViewPosition = viewPosition.xyz;
    // The view matrix is a rigid motion, so it transforms normals as well.
    vViewNormal = mat3(uView) * aNormal;
    vUv = aUv;
    vColor = aColor;
#ifdef NORMAL_MAP
    vTangent = vec4(mat3(uView) * aTangent.xyz, aTangent.w);
#endif
    gl_Position = uProj * viewPosition;
}
