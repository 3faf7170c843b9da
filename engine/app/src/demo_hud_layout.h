#pragma once
// THRONG_HUD_LAYOUT=FILE: the demo writes the HUD's buttons there, one "id x0 y0 x1 y1" line
// each in window pixels, rewritten when they move, so a test can click them as a person would.

#include <vector>

#include "throng/viewer/hud.h"

namespace throng::app {

class HudLayoutFile {
public:
    /// Writes `buttons` to $THRONG_HUD_LAYOUT when it is set and they changed since the last write.
    void write(const std::vector<viewer::ButtonRect>& buttons);

private:
    std::vector<viewer::ButtonRect> written_;
};

}  // namespace throng::app
