#include "mesh_precheck.hpp"

#include "mesh_limits.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace el_tools {
namespace {

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

// A character cursor over the start of a file, enough to read an OFF header the way assimp's
// OFF reader does (code/AssetLib/OFF/OFFLoader.cpp).
struct Cursor {
    std::FILE* f;
    int c;
    explicit Cursor(std::FILE* file) : f(file), c(std::fgetc(file)) {}
    void next() { c = std::fgetc(f); }
    bool space() const { return c == ' ' || c == '\t'; }
    bool eol() const { return c == '\n' || c == '\r'; }
    void skip_line() {
        while (c != EOF && !eol()) next();
        while (eol()) next();
    }
    // Blanks, line ends and '#' comment lines.
    void next_token() {
        while (space() || eol()) next();
        while (c == '#' || eol()) {
            skip_line();
            while (space() || eol()) next();
        }
    }
    bool accept(char ch) {
        if (c != ch) return false;
        next();
        return true;
    }
    // A decimal count, saturating instead of wrapping (assimp wraps at 2^32); false without digits.
    bool count(uint64_t& v) {
        if (!std::isdigit(c)) return false;
        v = 0;
        for (; std::isdigit(c); next()) v = std::min<uint64_t>(v * 10 + uint64_t(c - '0'), UINT64_MAX / 16);
        return true;
    }
};

// Lines from the cursor on (the rest of the current one included, as assimp may read a vertex
// from it): its OFF reader takes one line per vertex and per face.
uint64_t lines_left(Cursor& cur) {
    uint64_t lines = 1 + (cur.c == '\n');
    std::FILE* f = cur.f;
    char buf[1 << 16];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) lines += uint64_t(std::count(buf, buf + n, '\n'));
    return lines;
}

// OFF's header states its vertex and face counts, and assimp allocates them before reading a
// vertex: "OFF\n353535235358 6 0" would ask for 16 GB. Refuse counts above the caps, or more
// than the file has lines for. `must_be_off`: the extension says OFF, so a header without the
// keyword (which the format allows) is checked as well.
void check_off_header(const std::string& path, bool must_be_off) {
    File file(std::fopen(path.c_str(), "rb"), std::fclose);
    if (!file) return;  // assimp reports why it cannot open it
    Cursor cur(file.get());
    cur.next_token();
    if (cur.accept('S') && !cur.accept('T')) return;
    cur.accept('C');
    cur.accept('N');
    cur.accept('4');
    const bool has_dimension = cur.accept('n');
    const bool keyword = cur.accept('O') && cur.accept('F') && cur.accept('F');
    if (!keyword && !must_be_off) return;
    cur.next_token();
    uint64_t dimension = 3, vertices = 0, faces = 0;
    if (has_dimension) {
        if (!cur.count(dimension)) return;
        cur.next_token();
    }
    if (!cur.count(vertices)) return;  // assimp refuses a header without counts itself
    cur.next_token();
    if (!cur.count(faces)) return;
    const std::string claim = "OFF header claims " + std::to_string(vertices) + " vertices and " +
                              std::to_string(faces) + " faces";
    if (vertices > MeshLimits::max_vertices || faces > MeshLimits::max_triangles)
        throw std::runtime_error(claim + ", more than the limit (" + kMeshLimitsText + ")");
    const uint64_t lines = lines_left(cur);
    if (vertices + faces > lines)
        throw std::runtime_error(claim + " but the file has only " + std::to_string(lines) + " lines after it");
}

