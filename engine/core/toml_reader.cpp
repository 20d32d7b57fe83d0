// Scene loading through toml++: parse, --set overrides, typed and range-checked fields,
// unknown keys rejected. Every error is collected; nothing stops at the first.
#include "core/toml_reader.h"

#include "core/error.h"
#include "core/file_read.h"
#include "core/printable.h"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <set>
#include <toml++/toml.h>

namespace ob {

struct TomlDocument::Impl {
    toml::table root;
};

TomlDocument::TomlDocument() : m_impl(std::make_unique<Impl>()) {}
TomlDocument::~TomlDocument() = default;
TomlDocument::TomlDocument(TomlDocument&&) noexcept = default;
TomlDocument& TomlDocument::operator=(TomlDocument&&) noexcept = default;

// "file:line:column", or the --set assignment a value came from.
static std::string where(const toml::source_region& r) {
    if (!r.path) return "--set";
    const std::string p = printable(*r.path);
    if (p.rfind("--set", 0) == 0) return p;
    return p + ":" + std::to_string(r.begin.line) + ":" + std::to_string(r.begin.column);
}

static std::string parseErrorText(const toml::parse_error& e) {
    return where(e.source()) + ": TOML syntax error: " + std::string(e.description());
}

TomlDocument TomlDocument::fromFile(const std::string& path, std::vector<std::string>& errors) {
    TomlDocument doc;
    // Only a regular file is read (a device could block or read forever); an empty file
    // would silently be all defaults.
    std::string text;
    try {
        text = readRegularFile(path);
    } catch (const InputError& e) {
        errors.push_back(e.what());
        return doc;
    }
    if (text.empty()) {
        errors.push_back(path + ": is empty (a TOML file with at least one key is expected)");
        return doc;
    }
    try {
        doc.m_impl->root = toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        errors.push_back(parseErrorText(e));
    }
    return doc;
}

TomlDocument TomlDocument::fromString(const std::string& text, const std::string& sourceName,
                                      std::vector<std::string>& errors) {
    TomlDocument doc;
    try {
        doc.m_impl->root = toml::parse(text, sourceName);
    } catch (const toml::parse_error& e) {
        errors.push_back(parseErrorText(e));
    }
    return doc;
}

// Merges `from` into `into`: tables merge key by key, anything else replaces.
static bool mergeInto(toml::table& into, toml::table& from, const std::string& source, std::vector<std::string>& errors) {
    for (auto&& [key, value] : from) {
        toml::node* existing = into.get(key.str());
        if (existing && value.is_table()) {
            if (!existing->is_table()) {
                errors.push_back(source + ": '" + std::string(key.str()) + "' is not a section");
                return false;
            }
            if (!mergeInto(*existing->as_table(), *value.as_table(), source, errors)) return false;
        } else {
            into.insert_or_assign(key.str(), std::move(value));
        }
    }
    return true;
}

// One segment of a `--set` key path: a key, and the element of an array of tables it may pick.
struct PathSegment {
    std::string_view key;    // [A-Za-z0-9_-]+
    std::string_view index;  // the digits of [i]; empty when the segment has none
};

// Splits a key path ("objects[0].ship.speed") into segments, one pass, no recursion; "" or
// what is wrong. Long paths are refused before any work (no scene key comes near the limits).
static std::string scanKeyPath(std::string_view path, std::vector<PathSegment>& segments) {
    if (path.size() > MAX_KEY_PATH_CHARS)
        return "the key path has " + std::to_string(path.size()) + " characters (at most " +
               std::to_string(MAX_KEY_PATH_CHARS) + ")";
    auto isKeyChar = [](char c) {
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
    };
    auto isDigit = [](char c) { return c >= '0' && c <= '9'; };
    size_t i = 0;
    for (;;) {
        PathSegment seg;
        const size_t keyStart = i;
        while (i < path.size() && isKeyChar(path[i])) ++i;
        if (i == keyStart) return "expected key.path=value";
        seg.key = path.substr(keyStart, i - keyStart);
        if (i < path.size() && path[i] == '[') {
            const size_t digits = ++i;
            while (i < path.size() && isDigit(path[i])) ++i;
            if (i == digits || i >= path.size() || path[i] != ']') return "expected key.path=value";
            seg.index = path.substr(digits, i - digits);
            ++i;
        }
        segments.push_back(seg);
        if (segments.size() > MAX_KEY_PATH_SEGMENTS)
            return "the key path has more than " + std::to_string(MAX_KEY_PATH_SEGMENTS) + " segments";
        if (i == path.size()) return "";
        if (path[i] != '.') return "expected key.path=value";
        ++i;
    }
}

// The table segments [0, end) name: each a table, or with [i] an element of an array of
// tables. Null (and an error) when one is missing.
static toml::table* elementTable(toml::table& root, const std::vector<PathSegment>& segments, size_t end,
                                 const std::string& source, std::vector<std::string>& errors) {
    toml::table* table = &root;
    for (size_t s = 0; s < end; ++s) {
        const PathSegment& seg = segments[s];
        const std::string key(seg.key);
        toml::node* node = table->get(key);
        if (!seg.index.empty()) {
            // An index too large for size_t (a fuzzer's 30 digits) names no element either.
            size_t index = SIZE_MAX;
            std::from_chars(seg.index.data(), seg.index.data() + seg.index.size(), index);
            toml::array* array = node ? node->as_array() : nullptr;
            toml::node* item = array && index < array->size() ? array->get(index) : nullptr;
            if (!item || !item->is_table()) {
                errors.push_back(source + ": '" + key + "' has no element [" + std::string(seg.index) + "]");
                return nullptr;
            }
            table = item->as_table();
        } else {
            if (!node || !node->is_table()) {
                errors.push_back(source + ": '" + key + "' is not a section");
                return nullptr;
            }
            table = node->as_table();
        }
    }
    return table;
}

void TomlDocument::applyOverride(const std::string& assignment, std::vector<std::string>& errors) {
    // A long assignment is named by its start only: the message stays one line.
    const std::string source =
        "--set " + (assignment.size() > 2 * MAX_KEY_PATH_CHARS ? assignment.substr(0, MAX_KEY_PATH_CHARS) + "..." : assignment);
    const size_t eq = assignment.find('=');
    // Dotted keys; a segment may pick an element of an array of tables: objects[0].count.
    std::vector<PathSegment> segments;
    const std::string_view keyPath = std::string_view(assignment).substr(0, eq);
    if (eq == std::string::npos) {
        errors.push_back(source + ": expected key.path=value");
        return;
    }
    if (std::string problem = scanKeyPath(keyPath, segments); !problem.empty()) {
        errors.push_back(source + ": " + problem);
        return;
    }
    const std::string text = assignment.substr(eq + 1);
    // Up to the last [i]: the element table the rest of the path is set in.
    size_t last = segments.size();
    while (last > 0 && segments[last - 1].index.empty()) --last;
    toml::table* target = &m_impl->root;
    if (last == segments.size() && last > 0) {
        errors.push_back(source + ": expected key.path=value (a key inside the element: " + std::string(keyPath) + ".key=value)");
        return;
    }
    if (last > 0) {
        target = elementTable(m_impl->root, segments, last, source, errors);
        if (!target) return;
    }
    std::string path;
    for (size_t s = last; s < segments.size(); ++s) {
        if (!path.empty()) path += '.';
        path += segments[s].key;
    }
    // The value in TOML syntax; a bare word that is no TOML value is taken as a string.
    // The key path is a TOML dotted key, so the parse builds the nested tables itself.
    toml::table parsed;
    try {
        parsed = toml::parse(path + " = " + text, source);
    } catch (const toml::parse_error&) {
        std::string quoted = "\"";
        for (char c : text) {
            if (c == '"' || c == '\\') quoted += '\\';
            quoted += c;
        }
        try {
            parsed = toml::parse(path + " = " + quoted + "\"", source);
        } catch (const toml::parse_error&) {
            errors.push_back(source + ": value is neither TOML nor a plain word");
            return;
        }
    }
    mergeInto(*target, parsed, source, errors);
}

std::string TomlDocument::where(const std::string& keyPath, const std::string& fallback) const {
    const toml::node* node = m_impl->root.at_path(keyPath).node();
    return node && node->source().path ? ob::where(node->source()) : fallback;
}

// ---------------------------------------------------------------------------------------

struct TomlReader::State {
    struct Frame {
        const toml::table* table;    // null: section absent, every field keeps its default
        std::string prefix;          // "render." for keys inside [render]
        std::set<std::string> seen;  // keys a describe() asked for
    };
    std::vector<std::string>& errors;
    std::vector<Frame> stack;

