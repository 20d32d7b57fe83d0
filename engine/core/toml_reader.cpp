// Scene loading through toml++: parse, --set overrides, typed and range-checked fields,
// unknown keys rejected. Every error is collected; nothing stops at the first.
#include "core/toml_reader.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <regex>
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
    const std::string& p = *r.path;
    if (p.rfind("--set", 0) == 0) return p;
    return p + ":" + std::to_string(r.begin.line) + ":" + std::to_string(r.begin.column);
}

static std::string parseErrorText(const toml::parse_error& e) {
    return where(e.source()) + ": TOML syntax error: " + std::string(e.description());
}

TomlDocument TomlDocument::fromFile(const std::string& path, std::vector<std::string>& errors) {
    TomlDocument doc;
    // What is not a readable, non-empty regular file says so (a folder would read as an
    // error deep in the parser, a device could block or read forever, an empty file would
    // silently be all defaults).
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (fs::is_directory(status)) {
        errors.push_back(path + ": is a folder, not a TOML file");
        return doc;
    }
    if (fs::exists(status) && !fs::is_regular_file(status)) {
        errors.push_back(path + ": is not a regular file (a device, pipe or socket); give a TOML file");
        return doc;
    }
    FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) {
        errors.push_back(path + ": cannot open file (" + (fs::exists(status) ? "no read permission" : "no such file") + ")");
        return doc;
    }
    const bool empty = std::fgetc(f) == EOF;
    std::fclose(f);
    if (empty) {
        errors.push_back(path + ": is empty (a TOML file with at least one key is expected)");
        return doc;
    }
    try {
        doc.m_impl->root = toml::parse_file(path);
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

// The table a `--set` path's element part names ("objects[1]" or "a.b[0].c[2]"): each
// dotted segment is a table, each [i] an element of an array of tables. Null (and an error)
// when a segment is missing.
static toml::table* elementTable(toml::table& root, const std::string& head, const std::string& source,
                                 std::vector<std::string>& errors) {
    static const std::regex SEGMENT(R"(([A-Za-z0-9_-]+)(?:\[([0-9]+)\])?)");
    toml::table* table = &root;
    size_t start = 0;
    while (start <= head.size()) {
        size_t dot = head.find('.', start);
        std::string segment = head.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
        std::smatch m;
        std::regex_match(segment, m, SEGMENT);
        toml::node* node = table->get(m[1].str());
        if (m[2].matched) {
            // An index too large for size_t (a fuzzer's 30 digits) names no element either.
            const std::string digits = m[2].str();
            size_t index = SIZE_MAX;
            std::from_chars(digits.data(), digits.data() + digits.size(), index);
            toml::array* array = node ? node->as_array() : nullptr;
            toml::node* item = array && index < array->size() ? array->get(index) : nullptr;
            if (!item || !item->is_table()) {
                errors.push_back(source + ": '" + m[1].str() + "' has no element [" + m[2].str() + "]");
                return nullptr;
            }
            table = item->as_table();
        } else {
            if (!node || !node->is_table()) {
                errors.push_back(source + ": '" + m[1].str() + "' is not a section");
                return nullptr;
            }
            table = node->as_table();
        }
        if (dot == std::string::npos) break;
        start = dot + 1;
    }
    return table;
}

void TomlDocument::applyOverride(const std::string& assignment, std::vector<std::string>& errors) {
    const std::string source = "--set " + assignment;
    size_t eq = assignment.find('=');
    // Dotted keys; a segment may pick an element of an array of tables: objects[0].count.
    static const std::regex KEY_PATH(R"([A-Za-z0-9_-]+(\[[0-9]+\])?(\.[A-Za-z0-9_-]+(\[[0-9]+\])?)*)");
    if (eq == std::string::npos || !std::regex_match(assignment.substr(0, eq), KEY_PATH)) {
        errors.push_back(source + ": expected key.path=value");
        return;
    }
    std::string path = assignment.substr(0, eq);
    std::string text = assignment.substr(eq + 1);
    // Up to the last [i]: the element table the rest of the path is set in.
    toml::table* target = &m_impl->root;
    size_t close = path.rfind(']');
    if (close != std::string::npos) {
        if (close + 1 == path.size()) {
            errors.push_back(source + ": expected key.path=value (a key inside the element: " + path + ".key=value)");
            return;
        }
        target = elementTable(m_impl->root, path.substr(0, close + 1), source, errors);
        if (!target) return;
        path = path.substr(close + 2);
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
            errors.push_back(where(r) + ": " + f.prefix + name + ": " + what);
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

static std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

static std::string rangeText(const Limits& l) {
    bool lo = std::isfinite(l.min), hi = std::isfinite(l.max);
    if (lo && hi) return "in [" + num(l.min) + ", " + num(l.max) + "]";
    if (lo) return ">= " + num(l.min);
    return "<= " + num(l.max);
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
    bool inRange = v >= l.min && v <= l.max;
    bool pow2 = !l.powerOfTwo || (v >= 1 && (int64_t(v) & (int64_t(v) - 1)) == 0);
    if (inRange && pow2) return true;
    s.error(node, key, std::string("must be ") + (l.powerOfTwo ? "a power of two " : "") + rangeText(l) + ", got " + num(v));
    return false;
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

void TomlReader::field(const char* key, bool& value, const char*) {
    const toml::node* node = m_state->lookup(key);
    if (!node) return;
    if (auto b = node->as_boolean()) value = b->get();
    else m_state->error(*node, key, std::string("expected true or false, got ") + typeName(*node));
}

void TomlReader::field(const char* key, int& value, Limits limits, const char*) {
    const toml::node* node = m_state->lookup(key);
    if (!node) return;
    auto i = node->as_integer();
    if (!i) {
        m_state->error(*node, key, std::string("expected an integer, got ") + typeName(*node));
        return;
    }
    double v = double(i->get());
    if (checkRange(*m_state, *node, key, v, limits)) value = int(i->get());
}

void TomlReader::field(const char* key, uint64_t& value, const char*) {
    const toml::node* node = m_state->lookup(key);
    if (!node) return;
    auto i = node->as_integer();
    if (!i || i->get() < 0) {
        m_state->error(*node, key, std::string("expected a non-negative integer, got ") + (i ? num(double(i->get())) : typeName(*node)));
        return;
    }
    value = uint64_t(i->get());
}

void TomlReader::field(const char* key, float& value, Limits limits, const char*) {
    const toml::node* node = m_state->lookup(key);
    if (!node) return;
    double v;
    if (readNumber(*m_state, *node, key, v) && checkRange(*m_state, *node, key, v, limits)) value = float(v);
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
    double v[N];
    bool zero = true;
    for (int i = 0; i < N; ++i) {
        if (!readNumber(s, *arr->get(size_t(i)), key, v[i]) || !checkRange(s, *arr->get(size_t(i)), key, v[i], limits)) return;
        zero = zero && v[i] == 0.0;
    }
    if (limits.nonZero && zero) {
        s.error(*node, key, "must not be the zero vector (it is a direction)");
        return;
    }
    for (int i = 0; i < N; ++i) out[i] = float(v[i]);
}

void TomlReader::field(const char* key, glm::vec2& value, Limits limits, const char*) {
    readVector<2>(*m_state, key, &value.x, limits);
}

void TomlReader::field(const char* key, glm::vec3& value, Limits limits, const char*) {
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

void TomlReader::field(const char* key, std::string& value, const char*) {
    if (auto str = readString(*m_state, key)) value = str->get();
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
    m_state->error(*str, key, "must be one of " + list + ", got \"" + str->get() + "\"");
}

void TomlReader::field(const char* key, std::vector<glm::vec2>& points, Limits limits, const char*) {
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
        double v[2];
        for (size_t i = 0; i < 2; ++i)
            if (!readNumber(s, *pair->get(i), key, v[i]) || !checkRange(s, *pair->get(i), key, v[i], limits)) return;
        out.emplace_back(float(v[0]), float(v[1]));
    }
    points = std::move(out);
}

} // namespace ob
