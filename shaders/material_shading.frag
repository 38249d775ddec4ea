#version 450 core
// The lit metallic-roughness material, one definition for both shaded views: composite.frag (the
// depth layers' composite) and mesh.frag (the mesh and its stand-in while the camera moves) are
// linked with this file and declare shadeMaterial().
const float kPi = 3.14159265;

// Both files also use mappedNormal() and occludedAmbient() for a material's maps.

// Metallic-roughness in view space with the viewer along +z: Lambert as the headlight shading
// already gives it (lit = albedo × (ambient + 0.75 headlight); ambient is 0.25, less where an
// occlusion map darkens it), GGX specular from a key, a fill and a rim light, and a
// sky-over-ground environment blurred by roughness that metal reflects tinted by its colour,
// occluded as the ambient is.
vec3 shadeMaterial(vec3 lit, float ambient, float headlight, float roughness, float metallic,
                   vec3 n) {
    vec3 albedo = lit / (ambient + 0.75 * headlight);
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
    return lit * (1.0 - metallic) + specular +
           environment * fresnelEnv * environmentWeight * (ambient / 0.25);
}

// glTF's normal map: the facing normal n turned by a tangent-space texel (x right, y up the
// image, z out). tangent.xyz follows increasing u (any length, not yet perpendicular to n) and
// tangent.w is the sign of the bitangent cross(n, t); axes turns the mesh uvs' tangent frame into
// the map's (its placement, render::SurfaceMaps).
vec3 mappedNormal(vec3 n, vec4 tangent, vec3 texel, float scale, mat2 axes) {
    vec3 t = tangent.xyz - n * dot(n, tangent.xyz);
    if (!(dot(t, t) > 1e-12))
        return n;
    t = normalize(t);
    vec3 b = tangent.w * cross(n, t);
    vec3 tm = normalize(t * axes[0][0] + b * axes[0][1]);
    vec3 bm = normalize(t * axes[1][0] + b * axes[1][1]);
    vec3 m = texel * 2.0 - 1.0;
    m.xy *= scale;
    vec3 mapped = tm * m.x + bm * m.y + n * m.z;
    return dot(mapped, mapped) > 1e-12 ? normalize(mapped) : n;
}

// The ambient light's share where an occlusion map (its red texel) darkens it by strength.
float occludedAmbient(float occlusion, float strength) {
    return 0.25 * (1.0 + strength * (occlusion - 1.0));
}
