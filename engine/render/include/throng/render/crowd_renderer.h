#pragma once
// The per-frame GPU path: the character buffer upload, the compute pass that resolves every
// joint instance, the barrier, and the instanced sphere draw plus the ground.

#include <array>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "throng/gpu/pipeline.h"
#include "throng/gpu/resources.h"
#include "throng/render/gpu_types.h"
#include "throng/render/palette.h"
#include "throng/render/render_path.h"

namespace throng::render {

struct CrowdRendererCreateInfo {
    RenderPath path = RenderPath::Compute;
    vk::Format colorFormat = vk::Format::eR8G8B8A8Srgb;
    vk::Format depthFormat = vk::Format::eD32Sfloat;
    vk::SampleCountFlagBits samples = vk::SampleCountFlagBits::e1;
    std::uint32_t framesInFlight = 1;   ///< One character/instance/scene buffer set per frame in flight.
    std::uint32_t maxCharacters = 1;    ///< Capacity; checked against the device's storage limits.
    std::uint32_t sphereSegments = 12;  ///< Sphere mesh detail around the equator.
    std::uint32_t sphereRings = 8;      ///< Sphere mesh detail pole to pole.
    float lodPixels = 0.0F;             ///< Fast path: characters shorter than this on screen draw
                                        ///< only their major joints (BakedClip::jointDetail); 0 never.
};

class CrowdRenderer {
public:
    /// Throws ThrongException (BadInput) when maxCharacters × joints exceeds what one storage
    /// buffer can hold on this device, naming the largest crowd that fits.
    CrowdRenderer(const gpu::Context& context, const Palette& palette, const CrowdRendererCreateInfo& info);

    /// Largest crowd the device's storage buffer range allows with `jointsPerCharacter`.
    [[nodiscard]] static std::uint64_t maxCharactersFor(const gpu::Context& context, std::uint32_t jointsPerCharacter);

    /// Copies this frame's characters and scene into the frame's host-visible buffers.
    void update(std::uint32_t frame, std::span<const crowd::CharacterState> characters, const SceneUniforms& scene);
    /// Cpu path: this frame's resolved instances (characters × joints), computed by the caller.
    void uploadInstances(std::uint32_t frame, std::span<const InstanceGpu> instances);
    /// Records the compute resolve and the barrier that hands its output to the vertex shader.
    void recordCompute(const vk::raii::CommandBuffer& commands, std::uint32_t frame) const;
    /// Records the ground and sphere draws; call inside dynamic rendering.
    void recordDraw(const vk::raii::CommandBuffer& commands, std::uint32_t frame, vk::Extent2D extent) const;

    [[nodiscard]] const gpu::Buffer& instances(std::uint32_t frame) const { return frames_[frame].instances; }
    /// Fast path: the draw arguments (vertexCount = visible joints) and, per compacted
    /// instance, the character and joint it belongs to (two uints).
    [[nodiscard]] const gpu::Buffer& drawArguments(std::uint32_t frame) const { return frames_[frame].drawArguments; }
    [[nodiscard]] const gpu::Buffer& instanceOwners(std::uint32_t frame) const { return frames_[frame].instanceOwners; }
    [[nodiscard]] RenderPath path() const { return path_; }
    [[nodiscard]] std::uint32_t jointsPerCharacter() const { return jointsPerCharacter_; }

private:
    struct FrameResources {
        gpu::Buffer characters;  ///< HostUpload, written every frame.
        gpu::Buffer scene;       ///< HostUpload uniform buffer.
        gpu::Buffer instances;   ///< Written by compute (or the CPU), read by the vertex shader.
        gpu::Buffer drawArguments;       ///< Fast path: indirect draw, filled by the compute pass.
        gpu::Buffer instanceOwners;      ///< Fast path: character and joint of each compacted instance.
        PushConstants push;
        vk::raii::DescriptorSet descriptors{nullptr};
        std::uint32_t characterCount = 0;
    };

    const gpu::Context* context_;
    RenderPath path_;
    float cullRadius_ = 1.0F, cullHeight_ = 1.0F, lodPixels_ = 0.0F;
    std::uint32_t jointsPerCharacter_;
    std::uint32_t maxCharacters_;
    std::uint32_t sphereIndexCount_ = 0;
    gpu::Buffer sphereVertices_, sphereIndices_;
    vk::raii::DescriptorSetLayout setLayout_{nullptr};
    vk::raii::PipelineLayout pipelineLayout_{nullptr};
    vk::raii::Pipeline resolvePipeline_{nullptr}, spherePipeline_{nullptr}, groundPipeline_{nullptr};
    vk::raii::Pipeline paperPipeline_{nullptr}, cullPipeline_{nullptr}, impostorPipeline_{nullptr};
    vk::raii::DescriptorPool descriptorPool_{nullptr};
    std::vector<FrameResources> frames_;
};

/// Resolves every joint of every character on the CPU, as the compute pass does (the cpu
/// path, and a reference). `out` holds characters × jointsPerCharacter entries.
void resolveInstancesOnCpu(std::span<const motion::BakedClip> clips, std::span<const crowd::CharacterState> characters,
                           std::uint32_t jointsPerCharacter, std::span<InstanceGpu> out);

/// World-space frustum planes of a view-projection matrix (Vulkan depth 0..1), normalised,
/// inside where dot(xyz, p) + w >= 0.
[[nodiscard]] std::array<glm::vec4, 6> frustumPlanes(const glm::mat4& viewProjection);

/// Unit UV sphere: positions (which are also normals) and counter-clockwise triangle indices.
struct SphereMesh {
    std::vector<glm::vec3> positions;
    std::vector<std::uint16_t> indices;
};
[[nodiscard]] SphereMesh makeUnitSphere(std::uint32_t segments, std::uint32_t rings);

}  // namespace throng::render
