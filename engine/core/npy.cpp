// NumPy .npy read/write for float32 arrays (numpy.lib.format, versions 1.0 and 2.0).
#include "core/npy.h"

#include "core/error.h"
#include "core/file_read.h"
#include "core/file_write.h"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>

static_assert(std::endian::native == std::endian::little, "npy I/O assumes a little-endian host");

namespace ob {

namespace {

constexpr char MAGIC[6] = {'\x93', 'N', 'U', 'M', 'P', 'Y'};
constexpr size_t HEADER_ALIGN = 64;  // numpy pads magic + length + dict to this multiple

// The parts of the header dict we need. The dict is a Python literal such as
// "{'descr': '<f4', 'fortran_order': False, 'shape': (3, 4), }".
struct Header {
    std::string descr;
    bool fortranOrder = false;
    std::vector<size_t> shape;
    bool hasDescr = false, hasOrder = false, hasShape = false;
};

// Minimal parser for the header dict: string keys; values are strings, True/False or
// tuples of non-negative integers. Returns an empty string on success, else the problem.
class HeaderParser {
public:
    explicit HeaderParser(const std::string& text) : m_s(text) {}

    std::string parse(Header& h) {
        skipSpace();
        if (!eat('{')) return "header is not a Python dict";
        for (;;) {
            skipSpace();
            if (eat('}')) return {};
            std::string key;
            if (!readString(key)) return "header dict key is not a quoted string";
            skipSpace();
            if (!eat(':')) return "header dict has no ':' after '" + key + "'";
            skipSpace();
            if (key == "descr") {
                if (!readString(h.descr)) return "header 'descr' is not a string";
                h.hasDescr = true;
            } else if (key == "fortran_order") {
                if (m_s.compare(m_pos, 4, "True") == 0) { h.fortranOrder = true; m_pos += 4; }
                else if (m_s.compare(m_pos, 5, "False") == 0) { h.fortranOrder = false; m_pos += 5; }
                else return "header 'fortran_order' is not True or False";
                h.hasOrder = true;
            } else if (key == "shape") {
                if (!readShape(h.shape)) return "header 'shape' is not a tuple of integers";
                h.hasShape = true;
            } else {
                return "header has unknown key '" + key + "'";
            }
            skipSpace();
            if (eat(',')) continue;
            skipSpace();
            if (eat('}')) return {};
            return "header dict is malformed after '" + key + "'";
        }
    }

private:
    void skipSpace() {
        while (m_pos < m_s.size() && (m_s[m_pos] == ' ' || m_s[m_pos] == '\t' || m_s[m_pos] == '\n')) ++m_pos;
    }
    bool eat(char c) {
        if (m_pos < m_s.size() && m_s[m_pos] == c) { ++m_pos; return true; }
        return false;
    }
    bool readString(std::string& out) {
        if (m_pos >= m_s.size() || (m_s[m_pos] != '\'' && m_s[m_pos] != '"')) return false;
        char quote = m_s[m_pos++];
        size_t end = m_s.find(quote, m_pos);
        if (end == std::string::npos) return false;
        out = m_s.substr(m_pos, end - m_pos);
        m_pos = end + 1;
        return true;
    }
    bool readShape(std::vector<size_t>& shape) {
        if (!eat('(')) return false;
        for (;;) {
            skipSpace();
            if (eat(')')) return true;
            if (m_pos >= m_s.size() || m_s[m_pos] < '0' || m_s[m_pos] > '9') return false;
            size_t v = 0;
            while (m_pos < m_s.size() && m_s[m_pos] >= '0' && m_s[m_pos] <= '9') {
                if (v > (std::numeric_limits<size_t>::max() - 9) / 10) return false;
                v = v * 10 + size_t(m_s[m_pos++] - '0');
            }
            shape.push_back(v);
            skipSpace();
            if (eat(',')) continue;
            skipSpace();
            return eat(')');
        }
    }

