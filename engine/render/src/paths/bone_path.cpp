// Bone bodies (--body bones, skin, auto) on the fast path's plan: a planning pass, one compute
// invocation per character, culls it against the view frustum and lists it for the writers
// its size on screen needs; each writer, dispatched indirectly over its list, writes the bones
// (tapered capsules, resolved from the same palette sampling) for one indirect draw of a
// 4-vertex quad per bone, which bone.frag ray-casts, or joint spheres, or skinning transforms,
// over a soft contact shadow per character. The visibility path's form splats the bones,
// joints and shadows instead (visibility_path.cpp). No per-frame CPU work beyond the
// characters' states.
#include <algorithm>
#include <cstddef>
#include <limits>
#include <string>

#include "render_path_impl.h"
#include "skin_meshes.h"
#include "throng/core/log.h"
#include "throng/motion/body_mesh.h"
#include "throng/shaders/bone_frag.h"
#include "throng/shaders/bone_vert.h"
#include "throng/shaders/contact_shadow_frag.h"
#include "throng/shaders/contact_shadow_vert.h"
#include "throng/shaders/resolve_bones_comp.h"
#include "throng/shaders/skin_frag.h"
#include "throng/shaders/skin_over_splat_frag.h"
#include "throng/shaders/skin_vert.h"

