#include "throng/render/camera.h"

#include <algorithm>
#include <cmath>

namespace throng::render {

glm::mat4 Camera::projection(float aspect) const {
    glm::mat4 projection = glm::perspective(glm::radians(verticalFovDegrees), aspect, nearPlane, farPlane);
    projection[1][1] *= -1.0F;  // Vulkan's clip space has y pointing down
    projection[2][0] = -lensShiftX;  // x_ndc += lensShiftX (clip w is -z_view)
    return projection;
}

glm::mat4 Camera::viewProjection(float aspect) const { return projection(aspect) * glm::lookAt(eye, target, upFor(target - eye)); }

glm::mat4 Camera::viewProjectionAtEye(float aspect) const {
    const glm::vec3 forward = target - eye;
    return projection(aspect) * glm::lookAt(glm::vec3(0.0F), forward, upFor(forward));
}

glm::vec3 Camera::upFor(glm::vec3 forward) {
    // World up, unless the view is (nearly) vertical, where it no longer picks a direction
    // (lookAt's cross product would vanish and the view with it): then +Z, the direction a
    // camera of azimuth 0 faces, is the top of the image.
    const float length = glm::length(forward);
    const bool vertical = !(glm::length(glm::vec2(forward.x, forward.z)) > 1e-4F * length);  // within 0.006 degrees
    return vertical ? glm::vec3(0.0F, 0.0F, 1.0F) : glm::vec3(0.0F, 1.0F, 0.0F);
}

Camera frameCrowd(std::span<const glm::vec3> points, float height, float aspect, float azimuthDegrees,
                  float elevationDegrees) {
    glm::vec3 lo(1e30F), hi(-1e30F);
    for (const glm::vec3& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p + glm::vec3(0.0F, height, 0.0F));
    }
    if (points.empty()) lo = hi = glm::vec3(0.0F);
    lo -= glm::vec3(0.5F, 0.0F, 0.5F);  // half a body of margin around the outermost characters
    hi += glm::vec3(0.5F, 0.0F, 0.5F);
    Camera camera;
    const glm::vec3 centre = 0.5F * (lo + hi);
    const float azimuth = glm::radians(azimuthDegrees), elevation = glm::radians(elevationDegrees);
    const glm::vec3 forward(std::sin(azimuth) * std::cos(elevation), -std::sin(elevation), std::cos(azimuth) * std::cos(elevation));
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0F, 1.0F, 0.0F)));
    const glm::vec3 up = glm::cross(right, forward);
    const float tanV = std::tan(glm::radians(camera.verticalFovDegrees) / 2.0F), tanH = tanV * aspect;
    // Back off from the centre until every corner of the crowd's box is inside the frustum:
    // a corner at (x, y, z) in the camera basis needs distance >= |x| / tanH - z, likewise for y.
    float distance = 1.0F, farthest = 0.0F;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
        const glm::vec3 d = p - centre;
        const float z = glm::dot(d, forward);
        distance = std::max({distance, std::abs(glm::dot(d, right)) / tanH - z, std::abs(glm::dot(d, up)) / tanV - z});
        farthest = std::max(farthest, glm::length(d));
    }
    camera.target = centre;
    camera.nearPlane = std::max(0.05F, (distance - farthest) * 0.5F);
    camera.farPlane = distance + 4.0F * farthest + 100.0F;
    // Under perspective the box's centre is not the centre of its picture: recentre the
    // projected box and rescale the distance until it fills the frame with a small margin.
    constexpr float kFill = 0.94F;
    for (int pass = 0; pass < 8; ++pass) {
        camera.eye = camera.target - forward * distance;
        const glm::mat4 viewProjection = camera.viewProjection(aspect);
        glm::vec2 ndcLo(1e30F), ndcHi(-1e30F);
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec4 clip = viewProjection * glm::vec4((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y,
                                                              (corner & 4) ? hi.z : lo.z, 1.0F);
            const glm::vec2 ndc = glm::vec2(clip) / std::max(clip.w, 1e-3F);
            ndcLo = glm::min(ndcLo, ndc);
            ndcHi = glm::max(ndcHi, ndc);
        }
        const glm::vec2 middle = 0.5F * (ndcLo + ndcHi);
        // NDC y points down in Vulkan, so a positive middle.y means the picture sits low.
        camera.target += right * (middle.x * distance * tanH) - up * (middle.y * distance * tanV);
        distance *= std::max(0.5F * (ndcHi.x - ndcLo.x), 0.5F * (ndcHi.y - ndcLo.y)) / kFill;
    }
    camera.eye = camera.target - forward * distance;
    return camera;
}

Camera streetCamera(std::span<const glm::vec3> points, float aspect, float azimuthDegrees) {
    glm::vec2 lo(0.0F), hi(0.0F);
    if (!points.empty()) lo = hi = glm::vec2(points.front().x, points.front().z);
    for (const glm::vec3& p : points) {
        lo = glm::min(lo, glm::vec2(p.x, p.z));
        hi = glm::max(hi, glm::vec2(p.x, p.z));
    }
    const glm::vec2 centre = 0.5F * (lo + hi), half = 0.5F * (hi - lo) + 0.5F;
    const float azimuth = glm::radians(azimuthDegrees);
    const glm::vec2 forward(std::sin(azimuth), std::cos(azimuth));
    // Back from the centre to where that line leaves the crowd's box, then a few steps more.
    const float toEdge = std::min(half.x / std::max(std::abs(forward.x), 1e-3F), half.y / std::max(std::abs(forward.y), 1e-3F));
    const glm::vec2 standing = centre - forward * (toEdge + 3.0F);
    const float extent = 2.0F * std::max(half.x, half.y);
    const float height = std::clamp(0.07F * extent, 2.5F, 8.0F);
    // About 10 degrees down, steeper when the crowd's centre is nearer than that would look.
    const float ahead = std::min(height / std::tan(glm::radians(10.0F)), glm::max(toEdge + 3.0F, height));
    Camera camera;
    // A narrower picture (portrait) gets a wider vertical angle, so as much of the crowd shows across.
    camera.verticalFovDegrees = aspect >= 1.0F ? 40.0F : std::min(70.0F, 40.0F / std::max(aspect, 0.5F));
    camera.eye = glm::vec3(standing.x, height, standing.y);
    camera.target = glm::vec3(standing.x + forward.x * ahead, 0.0F, standing.y + forward.y * ahead);
    camera.nearPlane = 0.1F;
    camera.farPlane = 2.0F * (toEdge + 3.0F) + 4.0F * extent + 200.0F;
    return camera;
}

std::array<glm::vec4, 6> frustumPlanes(const glm::mat4& m) {
    const auto row = [&](int i) { return glm::vec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
    // Gribb and Hartmann: clip-space inequalities -w <= x, y <= w and 0 <= z <= w as planes.
    std::array<glm::vec4, 6> planes{row(3) + row(0), row(3) - row(0), row(3) + row(1), row(3) - row(1), row(2), row(3) - row(2)};
    for (glm::vec4& p : planes) p /= glm::length(glm::vec3(p));
    return planes;
}

}  // namespace throng::render
