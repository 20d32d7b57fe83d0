// Scene loading: reads a TOML table into Def structs through their describe() schema,
// collecting every error (file:line:column: key.path: message), rejecting unknown keys.
#pragma once
#include "core/schema.h"

#include <memory>
#include <string>
#include <vector>

namespace ob {

/// A `--set` key path's longest length and most segments (no scene key comes near either).
constexpr size_t MAX_KEY_PATH_CHARS = 256;
constexpr size_t MAX_KEY_PATH_SEGMENTS = 16;

/// One parsed TOML document (opaque here: toml++ stays inside toml_reader.cpp).
class TomlDocument {
public:
    /// Parses a file. Syntax errors and a missing file are appended to `errors`.
    static TomlDocument fromFile(const std::string& path, std::vector<std::string>& errors);
    /// Parses text; `sourceName` is what error messages call it.
    static TomlDocument fromString(const std::string& text, const std::string& sourceName, std::vector<std::string>& errors);
    /// Applies one `--set key.path=value` override (value in TOML syntax; a bare word is a
    /// string). A key path longer than MAX_KEY_PATH_CHARS or MAX_KEY_PATH_SEGMENTS is an error.
    void applyOverride(const std::string& assignment, std::vector<std::string>& errors);
    /// Where the value at `keyPath` ("objects[0].model") was written: "file:line:column" (or
    /// the --set assignment); `fallback` if the document has no such key.
    std::string where(const std::string& keyPath, const std::string& fallback) const;
    TomlDocument();
    ~TomlDocument();
    TomlDocument(TomlDocument&&) noexcept;
    TomlDocument& operator=(TomlDocument&&) noexcept;

    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

/// The loader visitor: `TomlReader r(doc, errors); describe(r, def); r.finish();`
class TomlReader {
public:
    TomlReader(const TomlDocument& doc, std::vector<std::string>& errors);
    ~TomlReader();

    void field(const char* key, bool& value, const char* doc, Change = {});
    void field(const char* key, int& value, Limits limits, const char* doc, Change = {});
    void field(const char* key, uint64_t& value, const char* doc, Change = {});
    void field(const char* key, float& value, Limits limits, const char* doc, Change = {});
    void field(const char* key, glm::vec2& value, Limits limits, const char* doc, Change = {});
    void field(const char* key, glm::vec3& value, Limits limits, const char* doc, Change = {});
    void field(const char* key, std::string& value, const char* doc, Change = {});
    template <NamedEnum E> void field(const char* key, E& value, const char* /*doc*/, Change = {}) {
        std::size_t index = std::size_t(value);
        choice(key, enumNames<E>, index);
        value = E(index);
    }
    /// One of `words` (an enum's), read as its index.
    void choice(const char* key, Words words, std::size_t& index);
    /// A list of an enum's words (`["a", "b"]`), each once.
    template <NamedEnum E> void field(const char* key, std::vector<E>& values, const char* /*doc*/, Change = {}) {
        std::vector<std::size_t> indices;
        if (!choices(key, enumNames<E>, indices)) return;
        values.clear();
        for (std::size_t i : indices) values.push_back(E(i));
    }
    /// A list of `words`, read as their indices; false when the key is absent or wrong.
    bool choices(const char* key, Words words, std::vector<std::size_t>& indices);
    /// A key the Def does not read in its present state (another object type's): set in the
    /// file, it is the error `why`.
    void refuse(const char* key, const std::string& why);
    /// A list of 2D points, `[[x, z], ...]` (may be empty).
    void field(const char* key, std::vector<glm::vec2>& points, Limits limits, const char* doc, Change = {});

    /// Reads another Def's keys from this table.
    template <class Def> void fields(Def& def) { describe(*this, def); }

    /// Reads sub-table `key` (absent: defaults stay) into `def` by its describe().
    template <class Def>
    void section(const char* key, Def& def) {
        if (!enterSection(key)) return;
        describe(*this, def);
        leaveSection();
    }

    /// Reads an array of tables (`[[key]]` or `key = [{...}, ...]`) into `items`, each
    /// element by its describe(); absent: `items` keeps its defaults.
    template <class Item>
    void list(const char* key, std::vector<Item>& items, const char* /*doc*/) {
        int count = 0;
        const void* array = enterList(key, count);
        if (!array) return;
        items.assign(size_t(count), Item{});
        for (int i = 0; i < count; ++i) {
            if (!enterListItem(array, key, i)) continue;
            describe(*this, items[size_t(i)]);
            leaveSection();
        }
    }

    /// Reports every key of the document that no describe() asked for.
    void finish();

    struct State; ///< reader state (toml++ types), defined in toml_reader.cpp

private:
    bool enterSection(const char* key);
    const void* enterList(const char* key, int& count);  // the toml::array, or null
    bool enterListItem(const void* array, const char* key, int index);
    void leaveSection();
    std::unique_ptr<State> m_state;
};

} // namespace ob
