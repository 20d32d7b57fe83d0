// Writing a Def back to TOML through its describe() schema: the keys whose values differ
// from the Def's defaults, sections as [a.b], lists as [[a]]; what the loader reads back
// gives the same Def.
#pragma once
#include "core/schema.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace ob {

/// A Def as text: its keys (TOML values, formatted), its sections, its lists. Sections and
/// lists are named structs, not pairs: a pair may not hold the incomplete TomlNode (clang
/// with libstdc++ rejects it).
struct TomlNode {
    struct Section;
    struct List;
    std::vector<std::pair<std::string, std::string>> keys;
    std::vector<Section> sections;
    std::vector<List> lists;
};
struct TomlNode::Section {
    std::string name;
    TomlNode node;
};
struct TomlNode::List {
    std::string name;
    std::vector<TomlNode> items;
};

/// TOML value text of each field kind (floats in their shortest round-trip form).
std::string tomlValue(bool v);
std::string tomlValue(int v);
std::string tomlValue(uint64_t v);
std::string tomlValue(float v);
std::string tomlValue(const glm::vec2& v);
std::string tomlValue(const glm::vec3& v);
std::string tomlValue(const std::string& v);
std::string tomlValue(const std::vector<glm::vec2>& v);

/// Drops from `node` every key equal to `defaults`' (sections recursively, by name).
void pruneDefaults(TomlNode& node, const TomlNode& defaults);
/// The TOML document of a node (`prefix` names the table it is, "" at the root).
std::string emitToml(const TomlNode& node, const std::string& prefix = "");

/// The visitor that collects a Def into a TomlNode; list items are pruned against a
/// default-constructed item as they are collected.
class TomlCollector {
public:
    explicit TomlCollector(TomlNode& node) : m_node(node) {}
    void field(const char* key, bool& v, const char*, Change = {}) { add(key, tomlValue(v)); }
    void field(const char* key, int& v, Limits, const char*, Change = {}) { add(key, tomlValue(v)); }
    void field(const char* key, uint64_t& v, const char*, Change = {}) { add(key, tomlValue(v)); }
    void field(const char* key, float& v, Limits, const char*, Change = {}) { add(key, tomlValue(v)); }
    void field(const char* key, glm::vec2& v, Limits, const char*, Change = {}) { add(key, tomlValue(v)); }
    void field(const char* key, glm::vec3& v, Limits, const char*, Change = {}) { add(key, tomlValue(v)); }
    void field(const char* key, std::string& v, const char*, Change = {}) { add(key, tomlValue(v)); }
    template <NamedEnum E> void field(const char* key, E& v, const char*, Change = {}) { add(key, tomlValue(std::string(enumName(v)))); }
    void field(const char* key, std::vector<glm::vec2>& v, Limits, const char*, Change = {}) { add(key, tomlValue(v)); }
    template <NamedEnum E> void field(const char* key, std::vector<E>& v, const char*, Change = {}) {
        std::string text = "[";
        for (size_t i = 0; i < v.size(); ++i) text += (i ? ", " : "") + tomlValue(std::string(enumName(v[i])));
        add(key, text + "]");
    }
    /// Another Def's keys in this table, those that differ from its own defaults (its
    /// sections and lists too: [[game.gates]] of a race's settings).
    template <class Def> void fields(Def& def) {
        TomlNode mine, defaults;
        TomlCollector c(mine), d(defaults);
        describe(c, def);
        Def fresh{};
        describe(d, fresh);
        pruneDefaults(mine, defaults);
        m_node.keys.insert(m_node.keys.end(), mine.keys.begin(), mine.keys.end());
        for (auto& s : mine.sections) m_node.sections.push_back(std::move(s));
        for (auto& l : mine.lists) m_node.lists.push_back(std::move(l));
    }
    template <class Def> void section(const char* key, Def& def) {
        TomlNode child;
        TomlCollector c(child);
        describe(c, def);
        m_node.sections.push_back({key, std::move(child)});
    }
    template <class Item> void list(const char* key, std::vector<Item>& items, const char*) {
        Item fresh{};
        TomlNode defaults;
        TomlCollector d(defaults);
        describe(d, fresh);
        std::vector<TomlNode> nodes;
        for (Item& item : items) {
            TomlNode n;
            TomlCollector c(n);
            describe(c, item);
            pruneDefaults(n, defaults);
            nodes.push_back(std::move(n));
        }
        m_node.lists.push_back({key, std::move(nodes)});
    }

private:
    void add(const char* key, std::string text) { m_node.keys.emplace_back(key, std::move(text)); }
    TomlNode& m_node;
};

/// `def` as a TOML document of the keys that differ from `Def{}`.
template <class Def> std::string writeToml(Def& def) {
    TomlNode node, defaults;
    TomlCollector c(node);
    describe(c, def);
    Def fresh{};
    TomlCollector d(defaults);
    describe(d, fresh);
    pruneDefaults(node, defaults);
    return emitToml(node);
}

} // namespace ob
