// Text from files made inert: control characters shown as printable escapes, long values cut
// for messages (docs/reliability.md#hostile-input).
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace ob {

/// How much of a value a message repeats (characters); the rest is counted, not shown.
constexpr size_t MESSAGE_VALUE_CHARS = 80;
/// The longest line an error message prints whole (characters): a safety net over every
/// message, for values no check cut itself.
constexpr size_t MESSAGE_LINE_CHARS = 1000;

/// `text` with every character a terminal could act on written as a printable escape: C0
/// controls (ESC, BEL, CR, LF, tab...) and DEL as `\x1b`-style escapes, C1 controls (U+0080 to
/// U+009F, e.g. CSI) and the bidirectional overrides (U+202A-U+202E, U+2066-U+2069) as `\u202e`,
/// a byte that is not UTF-8 as `\xff`. A backslash stays itself, so text without such
/// characters is unchanged (a scene read twice reads the same).
std::string printable(std::string_view text);

/// Whether printable(text) == text.
bool isPrintable(std::string_view text);

/// `text` for a message, unquoted: printable(), cut to `maxChars` with "..." and the whole
/// size said ("aaaa... (1048576 characters)").
std::string clipped(std::string_view text, size_t maxChars = MESSAGE_VALUE_CHARS);

/// `text` for a message: printable(), cut to `maxChars` with "..." and the whole size said
/// ("'aaaa...' (1048576 characters)"), in single quotes (or `quote`).
std::string quotedValue(std::string_view text, size_t maxChars = MESSAGE_VALUE_CHARS, char quote = '\'');

/// A whole message made safe to print: printable() per line (the newlines between problems
/// kept), each line cut to MESSAGE_LINE_CHARS with its size said.
std::string printableMessage(std::string_view message);

} // namespace ob
