#include "demo_hud_layout.h"

#include <cstdio>
#include <cstdlib>
#include <string>

#include "output.h"

namespace throng::app {
namespace {

std::string_view controlId(viewer::Action action) {
    for (const viewer::Control& control : viewer::kControls)
        if (control.action == action) return control.id;
    return "unknown";
}

bool sameLayout(const std::vector<viewer::ButtonRect>& a, const std::vector<viewer::ButtonRect>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].action != b[i].action || a[i].x0 != b[i].x0 || a[i].y0 != b[i].y0 || a[i].x1 != b[i].x1 || a[i].y1 != b[i].y1)
            return false;
    return true;
}

}  // namespace

void HudLayoutFile::write(const std::vector<viewer::ButtonRect>& buttons) {
    const char* path = std::getenv("THRONG_HUD_LAYOUT");
    if (path == nullptr || buttons.empty() || sameLayout(buttons, written_)) return;
    std::string text;
    for (const viewer::ButtonRect& b : buttons) {
        char line[128];
        std::snprintf(line, sizeof line, "%s %.0f %.0f %.0f %.0f\n", std::string(controlId(b.action)).c_str(), b.x0, b.y0, b.x1, b.y1);
        text += line;
    }
    if (writeOutput(path, text) == 0) written_ = buttons;
}

}  // namespace throng::app
