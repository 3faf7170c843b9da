#include "throng/motion/forward_kinematics.h"
#include "throng/core/error.h"

namespace throng::motion {

glm::dmat4 localTransform(const RawJoint& joint, std::span<const double> row, PositionChannels mode) {
    glm::dvec3 translation = joint.offset;
    glm::dmat4 rotation(1.0);
    for (std::size_t i = 0; i < joint.channels.size(); ++i) {
        const Channel channel = joint.channels[i];
        const double value = row[static_cast<std::size_t>(joint.firstValue) + i];
        const int axis = channelAxis(channel);
        if (isRotation(channel)) {
            glm::dvec3 axisVector(0.0);
            axisVector[axis] = 1.0;
            // Right-multiplying applies the later-listed rotation first to a column vector,
            // which is the BVH convention for the listed order.
            rotation = rotation * glm::rotate(glm::dmat4(1.0), glm::radians(value), axisVector);
        } else if (mode == PositionChannels::Replace) {
            translation[axis] = value;  // the parser guarantees one channel per axis
        } else {
            translation[axis] += value;
        }
    }
    glm::dmat4 local = rotation;
    local[3] = glm::dvec4(translation, 1.0);
    return local;
}

bool LocalToGlobalJob::validate() const {
    if (locals.size() != parents.size() || globals.size() != parents.size()) return false;
    for (std::size_t i = 0; i < parents.size(); ++i)
        if (parents[i] < -1 || parents[i] >= static_cast<int>(i)) return false;
    return true;
}

bool LocalToGlobalJob::run() const {
    if (!validate()) return false;
    const glm::dmat4 identity(1.0);
    const glm::dmat4& above = rootTransform != nullptr ? *rootTransform : identity;
    for (std::size_t i = 0; i < parents.size(); ++i) {
        const int parent = parents[i];
        globals[i] = (parent < 0 ? above : globals[static_cast<std::size_t>(parent)]) * locals[i];
    }
    return true;
}

std::vector<int> parentIndices(const RawMotion& motion) {
    std::vector<int> parents;
    parents.reserve(motion.joints.size());
    for (const RawJoint& joint : motion.joints) parents.push_back(joint.parent);
    return parents;
}

std::vector<glm::dmat4> globalTransforms(const RawMotion& motion, int frame, PositionChannels mode) {
    const std::span<const double> row = motion.frame(frame);
    std::vector<glm::dmat4> locals;
    locals.reserve(motion.joints.size());
    for (const RawJoint& joint : motion.joints) locals.push_back(localTransform(joint, row, mode));
    const std::vector<int> parents = parentIndices(motion);
    std::vector<glm::dmat4> globals(motion.joints.size());
    if (!LocalToGlobalJob{parents, locals, globals}.run())
        throw ThrongException(Error{Error::Kind::BadInput, "the skeleton's parents are not in depth-first order",
                                    {motion.sourceName, 0, 0}});
    return globals;
}

}  // namespace throng::motion
