#include "clip_spec.h"

#include "cli_internal.h"

#include <algorithm>
#include <set>
#include <vector>

namespace throng::app {
namespace {

// "yes"/"no" and "true"/"false" as well as 0/1: shells and scripts write all of them.
std::optional<bool> parseSwitch(std::string_view text) {
    if (text == "1" || text == "yes" || text == "true") return true;
    if (text == "0" || text == "no" || text == "false") return false;
    return std::nullopt;
}

bool isKey(std::string_view word) {
    return std::any_of(kClipOverrides.begin(), kClipOverrides.end(), [word](const ClipOverrideName& o) { return o.key == word; });
}

std::string keyList() {
    std::string list;
    for (std::size_t i = 0; i < kClipOverrides.size(); ++i)
        list += (i == 0 ? "" : i + 1 == kClipOverrides.size() ? " and " : ", ") + std::string(kClipOverrides[i].key);
    return list;
}

// Where the overrides start in `text` (the ':' before them), or npos when it is all path.
std::size_t overridesColon(std::string_view text) {
    for (std::size_t colon = text.rfind(':'); colon != std::string_view::npos;
         colon = colon == 0 ? std::string_view::npos : text.rfind(':', colon - 1)) {
        const std::string_view rest = text.substr(colon + 1);
        const std::string_view first = rest.substr(0, rest.find(','));
        if (first.find('=') != std::string_view::npos || isKey(first)) return colon;
    }
    return std::string_view::npos;
}

std::string refusal(std::string_view key, const std::string& takes, std::string_view value) {
    return std::string(key) + " takes " + takes + ", not '" + std::string(value) + "'";
}

}  // namespace

bool acceptedMetresPerUnit(double value) { return value > 0.0 && value <= kMaxMetresPerUnit; }

bool acceptedLoop(long long first, long long last) { return first >= 0 && first < last && last <= INT_MAX; }

std::optional<motion::PositionChannels> positionChannelsFromName(std::string_view name) {
    if (name == "replace") return motion::PositionChannels::Replace;
    if (name == "add") return motion::PositionChannels::Add;
    return std::nullopt;
}

std::string upAxisList() {
    constexpr std::array axes{motion::UpAxis::PlusY, motion::UpAxis::MinusY, motion::UpAxis::PlusZ,
                              motion::UpAxis::MinusZ, motion::UpAxis::PlusX, motion::UpAxis::MinusX};
    std::string list;
    for (std::size_t i = 0; i < axes.size(); ++i)
        list += (i == 0 ? "" : i + 1 == axes.size() ? " or " : ", ") + std::string(motion::upAxisName(axes[i]));
    return list;
}

std::optional<std::string> applyClipOverride(std::string_view key, std::string_view value, motion::BakeOptions& bake) {
    if (!isKey(key)) return "unknown key '" + std::string(key) + "'; the keys are " + keyList();
    if (key == "units") {
        const std::optional<double> units = detail::parseNumber<double>(value);
        if (!units || !acceptedMetresPerUnit(*units))
            return refusal(key, "a positive number of metres per file unit, at most 1e6 (e.g. 0.01 for centimetres)", value);
        bake.metresPerUnit = *units;
    } else if (key == "up") {
        const std::optional<motion::UpAxis> axis = motion::upAxisFromName(value);
        if (!axis) return refusal(key, upAxisList(), value);
        bake.upAxis = *axis;
    } else if (key == "root") {
        if (value.empty()) return std::string("root takes the name of a joint of the file, not an empty name");
        bake.travelJoint = std::string(value);
    } else if (key == "loop") {
        const std::size_t dash = value.find('-', 1);  // from 1: a leading '-' is a sign, refused below
        const std::optional<long long> first = detail::parseNumber<long long>(value.substr(0, dash));
        const std::optional<long long> last =
            dash == std::string_view::npos ? std::nullopt : detail::parseNumber<long long>(value.substr(dash + 1));
        if (!first || !last || !acceptedLoop(*first, *last)) return refusal(key, "FIRST-LAST frame indices with FIRST < LAST", value);
        bake.loop = motion::LoopRange{static_cast<int>(*first), static_cast<int>(*last)};
    } else if (key == "position-channels") {
        const std::optional<motion::PositionChannels> channels = positionChannelsFromName(value);
        if (!channels) return refusal(key, "replace or add", value);
        bake.positionChannels = *channels;
    } else {
        const std::optional<bool> on = parseSwitch(value);
        if (!on) return refusal(key, "0 or 1 (or no/yes, false/true)", value);
        if (key == "straighten") bake.straighten = *on;
        if (key == "foot-lock") bake.footLock = *on;
        if (key == "keep-first-frame") bake.skipFirstFrame = *on ? std::optional<bool>(false) : std::nullopt;
    }
    return std::nullopt;
}

Result<ClipSpec> parseClipArgument(std::string_view text, const std::function<bool(const std::string&)>& exists) {
    const auto refused = [](const std::string& message) { return Error{Error::Kind::BadInput, message, {}}; };
    ClipSpec clip{std::string(text), {}};
    const std::size_t colon = exists(clip.path) ? std::string_view::npos : overridesColon(text);
    if (colon == std::string_view::npos) return clip;
    clip.path = std::string(text.substr(0, colon));
    if (clip.path.empty()) return refused("FILE:key=value,... needs a FILE before the ':'");
    std::set<std::string_view> given;
    std::string_view rest = text.substr(colon + 1);
    while (true) {
        const std::size_t comma = rest.find(',');
        const std::string_view item = rest.substr(0, comma);
        const std::size_t equals = item.find('=');
        const std::string_view key = item.substr(0, equals);
        if (equals == std::string_view::npos) {
            if (isKey(key)) return refused(std::string(key) + " needs a value: " + std::string(key) + "=...");
            return refused("expected key=value, not '" + std::string(item) + "'; the keys are " + keyList());
        }
        if (!given.insert(key).second) return refused(std::string(key) + " is given twice");
        if (auto wrong = applyClipOverride(key, item.substr(equals + 1), clip.bake)) return refused(*wrong);
        if (comma == std::string_view::npos) return clip;
        rest.remove_prefix(comma + 1);
    }
}

}  // namespace throng::app
