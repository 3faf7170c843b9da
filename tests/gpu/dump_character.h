#pragma once
// A character's state as `throng render --dump-instances` / `--dump-bodies` record it: the
// floats the GPU read, so the casts here are exact.
#include <nlohmann/json.hpp>
#include <vector>

#include "throng/crowd/character_state.h"

inline throng::crowd::CharacterState characterFromDump(const nlohmann::json& character) {
    const auto ground = character.at("ground").get<std::vector<double>>();    // x, z, yaw
    const auto twist = character.at("foot_twist").get<std::vector<float>>();  // per leg
    const auto& blend = character.at("blend");                                // speed blending's second clip
    const auto& from = character.at("from");                                  // a transition's outgoing clip
    return {.groundFrame = glm::vec4(static_cast<float>(ground[0]), 0.0F, static_cast<float>(ground[1]), static_cast<float>(ground[2])),
            .clip = character.at("clip").get<std::uint32_t>(),
            .frame = character.at("frame").get<float>(),
            .scale = character.at("scale").get<float>(),
            .color = 0,
            .footTwist = glm::vec2(twist[0], twist[1]),
            .blendClip = blend.at("clip").get<std::uint32_t>(),
            .blendFrame = blend.at("frame").get<float>(),
            .blend = blend.at("weight").get<float>(),
            .fromClip = from.at("clip").get<std::uint32_t>(),
            .fromFrame = from.at("frame").get<float>(),
            .fromWeight = from.at("weight").get<float>()};
}