    Frame& top() { return stack.back(); }

    const toml::node* lookup(const char* key) {
        Frame& f = top();
        f.seen.insert(key);
        return f.table ? f.table->get(key) : nullptr;
    }

    void error(const toml::node& node, const char* key, const std::string& message) {
        errors.push_back(where(node.source()) + ": " + top().prefix + key + ": " + message);
    }

    void reportUnknown(const Frame& f) {
        if (!f.table) return;
        for (auto&& [k, v] : *f.table) {
            std::string name(k.str());
            if (f.seen.count(name)) continue;
            toml::source_region r = k.source().path ? k.source() : v.source();
            const char* what = v.is_table() ? "unknown section" : "unknown key";
            errors.push_back(where(r) + ": " + f.prefix + clipped(name) + ": " + what);
        }
    }
};

static const char* typeName(const toml::node& n) {
    switch (n.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a float";
    case toml::node_type::boolean: return "a boolean";
    default: return "a date/time";
    }
}

// A number as the user wrote it: an integral value in full (4294967296, not 4.29497e+09).
static std::string num(double v) {
    char buf[32];
    if (v == std::floor(v) && std::fabs(v) < 1e15) std::snprintf(buf, sizeof buf, "%.0f", v);
    else std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// The number in `node` as a double, or an error; integers are accepted where floats are.
static bool readNumber(TomlReader::State& s, const toml::node& node, const char* key, double& out) {
    if (auto i = node.as_integer()) {
        out = double(i->get());
        return true;
    }
    if (auto f = node.as_floating_point()) {
        out = f->get();
        if (std::isfinite(out)) return true;
        s.error(node, key, "must be a finite number");
        return false;
    }
    s.error(node, key, std::string("expected a number, got ") + typeName(node));
    return false;
}

static bool checkRange(TomlReader::State& s, const toml::node& node, const char* key, double v, const Limits& l) {
    bool inRange = ob::inRange(l, v);
    bool pow2 = !l.powerOfTwo || (v >= 1 && (int64_t(v) & (int64_t(v) - 1)) == 0);
    if (inRange && pow2) return true;
    s.error(node, key, std::string("must be ") + (l.powerOfTwo ? "a power of two " : "") + rangeText(l) + ", got " + num(v));
    return false;
}

// The number as the float it is stored in: a finite double beyond a float's range (1e308)
// would become infinity there, and NaN a step later.
static bool checkFloat(TomlReader::State& s, const toml::node& node, const char* key, double v, float& out) {
    out = float(v);
    if (std::isfinite(out)) return true;
    s.error(node, key, "must be a finite number within a 32-bit float's range (|x| <= 3.4e38), got " + num(v));
    return false;
}

// A number in range, stored as a float: readNumber, checkRange and checkFloat.
static bool readFloat(TomlReader::State& s, const toml::node& node, const char* key, const Limits& l, float& out) {
    double v;
    return readNumber(s, node, key, v) && checkRange(s, node, key, v, l) && checkFloat(s, node, key, v, out);
}

TomlReader::TomlReader(const TomlDocument& doc, std::vector<std::string>& errors)
    : m_state(std::make_unique<State>(State{errors, {}})) {
    m_state->stack.push_back({&doc.m_impl->root, "", {}});
}

TomlReader::~TomlReader() = default;

void TomlReader::finish() {
    while (m_state->stack.size() > 1) leaveSection();
    m_state->reportUnknown(m_state->top());
}

bool TomlReader::enterSection(const char* key) {
    State& s = *m_state;
    const toml::node* node = s.lookup(key);
    const toml::table* table = nullptr;
    if (node) {
        table = node->as_table();
        if (!table) {
            s.error(*node, key, std::string("expected a section (table), got ") + typeName(*node));
            return false;
        }
    }
    s.stack.push_back({table, s.top().prefix + key + ".", {}});
    return true;
}

const void* TomlReader::enterList(const char* key, int& count) {
    State& s = *m_state;
    const toml::node* node = s.lookup(key);
    if (!node) return nullptr;
    const toml::array* array = node->as_array();
    if (!array) {
        s.error(*node, key, std::string("expected an array of tables, got ") + typeName(*node));
        return nullptr;
    }
    count = int(array->size());
    return array;
}

bool TomlReader::enterListItem(const void* array, const char* key, int index) {
    State& s = *m_state;
    const toml::node* item = static_cast<const toml::array*>(array)->get(size_t(index));
    std::string name = std::string(key) + "[" + std::to_string(index) + "]";
    if (!item->is_table()) {
        s.error(*item, name.c_str(), std::string("expected a table, got ") + typeName(*item));
        return false;
    }
    s.stack.push_back({item->as_table(), s.top().prefix + name + ".", {}});
    return true;
}

void TomlReader::leaveSection() {
    m_state->reportUnknown(m_state->top());
    m_state->stack.pop_back();
}

void TomlReader::field(const char* key, bool& value, const char*, Change) {
    const toml::node* node = m_state->lookup(key);
    if (!node) return;
    if (auto b = node->as_boolean()) value = b->get();
    else m_state->error(*node, key, std::string("expected true or false, got ") + typeName(*node));
}

void TomlReader::field(const char* key, int& value, Limits limits, const char*, Change) {
    const toml::node* node = m_state->lookup(key);
    if (!node) return;
    auto i = node->as_integer();
    if (!i) {
        m_state->error(*node, key, std::string("expected an integer, got ") + typeName(*node));
        return;
    }
    const double v = double(i->get());
    const Limits within{std::max(limits.min, double(INT_MIN)), std::min(limits.max, double(INT_MAX)), limits.powerOfTwo, false, limits.orZero};
    if (checkRange(*m_state, *node, key, v, within)) value = int(i->get());
}

void TomlReader::field(const char* key, uint64_t& value, const char*, Change) {
    const toml::node* node = m_state->lookup(key);
    if (!node) return;
    auto i = node->as_integer();
    if (!i || i->get() < 0) {
        m_state->error(*node, key, std::string("expected a non-negative integer, got ") + (i ? num(double(i->get())) : typeName(*node)));
        return;
    }
    value = uint64_t(i->get());
}

void TomlReader::field(const char* key, float& value, Limits limits, const char*, Change) {
    const toml::node* node = m_state->lookup(key);
    if (!node) return;
    float v;
    if (readFloat(*m_state, *node, key, limits, v)) value = v;
}

template <int N>
static void readVector(TomlReader::State& s, const char* key, float* out, const Limits& limits) {
    const toml::node* node = s.lookup(key);
    if (!node) return;
    auto arr = node->as_array();
    if (!arr || arr->size() != size_t(N)) {
        s.error(*node, key, "expected an array of " + std::to_string(N) + " numbers");
        return;
    }
    float v[N];
    bool zero = true;
    for (int i = 0; i < N; ++i) {
        if (!readFloat(s, *arr->get(size_t(i)), key, limits, v[i])) return;
        zero = zero && v[i] == 0.0f;
    }
    if (limits.nonZero && zero) {
        s.error(*node, key, "must not be the zero vector (it is a direction)");
        return;
    }
    for (int i = 0; i < N; ++i) out[i] = v[i];
}

void TomlReader::field(const char* key, glm::vec2& value, Limits limits, const char*, Change) {
    readVector<2>(*m_state, key, &value.x, limits);
}

void TomlReader::field(const char* key, glm::vec3& value, Limits limits, const char*, Change) {
    readVector<3>(*m_state, key, &value.x, limits);
}

// The string at `key`, or null (absent, or an error reported).
static const toml::value<std::string>* readString(auto& s, const char* key) {
    const toml::node* node = s.lookup(key);
    if (!node) return nullptr;
    auto str = node->as_string();
    if (!str) s.error(*node, key, std::string("expected a string, got ") + typeName(*node));
    return str;
}

// A string is read inert: its control characters become printable escapes (core/printable.h),
// so a scene's names, notes and paths print and draw as text wherever they go.
void TomlReader::field(const char* key, std::string& value, const char*, Change) {
    if (auto str = readString(*m_state, key)) value = printable(str->get());
}

void TomlReader::refuse(const char* key, const std::string& why) {
    if (const toml::node* node = m_state->lookup(key)) m_state->error(*node, key, why);
}

void TomlReader::choice(const char* key, Words words, std::size_t& index) {
    auto str = readString(*m_state, key);
    if (!str) return;
    std::string list;
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (str->get() == words[i]) {
            index = i;
            return;
        }
        list += std::string(list.empty() ? "" : ", ") + "\"" + words[i] + "\"";
    }
    m_state->error(*str, key, "must be one of " + list + ", got " + quotedValue(str->get(), MESSAGE_VALUE_CHARS, '"'));
}

bool TomlReader::choices(const char* key, Words words, std::vector<std::size_t>& indices) {
    State& s = *m_state;
    const toml::node* node = s.lookup(key);
    if (!node) return false;
    auto arr = node->as_array();
    std::string list;
    for (const char* w : words) list += std::string(list.empty() ? "" : ", ") + "\"" + w + "\"";
    if (!arr) {
        s.error(*node, key, std::string("expected an array of words (") + list + "), got " + typeName(*node));
        return false;
    }
    for (const toml::node& item : *arr) {
        auto str = item.as_string();
        const auto at = str ? std::find(words.begin(), words.end(), str->get()) : words.end();
        if (at == words.end()) {
            s.error(item, key, "each must be one of " + list + (str ? ", got \"" + str->get() + "\"" : ", got a " + std::string(typeName(item))));
            return false;
        }
        const std::size_t index = std::size_t(at - words.begin());
        if (std::find(indices.begin(), indices.end(), index) != indices.end()) {
            s.error(item, key, "\"" + str->get() + "\" is listed twice");
            return false;
        }
        indices.push_back(index);
    }
    return true;
}

void TomlReader::field(const char* key, std::vector<glm::vec2>& points, Limits limits, const char*, Change) {
    State& s = *m_state;
    const toml::node* node = s.lookup(key);
    if (!node) return;
    auto arr = node->as_array();
    if (!arr) {
        s.error(*node, key, std::string("expected an array of [x, z] pairs, got ") + typeName(*node));
        return;
    }
    std::vector<glm::vec2> out;
    for (const toml::node& item : *arr) {
        auto pair = item.as_array();
        if (!pair || pair->size() != 2) {
            s.error(item, key, "expected an array of [x, z] pairs");
            return;
        }
        float v[2];
        for (size_t i = 0; i < 2; ++i)
            if (!readFloat(s, *pair->get(i), key, limits, v[i])) return;
        out.emplace_back(v[0], v[1]);
    }
    points = std::move(out);
}

} // namespace ob
