// The paper's path: no compute pass. Each sphere vertex resolves its own joint in the vertex
// shader from the instance index and the baked table.
#include "sphere_draw.h"
#include "throng/shaders/sphere_paper_vert.h"

namespace throng::render::detail {
namespace {

class PaperPath final : public RenderPathImpl {
public:
    explicit PaperPath(const PathSetup& setup) : spheres_(setup, kSpherePaperVertSpirv), joints_(setup.jointsPerCharacter) {}
    [[nodiscard]] RenderPath path() const override { return RenderPath::Paper; }
    [[nodiscard]] InstanceStorage storage() const override { return {.instances = false}; }
    void recordDraw(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const override {
        spheres_.record(commands, slot, joints_);
    }

private:
    SphereDraw spheres_;
    std::uint32_t joints_;
};

}  // namespace

std::unique_ptr<RenderPathImpl> makePaperPath(const PathSetup& setup) { return std::make_unique<PaperPath>(setup); }

}  // namespace throng::render::detail
