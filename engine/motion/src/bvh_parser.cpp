#include "throng/motion/bvh_parser.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <optional>
#include <sstream>
#include <system_error>

#include "bvh_lexer.h"
#include "throng/core/input_file.h"
#include "throng/core/supported_range.h"

namespace throng::motion {
namespace {

using detail::BvhLexer;
using detail::numberProblem;
using detail::parseBvhNumber;
using detail::quoteToken;
using detail::Token;

// Parsing is a straight-line recursive-descent reader with an explicit stack (so a
// hierarchy a million joints deep cannot overflow the call stack). Errors are thrown
// inside and turned into a Result at the boundary, so the code reads as the grammar.
class BvhReader {
public:
    BvhReader(std::string_view text, std::string_view sourceName, const BvhLimits& limits)
        : lexer_(text), limits_(limits) {
        motion_.sourceName = std::string(sourceName);
    }

    RawMotion read() {
        checkEncoding();
        readHierarchy();
        readMotion();
        return std::move(motion_);
    }

private:
    [[noreturn]] void fail(int line, int column, const std::string& message) const {
        throw ThrongException(Error{Error::Kind::BadInput, message, {motion_.sourceName, line, column}});
    }
    [[noreturn]] void failAt(const Token& token, const std::string& expected) const {
        fail(token.line, token.column, "expected " + expected + ", found " + describe(token));
    }
    // An empty token is the end of the line when reading within a line, else the end of file.
    std::string describe(const Token& token) const {
        if (token.atEnd() && lexer_.remainingBytes() > 0) return "end of line";
        return quoteToken(token.text);
    }

