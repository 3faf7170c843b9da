// Loop closing in joint space. Closing by moving each joint's global position on its own
// stretched bones by up to a third; correcting local rotations keeps the skeleton rigid.
#include <algorithm>

#include "bake_steps.h"

namespace throng::motion::bake_steps {
namespace {

struct LocalPose {
    glm::dquat rotation;
    glm::dvec3 translation;
};

LocalPose localOf(const PoseTable& poses, const std::vector<int>& parents, int f, int j) {
    const int parent = parents[static_cast<std::size_t>(j)];
    if (parent < 0) return {poses.rot(f, j), poses.pos(f, j)};
    const glm::dquat toParent = glm::conjugate(poses.rot(f, parent));
    return {toParent * poses.rot(f, j), toParent * (poses.pos(f, j) - poses.pos(f, parent))};
}

}  // namespace

double closeLoopInJointSpace(PoseTable& poses, const std::vector<int>& parents, const std::vector<char>& movingTranslation,
                             LoopRange loop) {
    const int joints = poses.joints;
    double mismatch = 0.0;
    for (int j = 0; j < joints; ++j)
        mismatch = std::max(mismatch, glm::length(poses.pos(loop.first, j) - poses.pos(loop.last, j)));
    // Per joint, the correction that takes the last frame's local pose onto the first's.
    std::vector<glm::dquat> turnBy(static_cast<std::size_t>(joints));
    std::vector<glm::dvec3> moveBy(static_cast<std::size_t>(joints), glm::dvec3(0.0));
    for (int j = 0; j < joints; ++j) {
        const LocalPose start = localOf(poses, parents, loop.first, j), end = localOf(poses, parents, loop.last, j);
        glm::dquat turn = glm::normalize(start.rotation * glm::conjugate(end.rotation));
        if (turn.w < 0) turn = -turn;  // the short way round
        turnBy[static_cast<std::size_t>(j)] = turn;
        if (parents[static_cast<std::size_t>(j)] < 0 || movingTranslation[static_cast<std::size_t>(j)] != 0)
            moveBy[static_cast<std::size_t>(j)] = start.translation - end.translation;
    }
    std::vector<LocalPose> locals(static_cast<std::size_t>(joints));
    const glm::dquat identity(1.0, 0.0, 0.0, 0.0);
    for (int f = loop.first + 1; f <= loop.last; ++f) {
        const double share = static_cast<double>(f - loop.first) / loop.length();
        for (int j = 0; j < joints; ++j) {
            LocalPose local = localOf(poses, parents, f, j);
            local.rotation = glm::normalize(glm::slerp(identity, turnBy[static_cast<std::size_t>(j)], share) * local.rotation);
            local.translation += share * moveBy[static_cast<std::size_t>(j)];
            locals[static_cast<std::size_t>(j)] = local;
        }
        // Forward kinematics again: parents precede children.
        for (int j = 0; j < joints; ++j) {
            const int parent = parents[static_cast<std::size_t>(j)];
            const LocalPose& local = locals[static_cast<std::size_t>(j)];
            if (parent < 0) {
                poses.rot(f, j) = local.rotation;
                poses.pos(f, j) = local.translation;
                continue;
            }
            poses.rot(f, j) = glm::normalize(poses.rot(f, parent) * local.rotation);
            poses.pos(f, j) = poses.pos(f, parent) + poses.rot(f, parent) * local.translation;
        }
    }
    return mismatch;
}

}  // namespace throng::motion::bake_steps
