#include "throng/viewer/hud.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

namespace throng::viewer {
namespace {

void checkImGuiResult(VkResult result) {
    if (result != VK_SUCCESS) gpu::throwVulkanError(static_cast<vk::Result>(result), "ImGui Vulkan backend", __FILE__, __LINE__);
}

}  // namespace

Hud::Hud(const gpu::Context& context, const Window& window, const Presenter& presenter) {
    const vk::DescriptorPoolSize size{vk::DescriptorType::eCombinedImageSampler, 16};
    pool_ = vk::raii::DescriptorPool(context.device(), vk::DescriptorPoolCreateInfo{
                                                           .flags = vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet,
                                                           .maxSets = 16, .poolSizeCount = 1, .pPoolSizes = &size});
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // never write imgui.ini into the user's working directory
    ImGui::StyleColorsDark();
    // ImGui's colours are sRGB values, but the swapchain is an sRGB format that encodes what the
    // shaders write: convert them to linear once, or the panel comes out washed-out grey.
    for (ImVec4& color : ImGui::GetStyle().Colors) {
        const auto linear = [](float c) { return c <= 0.04045F ? c / 12.92F : std::pow((c + 0.055F) / 1.055F, 2.4F); };
        color = ImVec4(linear(color.x), linear(color.y), linear(color.z), color.w);
    }
    ImGui_ImplGlfw_InitForVulkan(window.handle(), true);
    ImGui_ImplVulkan_InitInfo init{};
    init.Instance = *context.instance();
    init.PhysicalDevice = *context.physicalDevice();
    init.Device = *context.device();
    init.QueueFamily = context.queueFamily();
    init.Queue = *context.queue();
    init.DescriptorPool = *pool_;
    init.MinImageCount = 2;
    init.ImageCount = std::max(presenter.imageCount(), 2U);
    init.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    init.CheckVkResultFn = &checkImGuiResult;
    ImGui_ImplVulkan_Init(&init, presenter.overlayRenderPass());
    gpu::immediateSubmit(context, [](const vk::raii::CommandBuffer& commands) { ImGui_ImplVulkan_CreateFontsTexture(*commands); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

Hud::~Hud() {
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

bool Hud::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool Hud::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }
bool Hud::wantsTextInput() const { return ImGui::GetIO().WantTextInput; }

ActionSet Hud::build(const HudStats& stats) {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ActionSet actions{};
    if (visible_) buildPanel(stats, actions);
    ImGui::Render();
    return actions;
}

void Hud::buildPanel(const HudStats& stats, ActionSet& actions) {
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.94F);  // blending is in linear light: lower reads as grey
    ImGui::Begin("throng", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove);
    const double fps = stats.frameMs > 0 ? 1000.0 / stats.frameMs : 0.0;
    ImGui::Text("%.1f fps  %.2f ms/frame", fps, stats.frameMs);
    if (!stats.frameHistory.empty()) {
        const float highest = *std::max_element(stats.frameHistory.begin(), stats.frameHistory.end());
        ImGui::PlotLines("##frames", stats.frameHistory.data(), static_cast<int>(stats.frameHistory.size()), 0, "frame ms", 0.0F,
                         std::max(highest * 1.2F, 1.0F), ImVec2(260, 48));
    }
    // Paired lines keep the panel short enough to leave the scene room in a small window.
    if (stats.gpu.computeMs >= 0)
        ImGui::Text("CPU step %.2f ms   GPU compute %.2f ms  draw %.2f ms", stats.simulationMs, stats.gpu.computeMs, stats.gpu.drawMs);
    else
        ImGui::Text("CPU step %.2f ms   GPU timestamps not supported", stats.simulationMs);
    ImGui::Separator();
    ImGui::Text("%d characters x %u joints = %llu instances", stats.characters, stats.jointsPerCharacter,
                static_cast<unsigned long long>(stats.characters) * stats.jointsPerCharacter);
    if (stats.skinDetail >= 0)
        ImGui::Text("bodies: %lld skinned, %lld bones, %lld joint spheres, %lld culled", static_cast<long long>(stats.skinDetail),
                    static_cast<long long>(stats.boneDetail), static_cast<long long>(stats.coarseDetail), static_cast<long long>(stats.culled));
    else if (stats.fullDetail >= 0)
        ImGui::Text("detail: %lld full, %lld major joints only, %lld culled", static_cast<long long>(stats.fullDetail),
                    static_cast<long long>(stats.coarseDetail), static_cast<long long>(stats.culled));
    std::string modes;
    for (const std::string& mode : stats.groupModes) modes += (modes.empty() ? "" : ", ") + mode;
    ImGui::Text("%s %s   playback %.2fx   simulated %.1f s%s", stats.groupModes.size() > 1 ? "groups:" : "mode", modes.c_str(),
                static_cast<double>(stats.playbackSpeed), stats.simulatedSeconds, stats.paused ? "  (paused)" : "");
    if (stats.following >= 0) ImGui::Text("following character %d (highlighted)", stats.following);
    for (const std::string& line : stats.pace)
        if (!line.empty()) ImGui::TextUnformatted(line.c_str());
    if (!stats.recording.empty()) ImGui::TextColored(ImVec4(1.0F, 0.35F, 0.3F, 1.0F), "REC %s", stats.recording.c_str());
    ImGui::Separator();
    ImGui::TextUnformatted(stats.device.c_str());
    ImGui::Text("%s path, %ux MSAA, present %s, %u swapchain rebuilds", stats.renderPath.c_str(), stats.msaa,
                stats.presentMode.c_str(), stats.swapchainRecreations);
    if (!stats.tuning.empty()) ImGui::TextWrapped("picked for this device: %s", stats.tuning.c_str());
    ImGui::Separator();
    buttons_.clear();
    bool firstInRow = true;
    for (const Control& control : kControls) {
        if (!control.newRow && !firstInRow) ImGui::SameLine();
        firstInRow = false;
        std::string label = std::string(control.button) + " [" + std::string(control.keyLabel) + "]";
        if (control.action == Action::TogglePause && stats.paused) label = "Resume [" + std::string(control.keyLabel) + "]";
        // Recording turns its button red; its label stays, so the panel keeps its width and the
        // view beside it does not shift in the video.
        const bool recording = control.action == Action::Record && !stats.recording.empty();
        if (recording) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.75F, 0.2F, 0.18F, 1.0F));
        actions[static_cast<std::size_t>(control.action)] = ImGui::Button(label.c_str());
        if (recording) ImGui::PopStyleColor();
        const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
        buttons_.push_back({control.action, lo.x, lo.y, hi.x, hi.y});
    }
    ImGui::TextDisabled("mouse: left orbit, right/middle pan, wheel zoom; WASD/QE fly");
    panelRight_ = ImGui::GetWindowPos().x + ImGui::GetWindowSize().x;
    ImGui::End();
}

void Hud::record(const vk::raii::CommandBuffer& commands) const {
    ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), *commands);
}

}  // namespace throng::viewer