namespace throng::render::detail {
namespace {

constexpr std::uint32_t kWorkgroupSize = kPlanWorkgroup;
constexpr std::uint32_t kAllocatePass = 1 + kBodyWriters;  // resolve_bones.comp's kAllocate
constexpr std::uint32_t kQuadVertices = 4;    // one triangle strip per bone
using Stage = vk::PipelineStageFlagBits2;
using Access = vk::AccessFlagBits2;

// Skinned bodies' vertex input: motion::SkinVertex as it is. Over a splat (the visibility
// path, whose shading writes no depth) they test against its visibility buffer and the ground.
vk::raii::Pipeline createSkinPipeline(const PathSetup& setup, bool overSplat) {
    const auto vertex = gpu::createShaderModule(*setup.context, kSkinVertSpirv);
    const auto fragment = gpu::createShaderModule(*setup.context, overSplat ? std::span<const std::uint32_t>(kSkinOverSplatFragSpirv)
                                                                            : std::span<const std::uint32_t>(kSkinFragSpirv));
    using Format = vk::Format;
    const auto attribute = [](std::uint32_t location, Format format, std::size_t offset) {
        return vk::VertexInputAttributeDescription{.location = location, .binding = 0, .format = format, .offset = static_cast<std::uint32_t>(offset)};
    };
    gpu::GraphicsPipelineInfo info = targetPipeline(setup, vertex, &fragment, vk::PrimitiveTopology::eTriangleList);
    info.vertexBindings = {{.binding = 0, .stride = sizeof(motion::SkinVertex), .inputRate = vk::VertexInputRate::eVertex}};
    info.vertexAttributes = {attribute(0, Format::eR32G32B32Sfloat, offsetof(motion::SkinVertex, position)),
                             attribute(1, Format::eR32G32B32Sfloat, offsetof(motion::SkinVertex, normal)),
                             attribute(2, Format::eR32G32B32Sfloat, offsetof(motion::SkinVertex, girth)),
                             attribute(3, Format::eR32Uint, offsetof(motion::SkinVertex, mainBone)),
                             attribute(4, Format::eR16G16B16A16Uint, offsetof(motion::SkinVertex, joints)),
                             attribute(5, Format::eR8G8B8A8Unorm, offsetof(motion::SkinVertex, weights))};
    return gpu::createGraphicsPipeline(*setup.context, info);
}

// Whether the bodies asked for include skinned ones that every clip's skeleton can have. A
// skeleton with bones but no mesh (motion::skinnable: too many bones, or joints past the
// vertices' 16-bit indices) makes its crowd drawn with bones (auto: bones up close too), and
// the user is told why. A skeleton with no bone at all has nothing to skin or to draw as bones.
bool drawsSkin(Body body, std::span<const motion::BakedClip> clips) {
    if (body != Body::Skin && body != Body::Auto) return false;
    const auto unskinned = std::find_if(clips.begin(), clips.end(),
                                        [](const motion::BakedClip& clip) { return !clip.body.empty() && !motion::skinnable(clip); });
    if (unskinned == clips.end()) return true;
    const std::string why = unskinned->body.size() > motion::kMostSkinnedBones
                                ? std::to_string(unskinned->body.size()) + " body bones, more than the " + std::to_string(motion::kMostSkinnedBones) +
                                      " a skinned body is made from"
                                : std::to_string(unskinned->jointCount()) + " joints, more than a skinned body's vertices can name";
    log::warning("clip '" + unskinned->name + "' has " + why + ": the crowd is drawn with bones instead of skin");
    return false;
}

class BonePath final : public RenderPathImpl {
public:
    BonePath(const PathSetup& setup, Body body, float lodPixels, bool splat)
        : auto_(body == Body::Auto), skinned_(drawsSkin(body, setup.clips)), bonePixels_(auto_ ? kAutoBonePixels : 0.0F),
          skinPixels_(!skinned_ ? std::numeric_limits<float>::max() : body == Body::Skin ? 0.0F : kAutoSkinPixels), lodPixels_(lodPixels) {
        const gpu::Context& context = *setup.context;
        if (splat) splat_ = std::make_unique<Splat>(setup, true);
        if (skinned_) {
            skins_ = std::make_unique<SkinMeshes>(context, setup.clips, *setup.palette);
            skin_ = createSkinPipeline(setup, splat);
        }
        // The planning pass, its three writers and the allocation between them (resolve_bones.comp's kPass).
        const auto resolve = gpu::createShaderModule(context, kResolveBonesCompSpirv);
        const std::uint32_t mixes = clipsMayMix(setup.clips) ? 1U : 0U;
        for (std::uint32_t pass = 0; pass < resolve_.size(); ++pass) {
            const std::array<std::uint32_t, 3> constants{splatGroupLimit(), pass, mixes};
            resolve_[pass] = gpu::createComputePipeline(context, resolve, *setup.layout, constants);
        }
        const auto vertex = gpu::createShaderModule(context, kBoneVertSpirv);
        const auto fragment = gpu::createShaderModule(context, kBoneFragSpirv);
        if (!splat_) {
            gpu::GraphicsPipelineInfo bones = targetPipeline(setup, vertex, &fragment, vk::PrimitiveTopology::eTriangleStrip);
            bones.cullMode = vk::CullModeFlagBits::eNone;
            bones.alphaToCoverage = setup.samples != vk::SampleCountFlagBits::e1;
            bones_ = gpu::createGraphicsPipeline(context, bones);
        }
        const auto shadowVertex = gpu::createShaderModule(context, kContactShadowVertSpirv);
        const auto shadowFragment = gpu::createShaderModule(context, kContactShadowFragSpirv);
        gpu::GraphicsPipelineInfo shadows = targetPipeline(setup, shadowVertex, &shadowFragment, vk::PrimitiveTopology::eTriangleStrip);
        shadows.cullMode = vk::CullModeFlagBits::eNone;
        shadows.depthWrite = false;
        shadows.alphaBlend = true;
        shadows_ = gpu::createGraphicsPipeline(context, shadows);
        if (auto_ && !splat_) spheres_ = createJointSpritePipeline(setup);
    }
    [[nodiscard]] RenderPath path() const override { return splat_ ? RenderPath::Visibility : RenderPath::Fast; }
    [[nodiscard]] InstanceStorage storage() const override {
        return {.instances = auto_, .compacted = true, .bones = true, .skeletons = skins_ ? static_cast<std::uint32_t>(skins_->draws().size()) : 0U,
                .visibility = splat_ != nullptr, .shadesGround = splat_ != nullptr};
    }
    [[nodiscard]] const gpu::Buffer* bindPoses() const override { return skins_ ? &skins_->bindPoses() : nullptr; }
    void prepare(SlotBuffers& slot, std::span<const crowd::CharacterState> /*characters*/) override {
        slot.push.lodPixels = lodPixels_;
        slot.push.bonePixels = bonePixels_;
        slot.push.skinPixels = skinPixels_;
    }

