#include "throng/render/scene_look.h"

#include <algorithm>

namespace throng::render {

glm::vec3 skyColor() { return {0.62F, 0.70F, 0.78F}; }

std::array<float, 4> skyClearColor() {
    const glm::vec3 sky = skyColor();
    return {sky.r, sky.g, sky.b, 1.0F};
}

SceneUniforms makeScene(const Camera& camera, vk::Extent2D viewport, float groundHalfExtent, bool followsPrevious) {
    SceneUniforms scene;
    scene.levelFadesContinue = followsPrevious ? 1.0F : 0.0F;
    const float width = static_cast<float>(viewport.width), height = static_cast<float>(std::max(viewport.height, 1U));
    scene.viewProjection = camera.viewProjection(width / height);
    scene.inverseViewProjectionAtEye = glm::inverse(camera.viewProjectionAtEye(width / height));
    const float focal = 0.5F * height / std::tan(glm::radians(camera.verticalFovDegrees) * 0.5F);
    scene.viewport = glm::vec4(width, height, focal, 255.0F);
    scene.cameraPosition = camera.eye;
    scene.lightDirection = glm::normalize(glm::vec3(-0.45F, 0.8F, -0.35F));
    scene.lightColor = glm::vec4(0.95F, 0.9F, 0.82F, 0.0F);
    scene.skyColor = glm::vec4(0.32F, 0.36F, 0.42F, 0.0F);
    scene.bounceColor = glm::vec4(0.12F, 0.11F, 0.10F, 0.0F);
    const float distance = glm::length(camera.eye - camera.target);
    scene.groundParams = glm::vec4(groundHalfExtent, 2.0F, distance * 1.6F + 20.0F, distance * 3.5F + 60.0F);
    scene.fogColor = glm::vec4(skyColor(), 0.0F);
    return scene;
}

}  // namespace throng::render
