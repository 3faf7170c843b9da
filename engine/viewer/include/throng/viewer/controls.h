#pragma once
// The demo's controls, listed once: the window's key handling, the HUD's buttons and the help
// text are all read from these tables. No GLFW here: keys are named abstractly and mapped to
// GLFW codes only in window.cpp.

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace throng::viewer {

/// Keys the demo reacts to.
enum class Key : std::uint8_t { Escape, Space, Plus, Minus, Up, Down, LeftBracket, RightBracket, M, P, F, C, W, A, S, D, Q, E, F1, H, B, R, Count };
inline constexpr std::size_t kKeyCount = static_cast<std::size_t>(Key::Count);

/// What a key press or a HUD button asks for.
enum class Action : std::uint8_t {
    Quit, TogglePause, Slower, Faster, WalkSlower, WalkFaster, HalveCrowd, DoubleCrowd, NextMode, NextBody, FrameCrowd, FollowNext, Screenshot, Record, ToggleHud, Count
};
inline constexpr std::size_t kActionCount = static_cast<std::size_t>(Action::Count);

struct Control {
    Action action;
    std::string_view id;        ///< A stable one-word name (scripts and tests use it).
    Key key;
    Key altKey;                 ///< A second key for the same action, or Key::Count for none.
    std::string_view keyLabel;  ///< How the keys are written in help and on the button.
    std::string_view button;    ///< The HUD button's text.
    std::string_view help;      ///< What it does, for the help text.
    bool newRow = false;        ///< The HUD starts a new row of buttons here.
};

/// Every action with its key, in the HUD's button order.
inline constexpr std::array<Control, kActionCount> kControls{{
    {Action::TogglePause, "pause", Key::Space, Key::Count, "space", "Pause", "pause or resume", true},
    {Action::Slower, "slower", Key::Minus, Key::Count, "-", "Slower", "playback speed / 1.25"},
    {Action::Faster, "faster", Key::Plus, Key::Count, "+", "Faster", "playback speed x 1.25"},
    {Action::WalkSlower, "walk_slower", Key::Down, Key::Count, "Down", "Walk slower",
     "walk slower: every locomotion-set character wants less ground speed (toward standing)", true},
    {Action::WalkFaster, "walk_faster", Key::Up, Key::Count, "Up", "Walk faster",
     "walk faster: every locomotion-set character wants more ground speed (walk, then run)"},
    {Action::HalveCrowd, "halve", Key::LeftBracket, Key::Count, "[", "Halve crowd", "halve the crowd (regions shrink so the density stays)", true},
    {Action::DoubleCrowd, "double", Key::RightBracket, Key::Count, "]", "Double crowd", "double the crowd"},
    {Action::NextMode, "mode", Key::M, Key::Count, "M", "Next mode", "next locomotion mode (group, goals, avoid)", true},
    {Action::NextBody, "body", Key::B, Key::Count, "B", "Next body", "next body: joint spheres, bone capsules, skinned meshes, auto (by size on screen)"},
    {Action::FrameCrowd, "frame", Key::F, Key::Count, "F", "Frame crowd", "frame the whole crowd"},
    {Action::FollowNext, "follow", Key::C, Key::Count, "C", "Follow", "follow the next character"},
    {Action::Screenshot, "screenshot", Key::P, Key::Count, "P", "Screenshot", "save a screenshot, throng-screenshot-N.png (never overwrites)", true},
    {Action::Record, "record", Key::R, Key::Count, "R", "Record",
     "start or stop recording what the window shows, to throng-recording-N.mp4 (never overwrites)"},
    {Action::ToggleHud, "hud", Key::F1, Key::H, "F1/H", "Hide HUD", "hide or show the HUD (this panel)"},
    {Action::Quit, "quit", Key::Escape, Key::Count, "Esc", "Quit", "quit"},
}};

/// Controls that act while held or through the mouse: help text only.
struct PointerControl {
    std::string_view input;
    std::string_view help;
};
inline constexpr std::array<PointerControl, 4> kPointerControls{{
    {"left mouse drag", "orbit"},
    {"right or middle mouse drag", "pan"},
    {"mouse wheel", "zoom"},
    {"W A S D, Q E (held)", "fly over the ground, down and up"},
}};

/// The action bound to `key`, if any.
[[nodiscard]] constexpr std::optional<Action> actionForKey(Key key) {
    for (const Control& control : kControls)
        if (control.key == key || control.altKey == key) return control.action;
    return std::nullopt;
}

/// "Controls:" followed by one line per control, for --help.
[[nodiscard]] inline std::string controlsHelpText() {
    std::string text = "Controls:\n";
    const auto line = [&](std::string_view input, std::string_view help) {
        std::string padded(input);
        padded.resize(std::max<std::size_t>(padded.size() + 2, 30), ' ');
        text += "  " + padded + std::string(help) + "\n";
    };
    for (const PointerControl& control : kPointerControls) line(control.input, control.help);
    for (const Control& control : kControls) line(control.keyLabel, control.help);
    return text;
}

}  // namespace throng::viewer
