// The naive path: every joint of every character resolved on the CPU and uploaded each frame,
// then drawn as instanced sphere meshes.
#include <vector>

#include "throng/render/crowd_renderer.h"

#include "sphere_draw.h"
#include "throng/shaders/sphere_vert.h"

namespace throng::render::detail {
namespace {

class CpuPath final : public RenderPathImpl {
public:
    explicit CpuPath(const PathSetup& setup)
        : spheres_(setup, kSphereVertSpirv), clips_(setup.clips), joints_(setup.jointsPerCharacter) {}
    [[nodiscard]] RenderPath path() const override { return RenderPath::Cpu; }
    [[nodiscard]] InstanceStorage storage() const override { return {.intent = gpu::MemoryIntent::HostUpload}; }

    void prepare(SlotBuffers& slot, std::span<const crowd::CharacterState> characters) override {
        resolved_.resize(characters.size() * joints_);
        resolveInstancesOnCpu(clips_, characters, joints_, resolved_);
        slot.instances.write(std::as_bytes(std::span(resolved_)));
    }
    void recordDraw(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const override {
        spheres_.record(commands, slot, joints_);
    }

private:
    SphereDraw spheres_;
    std::span<const motion::BakedClip> clips_;
    std::uint32_t joints_;
    std::vector<InstanceGpu> resolved_;  ///< Scratch reused every frame.
};

}  // namespace

std::unique_ptr<RenderPathImpl> makeCpuPath(const PathSetup& setup) { return std::make_unique<CpuPath>(setup); }

}  // namespace throng::render::detail

namespace throng::render {

void resolveInstancesOnCpu(std::span<const motion::BakedClip> clips, std::span<const crowd::CharacterState> characters,
                           std::uint32_t jointsPerCharacter, std::span<InstanceGpu> out) {
    for (std::size_t m = 0; m < characters.size(); ++m) {
        const crowd::CharacterState& c = characters[m];
        const motion::BakedClip& clip = clips[c.clip];
        const glm::vec4 color(glm::unpackUnorm4x8(c.color));
        for (std::uint32_t j = 0; j < jointsPerCharacter; ++j) {
            InstanceGpu& instance = out[m * jointsPerCharacter + j];
            if (j >= static_cast<std::uint32_t>(clip.jointCount())) {  // a clip with fewer joints than k
                instance = {glm::vec4(0.0F), glm::vec4(0, 0, 0, 1), glm::vec4(0.0F)};
                continue;
            }
            const crowd::JointWorld joint = crowd::sampleJointWorld(clips, c, static_cast<int>(j));
            instance = {glm::vec4(joint.position, joint.radius),
                        glm::vec4(joint.orientation.x, joint.orientation.y, joint.orientation.z, joint.orientation.w),
                        glm::vec4(glm::vec3(color), 1.0F)};
        }
    }
}

}  // namespace throng::render
