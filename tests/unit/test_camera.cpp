// The render camera (render/camera.h): every view it is given shows what lies in front of it.
#include <gtest/gtest.h>

#include <cmath>

#include "throng/render/camera.h"

namespace {

using throng::render::Camera;

// Where a world point lands in normalised device coordinates, or NaN when it does not.
glm::vec3 project(const Camera& camera, glm::vec3 point) {
    const glm::vec4 clip = camera.viewProjection(16.0F / 9.0F) * glm::vec4(point, 1.0F);
    return glm::vec3(clip) / clip.w;
}

bool onScreen(glm::vec3 ndc) {
    return std::isfinite(ndc.x) && std::isfinite(ndc.y) && std::isfinite(ndc.z) && std::abs(ndc.x) <= 1.0F &&
           std::abs(ndc.y) <= 1.0F && ndc.z >= 0.0F && ndc.z <= 1.0F;
}

TEST(Camera, AViewStraightDownOrUpShowsTheGroundAroundItsTarget) {
    // glm::lookAt with world up along the view has no sideways direction: the whole view
    // became NaN and the image only sky, with exit 0.
    for (const float height : {10.0F, -10.0F}) {
        Camera camera;
        camera.eye = {3.0F, height, -2.0F};
        camera.target = {3.0F, 0.0F, -2.0F};
        const glm::vec3 centre = project(camera, camera.target);
        ASSERT_TRUE(onScreen(centre)) << height;
        EXPECT_NEAR(centre.x, 0.0F, 1e-5F);
        EXPECT_NEAR(centre.y, 0.0F, 1e-5F);
        // A metre off the target on the ground is still in view, off the centre.
        for (const glm::vec3 offset : {glm::vec3(1, 0, 0), glm::vec3(0, 0, 1)}) {
            const glm::vec3 ndc = project(camera, camera.target + offset);
            EXPECT_TRUE(onScreen(ndc)) << height;
            EXPECT_GT(std::abs(ndc.x) + std::abs(ndc.y), 0.01F) << height;
        }
    }
    // Looking down, +Z is the top of the image (Vulkan's y points down).
    Camera down;
    down.eye = {0.0F, 10.0F, 0.0F};
    down.target = {0.0F, 0.0F, 0.0F};
    EXPECT_LT(project(down, {0.0F, 0.0F, 1.0F}).y, 0.0F);
}

TEST(Camera, AnOrdinaryViewKeepsWorldUpAsTheImagesUp) {
    Camera camera;  // from behind and above, looking at the origin
    EXPECT_EQ(Camera::upFor(camera.target - camera.eye), glm::vec3(0.0F, 1.0F, 0.0F));
    // A nearly vertical view still has a sideways direction: world up stays.
    EXPECT_EQ(Camera::upFor({0.0F, -10.0F, 0.01F}), glm::vec3(0.0F, 1.0F, 0.0F));
    EXPECT_EQ(Camera::upFor({0.0F, -10.0F, 0.0F}), glm::vec3(0.0F, 0.0F, 1.0F));
    // A point above a point below on screen: higher in the world, higher in the image.
    EXPECT_LT(project(camera, {0.0F, 2.0F, 0.0F}).y, project(camera, {0.0F, 0.0F, 0.0F}).y);
}

}  // namespace
