#include "throng/render/crowd_renderer.h"

#include <algorithm>

#include "bindings.h"
#include "level_fades.h"
#include "paths/render_path_impl.h"
#include "throng/render/camera.h"
#include "throng/shaders/ground_frag.h"
#include "throng/shaders/ground_vert.h"

namespace throng::render {
namespace {

using detail::SlotBuffers;

constexpr vk::ShaderStageFlags kAllStages =
    vk::ShaderStageFlagBits::eCompute | vk::ShaderStageFlagBits::eVertex | vk::ShaderStageFlagBits::eFragment;
constexpr vk::DeviceSize kPlaceholderBytes = 16;  // a buffer the path never reads still needs a valid descriptor

// `buffer` as texels of `format`, for a shader's texelFetch (lavapipe fetches texels as one
// gather, where it loads a storage buffer's values lane by lane, each behind a branch): all of
// it, up to the most texels a view may hold (the visibility path's crowds and frames are kept
// within that; a larger buffer is one another path uses).
vk::raii::BufferView texelView(const gpu::Context& context, const gpu::Buffer& buffer, vk::Format format) {
    const vk::DeviceSize texel = vk::blockSize(format), most = vk::DeviceSize{context.limits().maxTexelBufferElements} * texel;
    return {context.device(), vk::BufferViewCreateInfo{.buffer = buffer.handle(), .format = format, .offset = 0, .range = std::min(buffer.size() / texel * texel, most)}};
}

std::unique_ptr<detail::RenderPathImpl> makePath(RenderPath path, Body body, const detail::PathSetup& setup, float lodPixels) {
    if (body != Body::Spheres) {
        if (path != RenderPath::Fast && path != RenderPath::Visibility)
            throw ThrongException(Error{Error::Kind::BadInput, "bone bodies are drawn by the fast and visibility paths only (not " + std::string(renderPathName(path)) + ")", {}});
        return detail::makeBonePath(setup, body, lodPixels, path == RenderPath::Visibility);
    }
    switch (path) {
        case RenderPath::Paper: return detail::makePaperPath(setup);
        case RenderPath::Cpu: return detail::makeCpuPath(setup);
        case RenderPath::Compute: return detail::makeComputePath(setup);
        case RenderPath::Fast: return detail::makeFastPath(setup, lodPixels);
        case RenderPath::Visibility: return detail::makeVisibilityPath(setup, lodPixels);
    }
    throw ThrongException(Error{Error::Kind::BadInput, "unknown render path", {}});
}

// Bone places a character's buffers hold: a skeleton of one joint has no bone, but its buffers
// still hold one (and sizes divided by the count stay defined).
std::uint64_t boneSlots(const Palette& palette) { return std::max(palette.bonesPerCharacter(), 1U); }

// The GPU memory one character costs: every per-character buffer grow() sizes for a path that
// stores `storage`, with `joints` joints and `bones` bones a character (the lists' and slots'
// share of a workgroup of characters, rounded up).
std::uint64_t perCharacterBytes(const detail::InstanceStorage& storage, std::uint64_t joints, std::uint64_t bones) {
    const std::uint64_t lists =
        storage.compacted ? (detail::characterListsBytes(detail::kPlanWorkgroup) + detail::kPlanWorkgroup - 1) / detail::kPlanWorkgroup : 0;
    return sizeof(crowd::CharacterState) + (storage.instances ? joints * sizeof(InstanceGpu) : 0) + (storage.owners ? joints * sizeof(glm::uvec2) : 0) +
           (storage.bones ? bones * sizeof(BoneInstanceGpu) + sizeof(BodyLevelGpu) + sizeof(std::uint32_t) : 0) +  // and its LevelFades word
           (storage.skeletons > 0 ? joints * sizeof(motion::JointPose) + storage.skeletons * sizeof(glm::uvec2) : 0) + lists;
}

}  // namespace

std::uint64_t CharacterFootprint::bytes() const {
    return (bones ? sizeof(BoneInstanceGpu) : sizeof(InstanceGpu)) * std::max<std::uint64_t>(count, 1);
}

std::uint64_t CrowdRenderer::maxCharactersFor(const gpu::Context& context, std::uint32_t jointsPerCharacter) {
    return maxCharactersFor(context, CharacterFootprint{.count = jointsPerCharacter, .bones = false});
}

CharacterFootprint CrowdRenderer::footprintOf(std::span<const motion::BakedClip> clips, Body body) {
    // Bone instances are the larger of auto's two per-character stores (64-byte bones, one more
    // than the joints with each End Site, against 48-byte joints).
    CharacterFootprint footprint{.count = 0, .bones = body != Body::Spheres};
    for (const motion::BakedClip& clip : clips)
        footprint.count = std::max(footprint.count, static_cast<std::uint32_t>(footprint.bones ? clip.body.size() : static_cast<std::size_t>(clip.jointCount())));
    return footprint;
}

std::uint64_t CrowdRenderer::bytesPerCharacter(std::span<const motion::BakedClip> clips, Body body) {
    std::uint64_t joints = 1, bones = 1;
    for (const motion::BakedClip& clip : clips) {
        joints = std::max<std::uint64_t>(joints, static_cast<std::uint64_t>(clip.jointCount()));
        bones = std::max<std::uint64_t>(bones, clip.body.size());
    }
    // The most any path stores for this body: compacted joints with owners, and for bodies the
    // bones and the skinning of every clip's skeleton.
    const bool bodies = body != Body::Spheres;
    const detail::InstanceStorage storage{.instances = true, .owners = true, .compacted = true, .bones = bodies,
                                          .skeletons = bodies ? static_cast<std::uint32_t>(std::max<std::size_t>(clips.size(), 1)) : 0U};
    return perCharacterBytes(storage, joints, bones);
}

std::uint64_t CrowdRenderer::maxCharactersFor(const gpu::Context& context, const CharacterFootprint& footprint) {
    return context.limits().maxStorageBufferRange / footprint.bytes();
}

CrowdRenderer::CrowdRenderer(const gpu::Context& context, const Palette& palette, std::span<const motion::BakedClip> clips,
                             const CrowdRendererCreateInfo& info)
    : context_(&context), palette_(&palette), cullRadius_(0.8F * palette.maxHeight()), cullHeight_(0.5F * palette.maxHeight()),
      jointsPerCharacter_(palette.jointsPerCharacter()) {
    // One layout for every path keeps the descriptor plumbing single: every stage sees every
    // binding, and a path simply leaves unused what it doesn't need.
    std::vector<gpu::DescriptorBinding> bindings;
    for (const Binding binding : kAllBindings)
        bindings.push_back({bindingIndex(binding), descriptorType(binding), kAllStages});
    setLayout_ = gpu::createDescriptorSetLayout(context, bindings);
    const vk::PushConstantRange push{.stageFlags = kAllStages, .offset = 0, .size = sizeof(PushConstants)};
    pipelineLayout_ = vk::raii::PipelineLayout(context.device(), vk::PipelineLayoutCreateInfo{.setLayoutCount = 1,
                                                                                              .pSetLayouts = &*setLayout_,
                                                                                              .pushConstantRangeCount = 1,
                                                                                              .pPushConstantRanges = &push});
    const detail::PathSetup setup{.context = &context, .palette = &palette, .clips = clips, .layout = &pipelineLayout_,
                                  .colorFormat = info.colorFormat, .depthFormat = info.depthFormat, .samples = info.samples,
                                  .jointsPerCharacter = jointsPerCharacter_};
    const auto groundVert = gpu::createShaderModule(context, kGroundVertSpirv);
    const auto groundFrag = gpu::createShaderModule(context, kGroundFragSpirv);
    gpu::GraphicsPipelineInfo ground = detail::targetPipeline(setup, groundVert, &groundFrag, vk::PrimitiveTopology::eTriangleList);
    ground.cullMode = vk::CullModeFlagBits::eNone;
    groundPipeline_ = gpu::createGraphicsPipeline(context, ground);
    path_ = makePath(info.path, info.body, setup, info.lodPixels);

    // Each of a batch's buffers must fit the device's storage buffer range: the per-character
    // state, the bones' (bodies), the joints' (and with auto both), and the skinning joints'.
    const detail::InstanceStorage needs = path_->storage();
    const CharacterFootprint footprint{.count = needs.bones ? palette_->bonesPerCharacter() : jointsPerCharacter_, .bones = needs.bones};
    const std::uint64_t range = context.limits().maxStorageBufferRange;
    std::uint64_t limit = std::min(maxCharactersFor(context, footprint), range / sizeof(crowd::CharacterState));
    if (needs.instances) limit = std::min(limit, maxCharactersFor(context, jointsPerCharacter_));
    if (needs.visibility) {  // its shading reads joints and bones through texel views: three texels a joint, four a bone
        limit = std::min<std::uint64_t>(limit, context.limits().maxTexelBufferElements / (3 * std::uint64_t{jointsPerCharacter_}));
        if (needs.bones) limit = std::min<std::uint64_t>(limit, context.limits().maxTexelBufferElements / (4 * boneSlots(palette)));
    }
    if (needs.skeletons > 0) {
        limit = std::min<std::uint64_t>(limit, range / (std::uint64_t{jointsPerCharacter_} * sizeof(motion::JointPose)));
        // skin.vert reads them through a texel view, two texels a joint.
        limit = std::min<std::uint64_t>(limit, context.limits().maxTexelBufferElements / (2 * std::uint64_t{jointsPerCharacter_}));
        limit = std::min<std::uint64_t>(limit, range / (std::uint64_t{needs.skeletons} * sizeof(glm::uvec2)));
    }
    batchCharacters_ = static_cast<std::uint32_t>(std::clamp<std::uint64_t>(limit, 1, UINT32_MAX));
    levelFades_ = std::make_unique<detail::LevelFades>(context, needs.bones, batchCharacters_);

    const std::uint32_t slots = std::max(info.slots, 1U);
    slots_.resize(slots);
    activeBatches_.assign(slots, 1);
    for (auto& batches : slots_) batches.push_back(makeBatch(0));
}

CrowdRenderer::~CrowdRenderer() = default;

// A batch with its own descriptor set, sized for one character until a crowd arrives.
std::unique_ptr<SlotBuffers> CrowdRenderer::makeBatch(std::uint32_t index) {
    auto batch = std::make_unique<SlotBuffers>();
    batch->batch = index;
    std::array<vk::DescriptorPoolSize, 3> sizes{vk::DescriptorPoolSize{vk::DescriptorType::eStorageBuffer, 0},
                                                vk::DescriptorPoolSize{vk::DescriptorType::eUniformBuffer, 0},
                                                vk::DescriptorPoolSize{vk::DescriptorType::eUniformTexelBuffer, 0}};
    for (const Binding binding : kAllBindings)
        for (vk::DescriptorPoolSize& size : sizes) size.descriptorCount += size.type == descriptorType(binding) ? 1 : 0;
    batch->descriptorPool = vk::raii::DescriptorPool(context_->device(), vk::DescriptorPoolCreateInfo{
                                                                             .flags = vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet,
                                                                             .maxSets = 1, .poolSizeCount = static_cast<std::uint32_t>(sizes.size()), .pPoolSizes = sizes.data()});
    vk::raii::DescriptorSets sets(context_->device(), vk::DescriptorSetAllocateInfo{.descriptorPool = *batch->descriptorPool,
                                                                                    .descriptorSetCount = 1, .pSetLayouts = &*setLayout_});
    batch->descriptors = std::move(sets.front());
    batch->scene = gpu::Buffer(*context_, {.size = sizeof(SceneUniforms), .usage = vk::BufferUsageFlagBits::eUniformBuffer,
                                           .intent = gpu::MemoryIntent::HostUpload});
    batch->counts = gpu::Buffer(*context_, {.size = sizeof(FastPathCounts), .usage = vk::BufferUsageFlagBits::eTransferDst,
                                            .intent = gpu::MemoryIntent::Readback});
    const FastPathCounts none{};  // what a batch reports before its first frame
    batch->counts.write(std::as_bytes(std::span(&none, 1)));
    grow(*batch, 1);
    return batch;
}

// Sizes the batch's per-character buffers for at least `characters` (doubling, so a growing
// crowd reallocates rarely, up to what one batch may hold) and points its descriptors at them.
void CrowdRenderer::grow(SlotBuffers& slot, std::uint32_t characters) const {
    const detail::InstanceStorage storage = path_->storage();
    const std::uint64_t bonesPerCharacter = boneSlots(*palette_);
    const std::uint64_t capacity =
        std::min<std::uint64_t>(std::max<std::uint64_t>(characters, 2ULL * slot.capacity), batchCharacters_);
    const std::uint64_t instances = capacity * jointsPerCharacter_;
    using Usage = vk::BufferUsageFlagBits;
    slot.characters = gpu::Buffer(*context_, {.size = capacity * sizeof(crowd::CharacterState), .usage = Usage::eStorageBuffer,
                                              .intent = gpu::MemoryIntent::HostUpload});
    slot.instances = gpu::Buffer(*context_, {.size = storage.instances ? instances * sizeof(InstanceGpu) : kPlaceholderBytes,
                                             .usage = Usage::eStorageBuffer | Usage::eUniformTexelBuffer | Usage::eTransferSrc, .intent = storage.intent});
    slot.instanceTexels = texelView(*context_, slot.instances, vk::Format::eR32G32B32A32Sfloat);
    slot.drawArguments = gpu::Buffer(*context_, {.size = sizeof(FastPathCounts),
                                                 .usage = Usage::eStorageBuffer | Usage::eIndirectBuffer | Usage::eTransferSrc});
    slot.instanceOwners = gpu::Buffer(*context_, {.size = storage.owners ? instances * sizeof(glm::uvec2) : kPlaceholderBytes,
                                                  .usage = Usage::eStorageBuffer | Usage::eTransferSrc});
    slot.boneInstances = gpu::Buffer(*context_, {.size = storage.bones ? capacity * bonesPerCharacter * sizeof(BoneInstanceGpu) : kPlaceholderBytes,
                                                 .usage = Usage::eStorageBuffer | Usage::eUniformTexelBuffer | Usage::eTransferSrc});
    slot.boneInstanceTexels = texelView(*context_, slot.boneInstances, vk::Format::eR32G32B32A32Sfloat);
    const std::uint64_t skeletons = std::max(storage.skeletons, 1U);
    const bool skins = storage.skeletons > 0;
    slot.skinJoints = gpu::Buffer(*context_, {.size = skins ? capacity * jointsPerCharacter_ * sizeof(motion::JointPose) : kPlaceholderBytes,
                                              .usage = Usage::eStorageBuffer | Usage::eUniformTexelBuffer});
    slot.skinJointTexels = texelView(*context_, slot.skinJoints, vk::Format::eR32G32B32A32Sfloat);
    slot.skinCharacters = gpu::Buffer(*context_, {.size = skins ? capacity * skeletons * sizeof(glm::uvec2) : kPlaceholderBytes,
                                                  .usage = Usage::eStorageBuffer});
    slot.skinDraws = gpu::Buffer(*context_, {.size = skeletons * sizeof(SkinDrawGpu),
                                             .usage = Usage::eStorageBuffer | Usage::eIndirectBuffer | Usage::eTransferDst});
    slot.bodyLevels = gpu::Buffer(*context_, {.size = storage.bones ? capacity * sizeof(BodyLevelGpu) : kPlaceholderBytes,
                                              .usage = Usage::eStorageBuffer | Usage::eTransferSrc});
    slot.characterLists = gpu::Buffer(*context_, {.size = storage.compacted ? detail::characterListsBytes(capacity) : kPlaceholderBytes,
                                                  .usage = Usage::eStorageBuffer | Usage::eIndirectBuffer | Usage::eTransferDst});
    slot.capacity = static_cast<std::uint32_t>(capacity);
    bindDescriptors(slot);
}

void CrowdRenderer::sizeVisibility(SlotBuffers& slot, vk::Extent2D extent) const {
    if (!path_->storage().visibility || (extent.width == slot.visibilityExtent.width && extent.height == slot.visibilityExtent.height))
        return;
    if (!visibilityFrameFits(*context_, extent))
        throw ThrongException(Error{Error::Kind::BadInput,
                                    "a " + std::to_string(extent.width) + "x" + std::to_string(extent.height) + " frame" + visibilityPaddingNote(extent) + " is more than the visibility path's " +
                                        std::to_string(visibilityPixelLimit(*context_)) + " pixels on device '" +
                                        context_->description().name + "' (one storage buffer and one texel view hold each pixel's nearest body); use --path fast or a smaller frame",
                                    {}});
    const vk::DeviceSize pixels = visibilityBufferPixels(extent), shadowBytes = path_->storage().bones ? shadowBufferTexels(extent) * sizeof(std::uint32_t) : 0;
    slot.visibility = gpu::Buffer(*context_, {.size = std::max<vk::DeviceSize>(pixels * sizeof(std::uint64_t), kPlaceholderBytes),
                                              .usage = vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eUniformTexelBuffer |
                                                       vk::BufferUsageFlagBits::eTransferDst});
    slot.shadows = gpu::Buffer(*context_, {.size = std::max(shadowBytes, kPlaceholderBytes),
                                           .usage = vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eUniformTexelBuffer |
                                                    vk::BufferUsageFlagBits::eTransferDst});
    slot.visibilityTexels = texelView(*context_, slot.visibility, vk::Format::eR32G32Uint);
    slot.shadowTexels = texelView(*context_, slot.shadows, vk::Format::eR32Uint);
    slot.shadingTiles = gpu::Buffer(*context_, {.size = detail::shadingTileBytes(extent),
                                                .usage = vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eIndirectBuffer |
                                                         vk::BufferUsageFlagBits::eTransferDst | vk::BufferUsageFlagBits::eTransferSrc});
    detail::visibilityBuffersMade(slot, extent);
    bindDescriptors(slot);
}

void CrowdRenderer::bindDescriptors(SlotBuffers& slot) const {
    const auto placeholderUsage = vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eUniformTexelBuffer;
    if (!slot.visibility.handle()) {
        slot.visibility = gpu::Buffer(*context_, {.size = kPlaceholderBytes, .usage = placeholderUsage});
        slot.visibilityTexels = texelView(*context_, slot.visibility, vk::Format::eR32G32Uint);
    }
    if (!slot.shadows.handle()) {
        slot.shadows = gpu::Buffer(*context_, {.size = kPlaceholderBytes, .usage = placeholderUsage});
        slot.shadowTexels = texelView(*context_, slot.shadows, vk::Format::eR32Uint);
    }
    if (!slot.shadingTiles.handle())
        slot.shadingTiles = gpu::Buffer(*context_, {.size = detail::shadingTileBytes({1, 1}), .usage = vk::BufferUsageFlagBits::eStorageBuffer});
    const gpu::Buffer* bindPoses = path_->bindPoses();
    const auto buffer = [](Binding b, vk::Buffer handle) { return gpu::BufferBinding{bindingIndex(b), descriptorType(b), handle}; };
    const auto texels = [](Binding b, const vk::raii::BufferView& view) { return gpu::BufferBinding{bindingIndex(b), descriptorType(b), {}, VK_WHOLE_SIZE, *view}; };
    const gpu::BufferBinding writes[] = {
        buffer(Binding::Poses, palette_->poses().handle()),
        buffer(Binding::Clips, palette_->clips().handle()),
        buffer(Binding::JointRadii, palette_->jointRadii().handle()),
        buffer(Binding::Characters, slot.characters.handle()),
        buffer(Binding::Instances, slot.instances.handle()),
        buffer(Binding::SceneUniforms, slot.scene.handle()),
        buffer(Binding::DrawArguments, slot.drawArguments.handle()),
        buffer(Binding::InstanceOwners, slot.instanceOwners.handle()),
        buffer(Binding::JointDetail, palette_->jointInfo().handle()),
        buffer(Binding::Bones, palette_->bones().handle()),
        buffer(Binding::BoneInstances, slot.boneInstances.handle()),
        buffer(Binding::BindPoses, bindPoses != nullptr ? bindPoses->handle() : slot.skinDraws.handle()),
        buffer(Binding::SkinJoints, slot.skinJoints.handle()),
        buffer(Binding::SkinCharacters, slot.skinCharacters.handle()),
        buffer(Binding::SkinDraws, slot.skinDraws.handle()),
        buffer(Binding::BodyLevels, slot.bodyLevels.handle()),
        buffer(Binding::Visibility, slot.visibility.handle()),
        buffer(Binding::CharacterLists, slot.characterLists.handle()),
        buffer(Binding::Shadows, slot.shadows.handle()),
        buffer(Binding::ShadingTiles, slot.shadingTiles.handle()),
        texels(Binding::VisibilityTexels, slot.visibilityTexels),
        texels(Binding::ShadowTexels, slot.shadowTexels),
        texels(Binding::SkinJointTexels, slot.skinJointTexels),
        buffer(Binding::LevelFades, levelFades_->buffer(slot.batch).handle()),
        texels(Binding::InstanceTexels, slot.instanceTexels),
        texels(Binding::BoneInstanceTexels, slot.boneInstanceTexels)};
    gpu::writeDescriptorSet(*context_, *slot.descriptors, writes);
}

void CrowdRenderer::update(std::uint32_t slot, const CharacterSource& characters, const SceneUniforms& scene, bool targetHoldsLastFrame) {
    auto& batches = slots_.at(slot);
    // Consecutive characters per batch, each a crowd of its own to the path: its shaders index only their batch's buffers.
    const std::size_t needed = std::max<std::size_t>((characters.count + batchCharacters_ - 1) / batchCharacters_, 1);
    // One visibility buffer keeps one batch's joint indices: a split crowd would need each pixel to name its batch too.
    if (needed > 1 && path_->storage().visibility)
        throw ThrongException(Error{Error::Kind::BadInput, "the visibility path draws at most " + std::to_string(batchCharacters_) +
                                                               " characters on this device (one storage buffer of joints), not " +
                                                               std::to_string(characters.count) + "; use --path fast", {}});
    while (batches.size() < needed) batches.push_back(makeBatch(static_cast<std::uint32_t>(batches.size())));
    activeBatches_.at(slot) = static_cast<std::uint32_t>(needed);
    levelFades_->idleFrom(static_cast<std::uint32_t>(needed));
    const std::array<glm::vec4, 6> planes = frustumPlanes(scene.viewProjection);
    for (std::size_t b = 0; b < needed; ++b) {
        SlotBuffers& buffers = *batches[b];
        const std::size_t first = std::min(b * batchCharacters_, characters.count);
        const std::size_t count = std::min<std::size_t>(batchCharacters_, characters.count - first);
        if (count > buffers.capacity) grow(buffers, static_cast<std::uint32_t>(count));
        sizeVisibility(buffers, {static_cast<std::uint32_t>(scene.viewport.x), static_cast<std::uint32_t>(scene.viewport.y)});
        const std::span<crowd::CharacterState> part(reinterpret_cast<crowd::CharacterState*>(buffers.characters.mapped()), count);  // mapped: aligned
        if (count > 0) characters.write(first, part);
        // The cross-fades move on from the previous frame only where it drew the same crowd.
        const detail::LevelFades::Frame fades = levelFades_->prepare(static_cast<std::uint32_t>(b), part.size(), scene.levelFadesContinue > 0.0F);
        for (auto& slotBatches : slots_)  // a buffer made again is named again by every slot's batch b
            if (fades.resized && slotBatches.size() > b) bindDescriptors(*slotBatches[b]);
        SceneUniforms batchScene = scene;
        batchScene.levelFadesContinue = fades.continues ? 1.0F : 0.0F;
        batchScene.visibilityEpoch = detail::beginVisibilityFrame(buffers, scene, targetHoldsLastFrame && needed == 1 && splats());
        buffers.scene.write(std::as_bytes(std::span(&batchScene, 1)));
        buffers.characterCount = static_cast<std::uint32_t>(part.size());
        buffers.push = {buffers.characterCount, jointsPerCharacter_, cullRadius_, cullHeight_, {}, 0.0F, {}, {},
                        static_cast<std::uint32_t>(b * batchCharacters_)};
        std::copy(planes.begin(), planes.end(), buffers.push.frustum);
        path_->prepare(buffers, part);
    }
}

void CrowdRenderer::forEachBatch(const vk::raii::CommandBuffer& commands, std::uint32_t slot, vk::PipelineBindPoint bindPoint,
                                 const std::function<void(std::uint32_t, const SlotBuffers&)>& record) const {
    for (std::uint32_t b = 0; b < activeBatches_.at(slot); ++b) {
        const SlotBuffers& buffers = *slots_.at(slot)[b];
        commands.bindDescriptorSets(bindPoint, *pipelineLayout_, 0, *buffers.descriptors, {});
        commands.pushConstants<PushConstants>(*pipelineLayout_, kAllStages, 0, buffers.push);
        record(b, buffers);
    }
}

void CrowdRenderer::recordCompute(const vk::raii::CommandBuffer& commands, std::uint32_t slot, const PassBoundary& boundary) const {
    const auto compute = vk::PipelineBindPoint::eCompute;
    forEachBatch(commands, slot, compute, [&](std::uint32_t, const SlotBuffers& buffers) { path_->recordCompute(commands, buffers); });
    if (!splats()) return;
    if (boundary) boundary(commands, FramePass::Visibility);
    forEachBatch(commands, slot, compute, [&](std::uint32_t, const SlotBuffers& buffers) { path_->recordVisibility(commands, buffers); });
}

void CrowdRenderer::recordDraw(const vk::raii::CommandBuffer& commands, std::uint32_t slot, vk::Extent2D extent, const PassBoundary& boundary) const {
    commands.setViewport(0, vk::Viewport{0.0F, 0.0F, static_cast<float>(extent.width), static_cast<float>(extent.height), 0.0F, 1.0F});
    commands.setScissor(0, vk::Rect2D{{0, 0}, extent});
    const auto graphics = vk::PipelineBindPoint::eGraphics;
    if (splats()) {
        forEachBatch(commands, slot, graphics, [&](std::uint32_t, const SlotBuffers& buffers) { path_->recordShading(commands, buffers); });
        if (boundary) boundary(commands, FramePass::Raster);
    }
    forEachBatch(commands, slot, graphics, [&](std::uint32_t batch, const SlotBuffers& buffers) {
        if (batch == 0 && !path_->storage().shadesGround) {
            commands.bindPipeline(vk::PipelineBindPoint::eGraphics, *groundPipeline_);
            commands.draw(6, 1, 0, 0);
        }
        path_->recordDraw(commands, buffers);
    });
}

bool CrowdRenderer::splats() const { return path_->storage().visibility; }
RenderPath CrowdRenderer::path() const { return path_->path(); }

InstanceLayout CrowdRenderer::instanceLayout() const {
    const detail::InstanceStorage storage = path_->storage();
    return {.exists = storage.instances,
            .compacted = storage.compacted,
            .gpuBytesPerCharacter = perCharacterBytes(storage, jointsPerCharacter_, boneSlots(*palette_))};
}

const SlotBuffers& CrowdRenderer::firstBatch(std::uint32_t slot) const { return *slots_.at(slot).front(); }
std::uint32_t CrowdRenderer::batchCount(std::uint32_t slot) const { return activeBatches_.at(slot); }
const gpu::Buffer& CrowdRenderer::instances(std::uint32_t slot) const { return firstBatch(slot).instances; }
const gpu::Buffer& CrowdRenderer::drawArguments(std::uint32_t slot) const { return firstBatch(slot).drawArguments; }
const gpu::Buffer& CrowdRenderer::instanceOwners(std::uint32_t slot) const { return firstBatch(slot).instanceOwners; }
const gpu::Buffer& CrowdRenderer::bodyLevels(std::uint32_t slot) const { return firstBatch(slot).bodyLevels; }
const gpu::Buffer& CrowdRenderer::boneInstances(std::uint32_t slot) const { return firstBatch(slot).boneInstances; }
std::uint32_t CrowdRenderer::characterCount(std::uint32_t slot) const { return firstBatch(slot).characterCount; }
bool CrowdRenderer::drawsOverLastFrame(std::uint32_t slot) const { return firstBatch(slot).drawsOverLastFrame; }
std::optional<std::uint32_t> CrowdRenderer::keptGroundSquares(std::uint32_t slot) const { return splats() ? std::optional(detail::keptGroundSquares(*context_, firstBatch(slot))) : std::nullopt; }

std::optional<DetailCounts> CrowdRenderer::detailCounts(std::uint32_t slot) const {
    std::optional<DetailCounts> sum;
    for (std::uint32_t b = 0; b < activeBatches_.at(slot); ++b) {
        const std::optional<DetailCounts> part = path_->detailCounts(*slots_.at(slot)[b]);
        if (!part) return std::nullopt;
        if (!sum) {
            sum = part;
            continue;
        }
        sum->full += part->full;
        sum->coarse += part->coarse;
        sum->culled += part->culled;
        if (sum->skin && part->skin) *sum->skin += *part->skin;
        if (sum->bones && part->bones) *sum->bones += *part->bones;
        if (sum->fading && part->fading) *sum->fading += *part->fading;
    }
    return sum;
}

}  // namespace throng::render

