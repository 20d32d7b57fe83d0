// TOML text of Def values, default pruning and emission ([section] after the keys, [[list]]).
#include "core/toml_writer.h"

#include <charconv>

namespace ob {

std::string tomlValue(bool v) { return v ? "true" : "false"; }
std::string tomlValue(int v) { return std::to_string(v); }
std::string tomlValue(uint64_t v) { return std::to_string(v); }

std::string tomlValue(float v) {
    // Shortest text that reads back as the same float; always with a point or exponent,
    // so TOML reads a float.
    char buf[32];
    auto result = std::to_chars(buf, buf + sizeof buf, v);
    std::string text(buf, result.ptr);
    if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
    return text;
}

// "[a, b, ...]" of already formatted values.
static std::string array(std::initializer_list<std::string> items) {
    std::string out = "[";
    for (const std::string& item : items) {
        if (out.size() > 1) out += ", ";
        out += item;
    }
    out += "]";
    return out;
}

std::string tomlValue(const glm::vec2& v) { return array({tomlValue(v.x), tomlValue(v.y)}); }
std::string tomlValue(const glm::vec3& v) { return array({tomlValue(v.x), tomlValue(v.y), tomlValue(v.z)}); }

std::string tomlValue(const std::string& v) {
    std::string out = "\"";
    for (char c : v) {
        if (c == '"' || c == '\\') out += '\\';
        if (c == '\n') {
            out += "\\n";
            continue;
        }
        out += c;
    }
    return out + "\"";
}

std::string tomlValue(const std::vector<glm::vec2>& v) {
    std::string out = "[";
    for (size_t i = 0; i < v.size(); ++i) {
        if (i) out += ", ";
        out += tomlValue(v[i]);
    }
    out += "]";
    return out;
}

void pruneDefaults(TomlNode& node, const TomlNode& defaults) {
    std::vector<std::pair<std::string, std::string>> kept;
    for (auto& [key, value] : node.keys) {
        bool same = false;
        for (const auto& [dk, dv] : defaults.keys) same = same || (dk == key && dv == value);
        if (!same) kept.emplace_back(key, value);
    }
    node.keys = std::move(kept);
    for (auto& [key, child] : node.sections)
        for (const auto& [dk, dchild] : defaults.sections)
            if (dk == key) pruneDefaults(child, dchild);
    // A list is kept whole unless it is empty: then it is dropped when the default is empty
    // too, else written as the key `name = []` (an empty array of tables has no [[ ]] form).
    std::vector<TomlNode::List> lists;
    for (auto& [key, items] : node.lists) {
        if (!items.empty()) {
            lists.push_back({key, std::move(items)});
            continue;
        }
        bool defaultEmpty = true;
        for (const auto& [dk, ditems] : defaults.lists)
            if (dk == key) defaultEmpty = ditems.empty();
        if (!defaultEmpty) node.keys.emplace_back(key, "[]");
    }
    node.lists = std::move(lists);
}

static bool isEmpty(const TomlNode& n) {
    if (!n.keys.empty() || !n.lists.empty()) return false;
    for (const auto& [key, child] : n.sections)
        if (!isEmpty(child)) return false;
    return true;
}

std::string emitToml(const TomlNode& node, const std::string& prefix) {
    std::string out;
    for (const auto& [key, value] : node.keys) {
        out += key;
        out += " = ";
        out += value;
        out += "\n";
    }
    for (const auto& [key, child] : node.sections) {
        if (isEmpty(child)) continue;
        const std::string name = prefix.empty() ? key : prefix + "." + key;
        if (!child.keys.empty()) {
            out += out.empty() ? "[" : "\n[";
            out += name;
            out += "]\n";
        }
        out += emitToml(child, name);
    }
    for (const auto& [key, items] : node.lists) {
        const std::string name = prefix.empty() ? key : prefix + "." + key;
        for (const TomlNode& item : items) {
            out += out.empty() ? "[[" : "\n[[";
            out += name;
            out += "]]\n";
            out += emitToml(item, name);
        }
    }
    return out;
}

} // namespace ob
