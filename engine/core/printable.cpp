// Printable escapes for control characters; cut values for messages.
#include "core/printable.h"

#include <cstdint>
#include <cstdio>

namespace ob {

namespace {

// The length of the UTF-8 sequence at `s[i]` and its code point; 0 when it is not one.
size_t utf8Sequence(std::string_view s, size_t i, uint32_t& cp) {
    const auto byte = [&](size_t k) { return uint8_t(s[k]); };
    const uint8_t b = byte(i);
    size_t n = b < 0x80 ? 1 : (b >> 5) == 0x6 ? 2 : (b >> 4) == 0xE ? 3 : (b >> 3) == 0x1E ? 4 : 0;
    if (n == 0 || i + n > s.size()) return 0;
    cp = n == 1 ? b : n == 2 ? (b & 0x1Fu) : n == 3 ? (b & 0x0Fu) : (b & 0x07u);
    for (size_t k = 1; k < n; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) return 0;
        cp = (cp << 6) | (byte(i + k) & 0x3Fu);
    }
    // Overlong forms and surrogates are not UTF-8 either.
    static constexpr uint32_t SMALLEST[5] = {0, 0, 0x80, 0x800, 0x10000};
    if (cp < SMALLEST[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
    return n;
}

// A code point a terminal or a text renderer acts on instead of showing.
bool isActingCodePoint(uint32_t cp) {
    return cp < 0x20 || cp == 0x7F || (cp >= 0x80 && cp <= 0x9F) || (cp >= 0x202A && cp <= 0x202E) ||
           (cp >= 0x2066 && cp <= 0x2069);
}

std::string escapeCode(const char* format, uint32_t value) {
    char buf[16];
    std::snprintf(buf, sizeof buf, format, unsigned(value));
    return buf;
}

// The longest prefix of `text` of at most `maxChars` bytes that ends at a character's start.
std::string_view printableHead(std::string_view text, size_t maxChars) {
    if (text.size() <= maxChars) return text;
    size_t cut = maxChars;
    while (cut > 0 && (uint8_t(text[cut]) & 0xC0) == 0x80) --cut;
    return text.substr(0, cut);
}

} // namespace

std::string printable(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size();) {
        uint32_t cp = 0;
        const size_t n = utf8Sequence(text, i, cp);
        if (n == 0) {
            out += escapeCode("\\x%02x", uint8_t(text[i]));
            i += 1;
            continue;
        }
        if (isActingCodePoint(cp)) out += escapeCode(cp < 0x80 ? "\\x%02x" : "\\u%04x", cp);
        else out.append(text.substr(i, n));
        i += n;
    }
    return out;
}

bool isPrintable(std::string_view text) {
    for (size_t i = 0; i < text.size();) {
        uint32_t cp = 0;
        const size_t n = utf8Sequence(text, i, cp);
        if (n == 0 || isActingCodePoint(cp)) return false;
        i += n;
    }
    return true;
}

std::string clipped(std::string_view text, size_t maxChars) {
    if (text.size() <= maxChars) return printable(text);
    return printable(printableHead(text, maxChars)) + "... (" + std::to_string(text.size()) + " characters)";
}

std::string quotedValue(std::string_view text, size_t maxChars, char quote) {
    const std::string q(1, quote);
    if (text.size() <= maxChars) return q + printable(text) + q;
    return q + printable(printableHead(text, maxChars)) + "..." + q + " (" + std::to_string(text.size()) + " characters)";
}

std::string printableMessage(std::string_view message) {
    std::string out;
    for (size_t start = 0; start <= message.size();) {
        size_t end = message.find('\n', start);
        if (end == std::string_view::npos) end = message.size();
        std::string_view line = message.substr(start, end - start);
        if (start > 0) out += '\n';
        out += printable(printableHead(line, MESSAGE_LINE_CHARS));
        if (line.size() > MESSAGE_LINE_CHARS) out += "... (a line of " + std::to_string(line.size()) + " characters, cut)";
        start = end + 1;
    }
    return out;
}

} // namespace ob