// PLY's header declares each element's count and properties, and assimp's PLY reader reserves
// them before reading a value: a 213-byte binary file claiming 200 million vertices took 2.4 GB
// and 37 s before it was refused, its ASCII twin ran for over a minute. Refuse a vertex or face
// count above the caps, and any element count the body cannot hold: binary, an item takes at
// least its scalars' bytes and each list's count; ASCII, at least two bytes (a digit and a
// separator) a property. `must_be_ply`: the extension says PLY.
void check_ply_header(const std::string& path, bool must_be_ply, uint64_t file_size) {
    File file(std::fopen(path.c_str(), "rb"), std::fclose);
    if (!file) return;
    // The header is text up to "end_header"; 64 KiB holds any real one.
    std::string head(1 << 16, '\0');
    head.resize(std::fread(head.data(), 1, head.size(), file.get()));
    if (head.compare(0, 3, "ply") != 0) return;  // not PLY: assimp decides
    const size_t end = head.find("end_header");
    if (end == std::string::npos) {
        if (must_be_ply && head.size() == (1u << 16)) throw std::runtime_error("PLY header longer than 64 KiB");
        return;  // assimp refuses a header without its end
    }
    const size_t body_start = std::min(head.find('\n', end) + 1, head.size());
    const uint64_t body = file_size > body_start ? file_size - body_start : 0;
    struct Element {
        std::string name;
        uint64_t count = 0, min_bytes = 0, properties = 0;
    };
    std::vector<Element> elements;
    bool ascii = false;
    const auto size_of = [](const std::string& type) -> uint64_t {
        if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
        if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
        if (type == "double" || type == "float64") return 8;
        return 4;  // int, uint, float and their sized names; assimp refuses an unknown type
    };
    size_t at = 0;
    while (at < end) {
        const size_t eol = std::min(head.find('\n', at), end);
        std::istringstream line(head.substr(at, eol - at));
        at = eol + 1;
        std::string word;
        line >> word;
        if (word == "format") {
            std::string kind;
            line >> kind;
            ascii = kind == "ascii";
        } else if (word == "element") {
            Element e;
            std::string count;
            line >> e.name >> count;
            if (count.empty() || !std::all_of(count.begin(), count.end(), [](unsigned char ch) { return std::isdigit(ch); }))
                return;  // assimp refuses it
            e.count = count.size() > 18 ? UINT64_MAX / 16 : std::stoull(count);
            elements.push_back(e);
        } else if (word == "property" && !elements.empty()) {
            std::string type;
            line >> type;
            if (type == "list") line >> type;  // the list's count type: the least a list takes
            elements.back().min_bytes += size_of(type);
            elements.back().properties += 1;
        }
    }
    for (const Element& e : elements) {
        const std::string claim = "PLY header claims " + std::to_string(e.count) + " " + e.name + " elements";
        if ((e.name == "vertex" && e.count > MeshLimits::max_vertices) ||
            (e.name == "face" && e.count > MeshLimits::max_triangles))
            throw std::runtime_error(claim + ", more than the limit (" + kMeshLimitsText + ")");
        const uint64_t per_item = ascii ? 2 * std::max<uint64_t>(e.properties, 1) : e.min_bytes;
        if (per_item > 0 && e.count > body / per_item)
            throw std::runtime_error(claim + " of at least " + std::to_string(per_item) + " bytes each, but the file has only " +
                                     std::to_string(body) + " bytes after its header");
    }
}

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
    return ext;
}

}  // namespace

void precheck_mesh_file(const std::string& path, bool assimp_knows_extension) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status)) throw std::runtime_error("no such file");
    // Importers read whole files: a FIFO or /dev/zero would never end.
    if (!std::filesystem::is_regular_file(status)) throw std::runtime_error("not a regular file");
    const uint64_t size = std::filesystem::file_size(path, ec);
    if (ec) throw std::runtime_error("cannot get its size: " + ec.message());
    if (size > MeshLimits::max_file_bytes)
        throw std::runtime_error(std::to_string(size) + " bytes, more than the limit (" + kMeshLimitsText + ")");
    const bool off_extension = lower_extension(path) == ".off";
    if (off_extension || !assimp_knows_extension) check_off_header(path, off_extension);
    const bool ply_extension = lower_extension(path) == ".ply";
    if (ply_extension || !assimp_knows_extension) check_ply_header(path, ply_extension, size);
}

}  // namespace el_tools
