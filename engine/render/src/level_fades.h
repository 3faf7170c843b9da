#pragma once
// Bone bodies' cross-fades between levels of detail, kept from frame to frame (lod_fade.glsl):
// one buffer per batch of the crowd, shared by every frame-in-flight slot, since the fades move
// on from whatever frame came before, whichever slot drew it. Private to the render module.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "throng/gpu/resources.h"

namespace throng::render::detail {

class LevelFades {
public:
    /// `kept`: whether the path plans bone bodies, the only ones that fade; otherwise every
    /// batch's buffer is a placeholder that no shader reads.
    LevelFades(const gpu::Context& context, bool kept, std::uint32_t batchCharacters);

    /// Batch `batch`'s buffer (made, a placeholder, on first use).
    [[nodiscard]] const gpu::Buffer& buffer(std::uint32_t batch);

    /// Before batch `batch` draws `characters` characters, continuing the previous frame's fades
    /// or not (SceneUniforms::levelFadesContinue): sizes its buffer for them, waiting for the
    /// device first when it must be made again (then `resized` is true and every descriptor set
    /// that named it must be written again), and says whether the frame may continue the fades:
    /// not when the buffer holds no previous frame of a crowd this size.
    struct Frame {
        bool resized = false;
        bool continues = false;
    };
    [[nodiscard]] Frame prepare(std::uint32_t batch, std::size_t characters, bool continues);
    /// Batches from `batch` on draw nothing this frame: whatever they held is no previous frame
    /// of the crowd they may draw later.
    void idleFrom(std::uint32_t batch);

private:
    const gpu::Context* context_;
    bool kept_;
    std::uint32_t batchCharacters_;
    struct Batch {
        gpu::Buffer buffer;
        std::size_t capacity = 0;  ///< characters the buffer holds (0: a placeholder)
        std::size_t drawn = 0;     ///< characters its last frame drew (0: none yet)
    };
    std::vector<Batch> batches_;
};

}  // namespace throng::render::detail
