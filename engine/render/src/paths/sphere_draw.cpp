#include "sphere_draw.h"

#include "throng/shaders/sphere_frag.h"

namespace throng::render::detail {

SphereMesh makeUnitSphere(std::uint32_t segments, std::uint32_t rings) {
    SphereMesh mesh;
    const float pi = glm::pi<float>();
    mesh.positions.push_back({0.0F, 1.0F, 0.0F});
    for (std::uint32_t ring = 1; ring < rings; ++ring) {
        const float polar = pi * static_cast<float>(ring) / static_cast<float>(rings);
        for (std::uint32_t segment = 0; segment < segments; ++segment) {
            const float azimuth = 2.0F * pi * static_cast<float>(segment) / static_cast<float>(segments);
            mesh.positions.push_back({std::sin(polar) * std::sin(azimuth), std::cos(polar), std::sin(polar) * std::cos(azimuth)});
        }
    }
    mesh.positions.push_back({0.0F, -1.0F, 0.0F});
    const auto bottom = static_cast<std::uint16_t>(mesh.positions.size() - 1);
    auto ringVertex = [&](std::uint32_t ring, std::uint32_t segment) {
        return static_cast<std::uint16_t>(1 + (ring - 1) * segments + segment % segments);
    };
    for (std::uint32_t s = 0; s < segments; ++s) mesh.indices.insert(mesh.indices.end(), {0, ringVertex(1, s), ringVertex(1, s + 1)});
    for (std::uint32_t ring = 1; ring + 1 < rings; ++ring)
        for (std::uint32_t s = 0; s < segments; ++s) {
            const std::uint16_t a = ringVertex(ring, s), b = ringVertex(ring, s + 1), c = ringVertex(ring + 1, s),
                                d = ringVertex(ring + 1, s + 1);
            mesh.indices.insert(mesh.indices.end(), {a, c, d, a, d, b});
        }
    for (std::uint32_t s = 0; s < segments; ++s)
        mesh.indices.insert(mesh.indices.end(), {bottom, ringVertex(rings - 1, s + 1), ringVertex(rings - 1, s)});
    return mesh;
}

SphereDraw::SphereDraw(const PathSetup& setup, std::span<const std::uint32_t> vertexSpirv) {
    const gpu::Context& context = *setup.context;
    const SphereMesh sphere = makeUnitSphere(12, 8);
    indexCount_ = static_cast<std::uint32_t>(sphere.indices.size());
    vertices_ = gpu::Buffer(context, {.size = sphere.positions.size() * sizeof(glm::vec3), .usage = vk::BufferUsageFlagBits::eVertexBuffer});
    indices_ = gpu::Buffer(context, {.size = sphere.indices.size() * sizeof(std::uint16_t), .usage = vk::BufferUsageFlagBits::eIndexBuffer});
    gpu::uploadToDeviceLocal(context, vertices_, std::as_bytes(std::span(sphere.positions)));
    gpu::uploadToDeviceLocal(context, indices_, std::as_bytes(std::span(sphere.indices)));
    const auto vertex = gpu::createShaderModule(context, vertexSpirv);
    const auto fragment = gpu::createShaderModule(context, kSphereFragSpirv);
    gpu::GraphicsPipelineInfo info = targetPipeline(setup, vertex, &fragment, vk::PrimitiveTopology::eTriangleList);
    info.vertexBindings = {{.binding = 0, .stride = sizeof(glm::vec3), .inputRate = vk::VertexInputRate::eVertex}};
    info.vertexAttributes = {{.location = 0, .binding = 0, .format = vk::Format::eR32G32B32Sfloat, .offset = 0}};
    pipeline_ = gpu::createGraphicsPipeline(context, info);
}

void SphereDraw::record(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot, std::uint32_t jointsPerCharacter) const {
    commands.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipeline_);
    commands.bindVertexBuffers(0, vertices_.handle(), vk::DeviceSize{0});
    commands.bindIndexBuffer(indices_.handle(), 0, vk::IndexType::eUint16);
    commands.drawIndexed(indexCount_, slot.characterCount * jointsPerCharacter, 0, 0, 0);
}

}  // namespace throng::render::detail