    void recordCompute(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const override {
        // Reset the draws (no joints, a quad per bone and no bones yet) once the previous frame's
        // indirect reads are done, plan and write bones (and, with auto, joints and skinning),
        // then hand them to the draws, or to the splat and the shading that reads them.
        const vk::PipelineStageFlags2 countReader = splat_ ? Stage::eComputeShader | Stage::eDrawIndirect : vk::PipelineStageFlags2(Stage::eDrawIndirect);
        const vk::AccessFlags2 countRead = splat_ ? Access::eShaderStorageRead | Access::eIndirectCommandRead : vk::AccessFlags2(Access::eIndirectCommandRead);
        const vk::PipelineStageFlags2 bodyReaders = splat_ ? Stage::eComputeShader | Stage::eFragmentShader : vk::PipelineStageFlags2(Stage::eVertexShader);
        const auto previous = bufferBarrier(slot.drawArguments, countReader | Stage::eCopy, countRead | Access::eTransferRead, Stage::eCopy,
                                            Access::eTransferWrite);
        commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &previous});
        commands.updateBuffer<FastPathCounts>(slot.drawArguments.handle(), 0, FastPathCounts{});
        const auto reset = bufferBarrier(slot.drawArguments, Stage::eCopy, Access::eTransferWrite, Stage::eComputeShader,
                                         Access::eShaderStorageRead | Access::eShaderStorageWrite);
        commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &reset});
        if (skins_) resetSkinDraws(commands, slot);
        // The planning pass moves each character's cross-fades on from what the last frame's
        // (or the last batch's, sharing none of them) planning pass wrote and its writers read.
        const vk::MemoryBarrier2 fadesKept{.srcStageMask = Stage::eComputeShader,
                                           .srcAccessMask = Access::eShaderStorageRead | Access::eShaderStorageWrite,
                                           .dstStageMask = Stage::eComputeShader,
                                           .dstAccessMask = Access::eShaderStorageRead | Access::eShaderStorageWrite};
        commands.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &fadesKept});
        commands.bindPipeline(vk::PipelineBindPoint::eCompute, *resolve_[0]);
        commands.dispatch((slot.characterCount + kWorkgroupSize - 1) / kWorkgroupSize, 1, 1);
        // One workgroup turns the plan's counts into where each character's joints and bones go.
        recordSlotsBarrier(commands, slot);
        commands.bindPipeline(vk::PipelineBindPoint::eCompute, *resolve_[kAllocatePass]);
        commands.dispatch(1, 1, 1);
        // The writers take the lists the plan made, each dispatched with the workgroups its list needs.
        const std::array<vk::BufferMemoryBarrier2, 3> planned{
            bufferBarrier(slot.drawArguments, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eComputeShader | Stage::eDrawIndirect,
                          Access::eShaderStorageRead | Access::eShaderStorageWrite | Access::eIndirectCommandRead),
            bufferBarrier(slot.characterLists, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eComputeShader, Access::eShaderStorageRead),
            bufferBarrier(slot.bodyLevels, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eComputeShader, Access::eShaderStorageWrite)};
        // The writers read the fades the plan wrote (a barrier on all memory: LevelFades is the
        // renderer's, not the slot's).
        const vk::MemoryBarrier2 fadesPlanned{.srcStageMask = Stage::eComputeShader, .srcAccessMask = Access::eShaderStorageWrite,
                                              .dstStageMask = Stage::eComputeShader, .dstAccessMask = Access::eShaderStorageRead};
        commands.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &fadesPlanned, .bufferMemoryBarrierCount = 3,
                                                     .pBufferMemoryBarriers = planned.data()});
        for (std::uint32_t writer = 0; writer < kBodyWriters; ++writer) {
            if (writer > 0) {
                // The next writer's dispatch is read from the buffer whose counters this one counts in.
                const auto counting = bufferBarrier(slot.drawArguments, Stage::eComputeShader, Access::eShaderStorageWrite,
                                                    Stage::eComputeShader | Stage::eDrawIndirect,
                                                    Access::eShaderStorageRead | Access::eShaderStorageWrite | Access::eIndirectCommandRead);
                commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &counting});
            }
            commands.bindPipeline(vk::PipelineBindPoint::eCompute, *resolve_[writer + 1]);
            commands.dispatchIndirect(slot.drawArguments.handle(), offsetof(FastPathCounts, writerDispatch) + writer * sizeof(DispatchArguments));
        }
        // Bones, levels and (with auto) joints are also copied out for --dump-bodies.
        const std::array<vk::BufferMemoryBarrier2, 4> resolved{
            bufferBarrier(slot.drawArguments, Stage::eComputeShader, Access::eShaderStorageWrite, countReader | Stage::eCopy,
                          countRead | Access::eTransferRead),
            // (The visibility path's shading reads bones and joints through their texel views.)
            bufferBarrier(slot.boneInstances, Stage::eComputeShader, Access::eShaderStorageWrite, bodyReaders | Stage::eCopy,
                          Access::eShaderStorageRead | Access::eShaderSampledRead | Access::eTransferRead),
            // The contact shadows' splat reads which characters are skinned (shading_tiles.glsl's skin bounds).
            bufferBarrier(slot.bodyLevels, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eComputeShader | Stage::eCopy,
                          Access::eShaderStorageRead | Access::eTransferRead),
            bufferBarrier(slot.instances, Stage::eComputeShader, Access::eShaderStorageWrite, bodyReaders | Stage::eCopy,
                          Access::eShaderStorageRead | Access::eShaderSampledRead | Access::eTransferRead)};
        // The splatted form's shading reads the joints buffer whether or not auto wrote it.
        commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = auto_ || splat_ ? 4U : 3U, .pBufferMemoryBarriers = resolved.data()});
        if (skins_) {
            const std::array<vk::BufferMemoryBarrier2, 3> skinned{
                bufferBarrier(slot.skinDraws, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eDrawIndirect, Access::eIndirectCommandRead),
                // skin.vert reads the skinning transforms through their texel view.
                bufferBarrier(slot.skinJoints, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eVertexShader, Access::eShaderSampledRead),
                bufferBarrier(slot.skinCharacters, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eVertexShader, Access::eShaderStorageRead)};
            commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 3, .pBufferMemoryBarriers = skinned.data()});
        }
        commands.copyBuffer(slot.drawArguments.handle(), slot.counts.handle(), vk::BufferCopy{.size = sizeof(FastPathCounts)});
        const vk::MemoryBarrier2 toHost{.srcStageMask = Stage::eCopy, .srcAccessMask = Access::eTransferWrite,
                                        .dstStageMask = Stage::eHost, .dstAccessMask = Access::eHostRead};
        commands.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &toHost});
    }
    void recordVisibility(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const override {
        if (splat_) splat_->record(commands, slot, auto_, true);
    }
    void recordShading(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const override {
        // The ground, the bodies and the contact shadows first (no depth); skinned bodies,
        // drawn in recordDraw, test themselves against the splat and the ground plane.
        if (splat_) splat_->recordShading(commands, slot);
    }
    [[nodiscard]] std::optional<DetailCounts> detailCounts(const SlotBuffers& slot) const override {
        const FastPathCounts counts = readCounts(slot);
        // Bones are the full detail; joint spheres, of either kind, the coarse.
        const std::uint32_t spheres = counts.fullCharacters + counts.coarseCharacters;
        const std::uint32_t near = counts.boneCharacters + counts.skinCharacters;
        const std::uint32_t visible = std::min(near + spheres, slot.characterCount);
        return DetailCounts{.full = near, .coarse = spheres, .culled = slot.characterCount - visible, .skin = counts.skinCharacters,
                            .bones = counts.boneCharacters, .fading = counts.fadingCharacters};
    }
    void recordDraw(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const override {
        // Contact shadows over the ground and under the bodies (they write no depth); splatted,
        // the shading has laid them on the ground already.
        if (!splat_) {
            commands.bindPipeline(vk::PipelineBindPoint::eGraphics, *shadows_);
            commands.draw(kQuadVertices, slot.characterCount, 0, 0);
        }
        if (auto_ && !splat_) {
            commands.bindPipeline(vk::PipelineBindPoint::eGraphics, *spheres_);
            commands.drawIndirect(slot.drawArguments.handle(), offsetof(FastPathCounts, draw), 1, sizeof(DrawArguments));
        }
        if (!splat_) {
            commands.bindPipeline(vk::PipelineBindPoint::eGraphics, *bones_);
            commands.drawIndirect(slot.drawArguments.handle(), offsetof(FastPathCounts, boneDraw), 1, sizeof(DrawArguments));
        }
        if (skins_) {
            if (splat_) splat_->recordSkinDepthReset(commands);  // the splatted form clears no depth
            commands.bindPipeline(vk::PipelineBindPoint::eGraphics, *skin_);
            commands.bindVertexBuffers(0, skins_->vertices().handle(), vk::DeviceSize{0});
            commands.bindIndexBuffer(skins_->indices().handle(), 0, vk::IndexType::eUint32);
            for (std::size_t s = 0; s < skins_->draws().size(); ++s)
                commands.drawIndexedIndirect(slot.skinDraws.handle(), s * sizeof(SkinDrawGpu), 1, sizeof(SkinDrawGpu));
        }
    }

private:
    // Each skeleton's draw starts the frame with no instances; its characters are listed in its
    // own stretch of the list, a crowd's worth long.
    void resetSkinDraws(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const {
        const auto previous = bufferBarrier(slot.skinDraws, Stage::eDrawIndirect, Access::eIndirectCommandRead, Stage::eCopy, Access::eTransferWrite);
        commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &previous});
        std::vector<SkinDrawGpu> draws = skins_->draws();
        for (std::size_t s = 0; s < draws.size(); ++s) draws[s].firstInstance = static_cast<std::uint32_t>(s) * slot.capacity;
        commands.updateBuffer(slot.skinDraws.handle(), 0, vk::ArrayProxy<const SkinDrawGpu>(draws));
        const auto reset = bufferBarrier(slot.skinDraws, Stage::eCopy, Access::eTransferWrite, Stage::eComputeShader,
                                         Access::eShaderStorageRead | Access::eShaderStorageWrite);
        commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &reset});
    }

    bool auto_;
    bool skinned_;  // skinned bodies drawn (drawsSkin)
    float bonePixels_, skinPixels_, lodPixels_;
    std::unique_ptr<SkinMeshes> skins_;
    std::unique_ptr<Splat> splat_;  ///< The visibility path's form: bones and joints splatted, not drawn as quads and sprites.
    std::array<vk::raii::Pipeline, 2 + kBodyWriters> resolve_{nullptr, nullptr, nullptr, nullptr, nullptr};  ///< The plan, its writers, the allocation.
    vk::raii::Pipeline bones_{nullptr}, shadows_{nullptr}, spheres_{nullptr}, skin_{nullptr};
};

}  // namespace

std::unique_ptr<RenderPathImpl> makeBonePath(const PathSetup& setup, Body body, float lodPixels, bool splat) {
    return std::make_unique<BonePath>(setup, body, lodPixels, splat);
}

}  // namespace throng::render::detail
