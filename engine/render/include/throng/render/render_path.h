#pragma once
// The render paths by name. Vulkan-free on purpose: the command line and the benchmark
// validate path names against this one table without pulling in the GPU code.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace throng::render {

/// How joints reach the screen. All draw the same crowd; they differ in where the work is.
enum class RenderPath : std::uint8_t {
    Paper,    ///< No compute pass: the sphere's vertex shader resolves its joint (the paper's method).
    Cpu,      ///< Joints resolved on the CPU and uploaded every frame (the naive path).
    Compute,  ///< A compute pass resolves every joint once, then instanced sphere meshes.
    Fast,     ///< Compute pass with frustum culling into an indirect draw of ray-cast point sprites.
    /// The fast path's culling, then a compute splat of every visible joint's exact sphere (and
    /// bone's capsule) into a per-pixel (depth, joint) buffer by 64-bit atomicMin, shaded in one
    /// pass square by square with the ground: no rasteriser work per joint. One sample, rims
    /// smoothed analytically; skinned bodies rasterised over it (see the README).
    Visibility,
};

/// Every path, in the order the benchmark sweeps them.
inline constexpr std::array<RenderPath, 5> kRenderPaths{RenderPath::Paper, RenderPath::Cpu, RenderPath::Compute,
                                                        RenderPath::Fast, RenderPath::Visibility};

/// The name used on the command line and in benchmark output ("paper", "cpu", "compute", "fast", "visibility").
[[nodiscard]] constexpr std::string_view renderPathName(RenderPath path) {
    constexpr std::array<std::string_view, 5> names{"paper", "cpu", "compute", "fast", "visibility"};
    return names[static_cast<std::size_t>(path)];
}

/// The path called `name`, or nullopt for an unknown name.
[[nodiscard]] constexpr std::optional<RenderPath> renderPathFromName(std::string_view name) {
    for (const RenderPath path : kRenderPaths)
        if (renderPathName(path) == name) return path;
    return std::nullopt;
}

/// The multisampling a path draws with when `wanted` samples are asked for: the visibility
/// path smooths its rims analytically and shades the ground filtered, so more samples would
/// change no pixel and only cost; it draws with one.
[[nodiscard]] constexpr std::uint32_t samplesFor(RenderPath path, std::uint32_t wanted) {
    return path == RenderPath::Visibility ? 1U : wanted;
}

/// "paper, cpu, compute, fast or visibility": for help and error texts.
[[nodiscard]] inline std::string renderPathList() {
    std::string list;
    for (std::size_t i = 0; i < kRenderPaths.size(); ++i)
        list += (i == 0 ? "" : i + 1 == kRenderPaths.size() ? " or " : ", ") + std::string(renderPathName(kRenderPaths[i]));
    return list;
}

/// What each character is drawn as.
enum class Body : std::uint8_t {
    Spheres,  ///< A sphere per joint: the paper's look, on every path.
    Bones,    ///< A tapered capsule per bone, ray-cast (the fast path draws them).
    Auto,     ///< Level of detail by screen size: skinned near, bones further, joint spheres far (the fast path).
    Skin,     ///< A skinned mesh generated from the bones (the fast path draws them).
};

inline constexpr std::array<Body, 4> kBodies{Body::Spheres, Body::Bones, Body::Skin, Body::Auto};

/// Whether `body` draws characters at more than one level of detail, dissolving a character
/// from one into the next over frames (scene_look.h's kLevelFadeFrames): only then does a
/// video's frame depend on the frames before it.
[[nodiscard]] constexpr bool fadesBetweenLevels(Body body) { return body == Body::Auto; }

[[nodiscard]] constexpr std::string_view bodyName(Body body) {
    constexpr std::array<std::string_view, 4> names{"spheres", "bones", "auto", "skin"};
    return names[static_cast<std::size_t>(body)];
}

/// --body auto: characters at least this many pixels tall on screen draw bones, smaller ones
/// joint spheres. Below it a bone is a pixel or two wide and reads no better than a sphere,
/// while its quad costs lavapipe several times a sprite's (at 12 pixels, 2000 characters seen
/// from above drew in 325 ms against 135 ms at 24).
inline constexpr float kAutoBonePixels = 24.0F;
/// --body auto: characters at least this many pixels tall draw skinned meshes (their smooth
/// silhouette and shading show from here; below, a bone is a few pixels wide and capsules
/// look the same for less).
inline constexpr float kAutoSkinPixels = 140.0F;

[[nodiscard]] constexpr std::optional<Body> bodyFromName(std::string_view name) {
    for (const Body body : kBodies)
        if (bodyName(body) == name) return body;
    return std::nullopt;
}

}  // namespace throng::render
