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

// What a pixel's shading shares between the surfaces along its ray: the way to the eye and the
// Blinn-Phong halfway vector depend only on the ray, not on which surface it meets.
struct View {
    vec3 toEye, halfway;
};

View viewAlong(vec3 toEye) { return View(toEye, normalize(scene.lightDirection.xyz + toEye)); }

// shade() for a unit normal seen along `view` from `distanceToEye`.
vec3 shadeSeen(vec3 albedo, vec3 n, View view, float distanceToEye, float shininess, float specularStrength) {
    const vec3 toLight = scene.lightDirection.xyz;
    const float diffuse = max(dot(n, toLight), 0.0);
    const float specular = diffuse > 0.0 ? highlight(max(dot(n, view.halfway), 0.0), shininess) * specularStrength : 0.0;
    const vec3 ambient = mix(scene.bounceColor.rgb, scene.skyColor.rgb, 0.5 + 0.5 * n.y);
    const vec3 lit = albedo * (ambient + diffuse * scene.lightColor.rgb) + specular * scene.lightColor.rgb;
    const float fog = smoothstep(scene.groundParams.z, scene.groundParams.w, distanceToEye);
    return mix(lit, scene.fogColor.rgb, fog);
}

vec3 shade(vec3 albedo, vec3 normal, vec3 position, float shininess, float specularStrength) {
    const vec3 toEye = normalize(scene.cameraPosition.xyz - position);
    return shadeSeen(albedo, normalize(normal), viewAlong(toEye), length(scene.cameraPosition.xyz - position), shininess, specularStrength);
}

#endif
