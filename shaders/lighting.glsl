// Phong shading shared by the spheres and the ground: a key light, hemisphere ambient
// (sky from above, bounce from below), Blinn-Phong highlights, and distance fog.
#ifndef THRONG_LIGHTING_GLSL
#define THRONG_LIGHTING_GLSL

// pow(x, shininess) for the two exponents the shaders use, 16 and 48, by squaring: a CPU
// rasteriser evaluates pow as exp2(log2) polynomials for every pixel, four multiplies are cheaper.
float highlight(float x, float shininess) {
    const float x2 = x * x, x4 = x2 * x2, x8 = x4 * x4, x16 = x8 * x8;
    return shininess > 32.0 ? x16 * x16 * x16 : x16;
}

vec3 shade(vec3 albedo, vec3 normal, vec3 position, float shininess, float specularStrength) {
    const vec3 n = normalize(normal);
    const vec3 toLight = scene.lightDirection.xyz;
    const vec3 toEye = normalize(scene.cameraPosition.xyz - position);
    const float diffuse = max(dot(n, toLight), 0.0);
    const vec3 halfway = normalize(toLight + toEye);
    const float specular = diffuse > 0.0 ? highlight(max(dot(n, halfway), 0.0), shininess) * specularStrength : 0.0;
    const vec3 ambient = mix(scene.bounceColor.rgb, scene.skyColor.rgb, 0.5 + 0.5 * n.y);
    const vec3 lit = albedo * (ambient + diffuse * scene.lightColor.rgb) + specular * scene.lightColor.rgb;
    const float distanceToEye = length(scene.cameraPosition.xyz - position);
    const float fog = smoothstep(scene.groundParams.z, scene.groundParams.w, distanceToEye);
    return mix(lit, scene.fogColor.rgb, fog);
}

#endif
