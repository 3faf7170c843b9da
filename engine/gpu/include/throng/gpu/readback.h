#pragma once
// Getting GPU results back to the host: an image copied into a pitched host buffer, or the
// first bytes of a device-local buffer.

#include <cstdint>
#include <vector>

#include "throng/gpu/resources.h"

namespace throng::gpu {

/// A host-visible buffer that an RGBA8 image is copied into. Rows start every rowTexels()
/// texels (a multiple of 64) rather than every width, as a driver's preferred pitch would;
/// the copy is told the pitch and read() honours it.
class ImageReadback {
public:
    ImageReadback(const Context& context, vk::Extent2D extent);

    /// Records the copy of `image` (in TransferSrcOptimal, written by earlier commands and
    /// already made visible to transfer reads) and the barrier that makes it visible to the host.
    void recordCopy(const vk::raii::CommandBuffer& commands, vk::Image image) const;
    /// After the submission's fence: width × height × 4 bytes, rows top to bottom, tightly packed.
    [[nodiscard]] std::vector<std::uint8_t> read() const;
    [[nodiscard]] vk::Extent2D extent() const { return extent_; }
    [[nodiscard]] std::uint32_t rowTexels() const { return rowTexels_; }

private:
    vk::Extent2D extent_;
    std::uint32_t rowTexels_;
    Buffer buffer_;
};

/// Copies the first `bytes` of `source` (which needs TransferSrc usage) to the host, waiting
/// for the copy. For tests and dumps, not for per-frame work.
[[nodiscard]] std::vector<std::byte> downloadBuffer(const Context& context, const Buffer& source, std::size_t bytes);

}  // namespace throng::gpu
