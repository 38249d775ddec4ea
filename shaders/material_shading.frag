#version 450 core
// The lit metallic-roughness material, one definition for both shaded views: composite.frag (the
// depth layers' composite) and mesh.frag (the mesh and its stand-in while the camera moves) are
// linked with this file and declare shadeMaterial().
const float kPi = 3.14159265;

// Metallic-roughness in view space with the viewer along +z: Lambert as the headlight shading
// already gives it (lit, with its ambient), GGX specular from a key, a fill and a rim light, and
// a sky-over-ground environment blurred by roughness that metal reflects tinted by its colour.
vec3 shadeMaterial(vec3 lit, float headlight, float roughness, float metallic, vec3 n) {
    vec3 albedo = lit / (0.25 + 0.75 * headlight);
    vec3 f0 = mix(vec3(0.04), albedo, metallic);
    float r = clamp(roughness, 0.05, 1.0);
    float a2 = r * r * r * r;
    float k = 0.5 * r * r;
    const vec3 v = vec3(0.0, 0.0, 1.0);
    float nv = max(n.z, 1e-3);
    const vec3 lights[3] = vec3[3](vec3(-0.5, 0.6, 0.62), vec3(0.78, -0.1, 0.62),
                                   vec3(0.2, 0.48, -0.85));
    const float power[3] = float[3](2.4, 0.6, 1.6);
    vec3 specular = vec3(0.0);
    for (int i = 0; i < 3; ++i) {
        vec3 l = normalize(lights[i]);
        vec3 h = normalize(l + v);
        float nl = max(dot(n, l), 0.0);
        float nh = max(dot(n, h), 0.0);
        float d = nh * nh * (a2 - 1.0) + 1.0;
        float ggx = a2 / (kPi * d * d);
        float visibility = 1.0 / (4.0 * (nl * (1.0 - k) + k) * (nv * (1.0 - k) + k));
        vec3 fresnel = f0 + (1.0 - f0) * pow(1.0 - max(dot(v, h), 0.0), 5.0);
        specular += power[i] * nl * ggx * visibility * fresnel;
    }
    // The environment: sky over dark ground and two soft boxes where the key and the fill
    // light are, wider and dimmer the rougher the surface, so curved metal shows bands.
    vec3 reflected = reflect(-v, n);
    float sky = smoothstep(-0.3, 0.5, reflected.y);
    float width = mix(0.03, 0.7, r);
    float boxes = 2.5 * smoothstep(1.0 - width - 0.04, 1.0 - 0.5 * width,
                                   dot(reflected, normalize(lights[0]))) +
                  1.2 * smoothstep(1.0 - width - 0.04, 1.0 - 0.5 * width,
                                   dot(reflected, normalize(lights[1])));
    vec3 environment = mix(vec3(mix(0.06, 0.8, sky) + boxes * (1.0 - 0.8 * r)), vec3(0.45), r * r);
    vec3 fresnelEnv = f0 + (max(vec3(1.0 - r), f0) - f0) * pow(1.0 - nv, 5.0);
    // A rough dielectric's environment is the headlight shading's ambient already.
    float environmentWeight = mix(1.0 - r, 1.0, metallic);
    return lit * (1.0 - metallic) + specular + environment * fresnelEnv * environmentWeight;
}
