#include "render_dumps.h"

#include <array>
#include <string>

#include "throng/core/error.h"

namespace throng::app {

Json clipListJson(std::span<const motion::BakedClip> clips) {
    Json list = Json::array();
    for (const motion::BakedClip& clip : clips) list.push_back({{"source", clip.name}, {"joints", clip.jointNames}, {"height", clip.stature}});
    return list;
}

Json characterJson(std::size_t index, const crowd::CharacterState& c) {
    return {{"index", index},
            {"clip", c.clip},
            {"frame", c.frame},
            {"ground", {c.groundFrame.x, c.groundFrame.z, c.groundFrame.w}},
            {"scale", c.scale},
            {"foot_twist", {c.footTwist.x, c.footTwist.y}},
            {"blend", {{"clip", c.blendClip}, {"frame", c.blendFrame}, {"weight", c.blend}}},
            {"from", {{"clip", c.fromClip}, {"frame", c.fromFrame}, {"weight", c.fromWeight}}}};
}

Json bodyDump(std::span<const motion::BakedClip> clips, std::span<const crowd::CharacterState> packed, const render::OffscreenRenderer& offscreen) {
    constexpr std::array<const char*, 4> kLevels{"culled", "spheres", "bones", "skin"};
    const std::vector<render::BodyLevelGpu> levels = offscreen.bodyLevels();
    const std::vector<render::BoneInstanceGpu> bones = offscreen.boneInstances();
    const auto invalid = [] { return ThrongException(Error{Error::Kind::Runtime, "the GPU returned an invalid body record; nothing written", {}}); };
    if (levels.size() != packed.size()) throw invalid();
    Json characters = Json::array();
    for (std::size_t m = 0; m < packed.size(); ++m) {
        const render::BodyLevelGpu& level = levels[m];
        const motion::BakedClip& clip = clips[packed[m].clip];
        // Data read back from the GPU is checked like any input before it indexes anything.
        if (level.level >= kLevels.size() || (level.boneCount > 0 && (level.boneCount != clip.body.size() || level.firstBone > bones.size() ||
                                                                      bones.size() - level.firstBone < level.boneCount)))
            throw invalid();
        Json record = characterJson(m, packed[m]);
        record["level"] = kLevels[level.level];
        record["pixels_tall"] = level.pixelsTall;
        Json drawn = Json::array();
        for (std::uint32_t b = 0; b < level.boneCount; ++b) {
            const render::BoneInstanceGpu& bone = bones[level.firstBone + b];
            const motion::BodyBone& source = clip.body[b];
            drawn.push_back({{"joint", source.joint}, {"child", source.child}, {"start", {bone.start.x, bone.start.y, bone.start.z}},
                             {"end", {bone.end.x, bone.end.y, bone.end.z}}, {"radii", {bone.start.w, bone.end.w}}});
        }
        if (level.boneCount > 0) record["first_bone"] = level.firstBone;  // where its bones are among those written
        record["bones"] = drawn;
        characters.push_back(record);
    }
    Json json;
    json["clips"] = clipListJson(clips);
    json["characters"] = characters;
    return json;
}

}  // namespace throng::app