    const std::string& m_s;
    size_t m_pos = 0;
};

std::string shapeText(const std::vector<size_t>& shape) {
    std::string s = "(";
    for (size_t i = 0; i < shape.size(); ++i) {
        if (i) s += ", ";
        s += std::to_string(shape[i]);
    }
    if (shape.size() == 1) s += ",";
    return s + ")";
}

[[noreturn]] void bad(const std::string& path, const std::string& what) {
    throw InputError(path + ": " + what);
}

} // namespace

NpyArray readNpy(const std::string& path) {
    // A regular file only (a named pipe would block, a device read forever), read whole.
    return parseNpy(readRegularFile(path), path);
}

NpyArray parseNpy(const std::string& file, const std::string& path) {
    const uint64_t fileSize = file.size();
    const auto* bytes = reinterpret_cast<const unsigned char*>(file.data());

    if (fileSize < 8 || std::memcmp(bytes, MAGIC, 6) != 0) bad(path, "not a .npy file (bad magic; expected \\x93NUMPY)");
    const int major = bytes[6], minor = bytes[7];
    uint64_t headerLen = 0;
    size_t lenBytes = 0;
    if (major == 1 && minor == 0) {
        if (fileSize < 10) bad(path, "truncated .npy header");
        headerLen = uint64_t(bytes[8]) | uint64_t(bytes[9]) << 8;
        lenBytes = 2;
    } else if (major == 2 && minor == 0) {
        if (fileSize < 12) bad(path, "truncated .npy header");
        headerLen = uint64_t(bytes[8]) | uint64_t(bytes[9]) << 8 | uint64_t(bytes[10]) << 16 | uint64_t(bytes[11]) << 24;
        lenBytes = 4;
    } else {
        bad(path, "unsupported .npy version " + std::to_string(major) + "." + std::to_string(minor) +
                      " (supported: 1.0, 2.0)");
    }
    const uint64_t dataOffset = 8 + lenBytes + headerLen;
    if (dataOffset > fileSize) bad(path, "truncated .npy header");
    const std::string header = file.substr(8 + lenBytes, size_t(headerLen));

    Header h;
    if (std::string problem = HeaderParser(header).parse(h); !problem.empty()) bad(path, problem);
    if (!h.hasDescr || !h.hasOrder || !h.hasShape)
        bad(path, "header lacks one of 'descr', 'fortran_order', 'shape'");
    if (h.descr != "<f4")
        bad(path, "dtype '" + h.descr + "' is not supported (need little-endian float32 '<f4')");
    if (h.fortranOrder) bad(path, "fortran_order is True (need C order)");

    size_t count = 1;
    for (size_t d : h.shape) {
        if (d != 0 && count > std::numeric_limits<size_t>::max() / 4 / d) bad(path, "shape " + shapeText(h.shape) + " is too large");
        count *= d;
    }
    const uint64_t need = uint64_t(count) * sizeof(float);
    if (fileSize - dataOffset < need)
        bad(path, "truncated data: shape " + shapeText(h.shape) + " needs " + std::to_string(need) +
                      " bytes, file has " + std::to_string(fileSize - dataOffset));

    NpyArray arr;
    arr.shape = std::move(h.shape);
    arr.data.resize(count);
    if (count) std::memcpy(arr.data.data(), bytes + dataOffset, size_t(need));
    return arr;
}

void writeNpy(const std::string& path, const std::vector<size_t>& shape, const float* data) {
    size_t count = 1;
    for (size_t d : shape) count *= d;

    std::string header = "{'descr': '<f4', 'fortran_order': False, 'shape': " + shapeText(shape) + ", }";
    // magic(6) + version(2) + length(2) + header + padding + '\n' is a multiple of 64.
    const size_t unpadded = 10 + header.size() + 1;
    header.append((HEADER_ALIGN - unpadded % HEADER_ALIGN) % HEADER_ALIGN, ' ');
    header += '\n';
    if (header.size() > 0xFFFF) throw RuntimeError(path + ": shape too long for a version 1.0 .npy header");

    writeFileWhole(path, "output", [&](std::ostream& out) {
        const unsigned char pre[10] = {0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0,
                                       static_cast<unsigned char>(header.size() & 0xFF),
                                       static_cast<unsigned char>(header.size() >> 8)};
        out.write(reinterpret_cast<const char*>(pre), sizeof pre);
        out.write(header.data(), std::streamsize(header.size()));
        if (count) out.write(reinterpret_cast<const char*>(data), std::streamsize(count * sizeof(float)));
    });
}

} // namespace ob