    // Reject UTF-16 and binary data up front with a message that says so, rather than a
    // confusing "expected HIERARCHY" later. A UTF-8 byte-order mark is allowed and skipped.
    void checkEncoding() {
        std::string_view text = lexer_.text();
        if (text.size() >= 2 && ((text[0] == '\xff' && text[1] == '\xfe') ||
                                 (text[0] == '\xfe' && text[1] == '\xff')))
            fail(1, 1, "file is UTF-16 encoded; BVH must be ASCII or UTF-8 text");
        int line = 1, column = 1;
        for (char c : text) {
            const auto byte = static_cast<unsigned char>(c);
            if (byte == 0 || (byte < 0x20 && c != '\n' && c != '\r' && c != '\t' && c != '\f' && c != '\v'))
                fail(line, column, "expected text, found binary byte 0x" + hexByte(byte) +
                                       (byte == 0 ? " (UTF-16 or binary data?)" : ""));
            if (c == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
    }

    static std::string hexByte(unsigned byte) {
        static constexpr char kDigits[] = "0123456789abcdef";
        return {kDigits[(byte >> 4U) & 15U], kDigits[byte & 15U]};
    }

    void expectKeyword(std::string_view keyword) {
        const Token token = lexer_.next();
        if (token.text != keyword) failAt(token, "'" + std::string(keyword) + "'");
    }

    double readNumber(const Token& token, const char* what) const {
        std::optional<double> value = parseBvhNumber(token.text);
        if (!value) {
            if (token.atEnd() || token.text == "{" || token.text == "}")
                failAt(token, std::string(what));
            fail(token.line, token.column, std::string("expected ") + what + ", found " + quoteToken(token.text) +
                                               numberProblem(token.text));
        }
        return *value;
    }

    // OFFSET coordinates and channel values are bounded (throng/core/supported_range.h), so
    // forward kinematics can't overflow whatever the skeleton's depth.
    double readValue(const Token& token, const char* what) const {
        const double value = readNumber(token, what);
        if (!range::isBvhValue(value))
            fail(token.line, token.column, std::string("expected ") + what + " " + range::kBvhValueText + ", found " +
                                               quoteToken(token.text) + " (outside the supported range)");
        return value;
    }

    // Frame time gets its own checks: a value that parses may still be meaningless.
    double readFrameTime(const Token& token) const {
        const double value = readNumber(token, "a frame time in seconds");
        if (!(value > 0.0))
            fail(token.line, token.column, "frame time must be positive, found " + quoteToken(token.text));
        if (value < range::kMinFrameTime || value > range::kMaxFrameTime)
            fail(token.line, token.column,
                 "frame time must be between 1e-6 and 3600 seconds, found " + quoteToken(token.text));
        return value;
    }

    glm::dvec3 readOffset() {
        glm::dvec3 offset;
        for (int axis = 0; axis < 3; ++axis) offset[axis] = readValue(lexer_.next(), "an OFFSET coordinate");
        return offset;
    }

    std::vector<Channel> readChannels() {
        const Token countToken = lexer_.next();
        const std::optional<double> count = parseBvhNumber(countToken.text);
        if (!count || *count != std::floor(*count) || *count < 0 || *count > 6)
            failAt(countToken, "a channel count from 0 to 6");
        std::vector<Channel> channels;
        for (int i = 0; i < static_cast<int>(*count); ++i) {
            const Token token = lexer_.next();
            const std::optional<Channel> channel = channelFromName(token.text);
            if (!channel) {
                if (token.text == "}" || token.text == "JOINT" || token.text == "End" || token.text == "OFFSET")
                    fail(token.line, token.column,
                         "CHANNELS declares " + std::to_string(static_cast<int>(*count)) + " channels but lists " +
                             std::to_string(i) + ", found " + quoteToken(token.text));
                failAt(token, "a channel name (Xposition, Yposition, Zposition, Xrotation, Yrotation, Zrotation)");
            }
            for (Channel seen : channels)
                if (seen == *channel) fail(token.line, token.column, "channel " + std::string(token.text) + " is listed twice");
            channels.push_back(*channel);
        }
        return channels;
    }

    static std::optional<Channel> channelFromName(std::string_view name) {
        static constexpr Channel kAll[] = {Channel::Xposition, Channel::Yposition, Channel::Zposition,
                                           Channel::Xrotation, Channel::Yrotation, Channel::Zrotation};
        for (Channel c : kAll) {
            const std::string_view expected = channelName(c);
            if (name.size() != expected.size()) continue;
            bool same = true;  // Exporters disagree on case ("XROTATION", "Xrotation").
            for (std::size_t i = 0; i < name.size() && same; ++i)
                same = std::tolower(static_cast<unsigned char>(name[i])) ==
                       std::tolower(static_cast<unsigned char>(expected[i]));
            if (same) return c;
        }
        return std::nullopt;
    }

    void readHierarchy() {
        expectKeyword("HIERARCHY");
        const Token root = lexer_.next();
        if (root.text != "ROOT") failAt(root, "'ROOT'");
        beginJoint(root, -1);

        // Open blocks: joint index, or -2 for an End Site (which may hold only an OFFSET).
        std::vector<int> open{0};
        std::vector<bool> hasOffset{false}, hasChannels{false};
        while (!open.empty()) {
            const Token token = lexer_.next();
            const int current = open.back();
            const bool inEndSite = current == -2;
            if (token.text == "}") {
                if (!hasOffset.back())
                    fail(token.line, token.column, "block closed without an OFFSET in " + blockName(current));
                open.pop_back();
                hasOffset.pop_back();
                hasChannels.pop_back();
            } else if (token.text == "OFFSET") {
                if (hasOffset.back()) fail(token.line, token.column, "second OFFSET in the same block");
                const glm::dvec3 offset = readOffset();
                if (inEndSite) {
                    motion_.endSites.back().offset = offset;
                } else {
                    motion_.joints[current].offset = offset;
                }
                hasOffset.back() = true;
            } else if (token.text == "CHANNELS" && !inEndSite) {
                if (hasChannels.back()) fail(token.line, token.column, "second CHANNELS line in the same joint");
                motion_.joints[current].channels = readChannels();
                hasChannels.back() = true;
            } else if (token.text == "JOINT" && !inEndSite) {
                open.push_back(beginJoint(token, current));
                hasOffset.push_back(false);
                hasChannels.push_back(false);
            } else if (token.text == "End" && !inEndSite) {
                const Token site = lexer_.next();
                if (site.text != "Site") failAt(site, "'Site' after 'End'");
                expectKeyword("{");
                motion_.endSites.push_back({current, glm::dvec3(0.0)});
                open.push_back(-2);
                hasOffset.push_back(false);
                hasChannels.push_back(false);
            } else if (token.atEnd()) {
                fail(token.line, token.column,
                     "expected '}' to close " + blockName(current) + ", found end of file (unbalanced braces?)");
            } else if (token.text == "MOTION" || token.text == "ROOT") {
                fail(token.line, token.column,
                     "expected '}' to close " + blockName(current) + ", found " + quoteToken(token.text) +
                         " (unbalanced braces?)");
            } else {
                failAt(token, inEndSite ? "OFFSET or '}' in End Site"
                                        : "OFFSET, CHANNELS, JOINT, End Site or '}' in " + blockName(current));
            }
        }
        int firstValue = 0;
        for (RawJoint& joint : motion_.joints) {
            joint.firstValue = firstValue;
            firstValue += static_cast<int>(joint.channels.size());
        }
        motion_.channelCount = firstValue;
    }

    std::string blockName(int joint) const {
        return joint == -2 ? "End Site" : "joint " + quoteToken(motion_.joints[joint].name);
    }

    int beginJoint(const Token& keyword, int parent) {
        const Token name = lexer_.restOfLine();
        if (name.text.empty()) failAt(name, "a joint name after " + std::string(keyword.text));
        if (name.text.size() > range::kMaxJointNameBytes)
            fail(name.line, name.column, "joint name is longer than " + std::to_string(range::kMaxJointNameBytes) + " bytes");
        if (motion_.joints.size() >= static_cast<std::size_t>(limits_.maxJoints))
            fail(keyword.line, keyword.column,
                 "more than " + std::to_string(limits_.maxJoints) + " joints; refusing an absurd skeleton");
        expectKeyword("{");
        RawJoint joint;
        joint.name = std::string(name.text);
        joint.parent = parent;
        joint.sourceLine = keyword.line;
        motion_.joints.push_back(std::move(joint));
        return static_cast<int>(motion_.joints.size()) - 1;
    }

    // "Frames: 12", "Frames:12" and "Frames:<TAB>12" all occur in the wild.
    Token readHeaderValue(std::string_view label, const std::string& description) {
        Token token = lexer_.next();
        if (token.text.substr(0, label.size()) != label) failAt(token, "'" + std::string(label) + "'");
        if (token.text.size() > label.size()) {
            token.text.remove_prefix(label.size());
            token.column += static_cast<int>(label.size());
            return token;
        }
        Token value = lexer_.nextOnLine();
        if (value.atEnd()) failAt(value, description + " after '" + std::string(label) + "'");
        return value;
    }

    void readMotion() {
        const Token motionToken = lexer_.next();
        if (motionToken.text == "ROOT")
            fail(motionToken.line, motionToken.column, "a second ROOT hierarchy is not supported");
        if (motionToken.text != "MOTION") failAt(motionToken, "'MOTION' after the hierarchy");

        const Token framesToken = readHeaderValue("Frames:", "a frame count");
        const std::optional<double> frames = parseBvhNumber(framesToken.text);
        if (!frames || *frames != std::floor(*frames) || *frames < 0)
            failAt(framesToken, "a non-negative whole frame count");

        const Token frameWord = lexer_.next();
        if (frameWord.text != "Frame") failAt(frameWord, "'Frame Time:'");
        const Token timeToken = readHeaderValue("Time:", "a frame time");
        motion_.frameTime = readFrameTime(timeToken);
        const Token trailing = lexer_.nextOnLine();
        if (!trailing.atEnd()) failAt(trailing, "end of line after the frame time");
        readRows(framesToken, *frames);
    }

    void readRows(const Token& framesToken, double declaredFrames) {
        const int channels = motion_.channelCount;
        // Every value takes at least two bytes ("0 " or "0\n"), so the text left bounds how
        // many rows can exist. A count beyond that is refused before any allocation from it.
        // With no channels a row is an empty line, so count the lines that are left.
        const std::string_view rest = lexer_.text().substr(lexer_.offset());
        const double possibleRows =
            channels == 0 ? static_cast<double>(std::count(rest.begin(), rest.end(), '\n')) + 1.0
                          : static_cast<double>(lexer_.remainingBytes() + 1) / (2.0 * channels);
        if (declaredFrames > possibleRows || declaredFrames > 1e9)
            fail(framesToken.line, framesToken.column,
                 "Frames: " + std::string(framesToken.text) + " is more than the rest of the file can hold (at most " +
                     std::to_string(static_cast<long long>(std::min(possibleRows, 1e9))) + " rows)");
        const auto frameCount = static_cast<int>(declaredFrames);
        motion_.frameCount = frameCount;
        motion_.values.reserve(static_cast<std::size_t>(frameCount) * channels);

        int rowsRead = 0;
        while (lexer_.nextLine()) {
            Token first = lexer_.nextOnLine();
            if (first.atEnd()) continue;  // blank line
            if (rowsRead == frameCount)
                fail(first.line, first.column,
                     "expected end of file after " + std::to_string(frameCount) + " frame rows (Frames: " +
                         std::to_string(frameCount) + "), found another row starting " + quoteToken(first.text));
            int count = 0;
            for (Token value = first; !value.atEnd(); value = lexer_.nextOnLine()) {
                if (count == channels)
                    fail(value.line, value.column,
                         "frame row " + std::to_string(rowsRead + 1) + " has more than the " + std::to_string(channels) +
                             " values the hierarchy declares, found extra value " + quoteToken(value.text));
                motion_.values.push_back(readValue(value, "a number"));
                ++count;
            }
            if (count < channels)
                fail(first.line, lexer_.column(),
                     "frame row " + std::to_string(rowsRead + 1) + " has " + std::to_string(count) + " values, expected " +
                         std::to_string(channels));
            ++rowsRead;
        }
        if (rowsRead < frameCount && channels > 0)
            fail(lexer_.line(), lexer_.column(),
                 "file ends after " + std::to_string(rowsRead) + " of " + std::to_string(frameCount) +
                     " frame rows (truncated?)");
    }

    BvhLexer lexer_;
    BvhLimits limits_;
    RawMotion motion_;
};

}  // namespace

const char* channelName(Channel channel) {
    switch (channel) {
        case Channel::Xposition: return "Xposition";
        case Channel::Yposition: return "Yposition";
        case Channel::Zposition: return "Zposition";
        case Channel::Xrotation: return "Xrotation";
        case Channel::Yrotation: return "Yrotation";
        case Channel::Zrotation: return "Zrotation";
    }
    return "?";
}

Result<RawMotion> parseBvh(std::string_view text, std::string_view sourceName, const BvhLimits& limits) {
    // Skip a UTF-8 byte-order mark; column numbers then count from the first real character.
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    // Classic Mac files end lines with a lone CR. Read them as LF so lines count right.
    std::string converted;
    if (text.find('\n') == std::string_view::npos && text.find('\r') != std::string_view::npos) {
        converted.assign(text);
        std::replace(converted.begin(), converted.end(), '\r', '\n');
        text = converted;
    }
    try {
        return BvhReader(text, sourceName, limits).read();
    } catch (const ThrongException& e) {
        return e.error();
    } catch (const std::bad_alloc&) {
        return Error{Error::Kind::Runtime, "not enough memory to read this file", {std::string(sourceName), 0, 0}};
    }
}

Result<RawMotion> loadBvhFile(const std::string& path, const BvhLimits& limits) {
    auto text = readInputFile(path, static_cast<std::uint64_t>(limits.maxFileBytes), "BVH file");
    if (!text) return text.error();
    return parseBvh(text.value(), path, limits);
}

}  // namespace throng::motion
