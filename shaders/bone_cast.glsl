// A bone's tapered capsule ray-cast through a pixel (the convex hull of a sphere at each end:
// two spheres and the cone tangent to both), optionally flattened along one axis (soles,
// palms): exact silhouette, normal and depth. Shared by the bone sprites (bone.frag) and the
// visibility path's splat and shading, so both draw the same bodies.
//
// The cone: with the axis from the start a (radius ra) to the end b (rb), length L, a point at
// distance x along the axis and rho from it is on the cone's side when
//   sin * x + cos * rho = ra,  sin = (ra - rb) / L, cos = sqrt(1 - sin^2),
// a line tangent to both end circles in the (x, rho) profile, touching them at x = ra sin and
// x = L + rb sin. Squaring gives a quadratic along the ray. The first point where the ray meets
// any of the three surfaces is where it enters the (convex) capsule.
#ifndef THRONG_BONE_CAST_GLSL
#define THRONG_BONE_CAST_GLSL

const float kMiss = 1e30;

// The flattened shape is the round one squeezed along flatten.xyz by its thickness w; this
// stretches a vector back (1 / w along the axis). It maps normals forward too: the squeeze's
// inverse transpose is the same stretch.
vec3 unflatten(vec3 v, vec4 flatten) {
    return v + (1.0 / flatten.w - 1.0) * dot(v, flatten.xyz) * flatten.xyz;
}

// Where the ray o + t d (d not unit) first enters the sphere, or kMiss.
float sphereEntry(vec3 o, vec3 d, vec3 centre, float radius) {
    const vec3 oc = o - centre;
    const float a = dot(d, d), b = dot(oc, d), c = dot(oc, oc) - radius * radius;
    const float h = b * b - a * c;
    if (h < 0.0) return kMiss;
    const float t = (-b - sqrt(h)) / a;
    return t > 0.0 ? t : kMiss;
}

struct BoneHit {
    float t;        // distance along the unit ray to the surface (kMiss: none)
    vec3 normal;    // the round shape's, before unflatten()
    float inside;   // how far the ray passes inside the capsule, metres: its rim coverage
};

// The unit ray from `eye` along `direction` against the capsule from start.xyz (radius start.w)
// to end.xyz (end.w), flattened by `flatten`.
BoneHit castBone(vec3 eye, vec3 direction, vec4 start, vec4 end, vec4 flatten) {
    // Into the round shape's space, about the bone's middle (t is the same in both spaces), and
    // with the middle as the origin: far from the world's origin (30 km), a float position holds
    // millimetres only, and the eye and the ends' small offsets from each other would round away.
    const vec3 middle = 0.5 * (start.xyz + end.xyz);
    const vec3 a = start.xyz - middle, b = end.xyz - middle;
    const float ra = start.w, rb = end.w;
    const vec3 o = unflatten(eye - middle, flatten), d = unflatten(direction, flatten);

    BoneHit hit;
    hit.t = kMiss;
    hit.normal = vec3(0.0, 1.0, 0.0);
    const float tStart = sphereEntry(o, d, a, ra);
    if (tStart < hit.t) { hit.t = tStart; hit.normal = (o + tStart * d - a) / ra; }
    const float tEnd = sphereEntry(o, d, b, rb);
    if (tEnd < hit.t) { hit.t = tEnd; hit.normal = (o + tEnd * d - b) / rb; }
    const vec3 ab = b - a;
    const float len = length(ab);
    if (len > abs(ra - rb) + 1e-6) {  // else one sphere holds the other: no side
        const vec3 u = ab / len;
        const float sine = (ra - rb) / len, cosine = sqrt(1.0 - sine * sine);
        const vec3 w0 = o - a;
        const float x0 = dot(w0, u), xd = dot(d, u);
        const float c2 = cosine * cosine, reach = ra - sine * x0;
        const float q2 = c2 * (dot(d, d) - xd * xd) - sine * sine * xd * xd;
        const float q1 = c2 * (dot(w0, d) - x0 * xd) + sine * xd * reach;
        const float q0 = c2 * (dot(w0, w0) - x0 * x0) - reach * reach;
        const float h = q1 * q1 - q2 * q0;
        if (h >= 0.0 && abs(q2) > 1e-12) {
            const float root = sqrt(h);
            for (int k = 0; k < 2; ++k) {
                const float t = (-q1 + (k == 0 ? -root : root)) / q2;
                const float x = x0 + t * xd;
                if (t > 0.0 && t < hit.t && x >= ra * sine && x <= len + rb * sine && ra - sine * x >= 0.0) {
                    hit.t = t;
                    const vec3 radial = w0 + t * d - x * u;
                    hit.normal = sine * u + cosine * normalize(radial);
                }
            }
        }
    }
    // How far the ray passes inside the capsule: its radius there less the ray's distance from
    // the axis (for the rim's coverage).
    const vec3 dn = normalize(d);
    const vec3 w = o - a;
    const float along = dot(dn, ab), axisSq = dot(ab, ab);
    const float denominator = axisSq - along * along;
    const float s = denominator > 1e-9 ? clamp((dot(ab, w) - dot(dn, w) * along) / denominator, 0.0, 1.0) : 0.0;
    const float t = s * along - dot(dn, w);
    hit.inside = mix(ra, rb, s) - length(w + t * dn - s * ab);
    return hit;
}

// The round capsule castBone casts (start.xyz, radius start.w, to end.xyz, end.w), at `p`, a
// point on its surface: the outward normal, and the radius of the sphere inside it that touches
// there. The surfaces are castBone's: the start sphere where p lies along the axis before
// ra sine, the end sphere past L + rb sine, the cone between. A joint sphere is the capsule
// whose ends coincide. The visibility path's shading takes this from the splat's hit point
// instead of casting the ray again.
vec3 boneNormalAt(vec3 p, vec4 start, vec4 end, out float radius) {
    const vec3 a = start.xyz, b = end.xyz;
    const float ra = start.w, rb = end.w;
    const vec3 ab = b - a;
    const float len = length(ab);
    // The end sphere holds the other (or they coincide): the capsule is that sphere.
    const bool oneSphere = len <= abs(ra - rb) + 1e-6;
    const vec3 u = ab / max(len, 1e-6);
    const float sine = oneSphere ? 0.0 : (ra - rb) / len, cosine = sqrt(1.0 - sine * sine);
    const float x = dot(p - a, u);
    const bool onStart = oneSphere ? ra >= rb : x <= ra * sine;
    const bool onEnd = oneSphere ? ra < rb : x >= len + rb * sine;
    const vec3 radial = p - a - x * u;
    const float rho = length(radial);
    radius = onStart ? ra : onEnd ? rb : rho / cosine;
    if (!onStart && !onEnd && rho > 1e-9) return sine * u + cosine * (radial / rho);
    const vec3 fromCentre = p - (onEnd ? b : a);
    return dot(fromCentre, fromCentre) > 0.0 ? normalize(fromCentre) : vec3(0.0, 1.0, 0.0);
}

#endif
