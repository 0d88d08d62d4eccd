#include "off_mesh.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace el_tools {
namespace {

// The file's words, '#' comments dropped.
std::istringstream words_of(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw std::runtime_error("cannot read '" + path + "': cannot open it");
    std::ostringstream text;
    for (std::string line; std::getline(f, line);) text << line.substr(0, line.find('#')) << '\n';
    return std::istringstream(text.str());
}

}  // namespace

LoadedMesh read_off(const std::string& path) {
    const auto fail = [&](const std::string& why) { return std::runtime_error("cannot read '" + path + "': " + why); };
    std::istringstream in = words_of(path);
    std::string keyword;
    in >> keyword;
    uint64_t nv = 0, nf = 0, ne = 0;
    if (keyword == "OFF") {
        in >> nv >> nf >> ne;
    } else if (keyword.size() > 3 && keyword.compare(0, 3, "OFF") == 0 && std::isdigit((unsigned char)keyword[3])) {
        // "OFF8 2 1 0": counts run on from the keyword (as some exporters write it)
        nv = std::stoull(keyword.substr(3));
        in >> nf >> ne;
    } else {
        throw fail("not an OFF file (no OFF keyword)");
    }
    if (!in || nv == 0 || nv > (1u << 28) || nf > (1u << 28)) throw fail("bad OFF header counts");
    // Equal positions become one vertex (mesh_io.cpp welds what assimp reads the same way).
    std::map<std::tuple<float, float, float>, uint32_t> index_of;
    std::vector<uint32_t> vertex(nv);
    LoadedMesh m;
    for (uint64_t i = 0; i < nv; ++i) {
        double x, y, z;
        if (!(in >> x >> y >> z)) throw fail("fewer vertices than the header's " + std::to_string(nv));
        if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) throw fail("a position is not finite");
        const auto key = std::make_tuple(float(x), float(y), float(z));
        const auto [it, added] = index_of.emplace(key, uint32_t(m.positions.size() / 3));
        if (added) m.positions.insert(m.positions.end(), {float(x), float(y), float(z)});
        vertex[i] = it->second;
        std::string rest;  // colours or normals after the position: the line's remainder
        std::getline(in, rest);
    }
    for (uint64_t f = 0; f < nf; ++f) {
        uint64_t k;
        if (!(in >> k) || k < 3 || k > 4096) throw fail("face " + std::to_string(f) + " has no usable corner count");
        std::vector<uint32_t> corner(k);
        for (auto& c : corner) {
            uint64_t v;
            if (!(in >> v)) throw fail("face " + std::to_string(f) + " ends early");
            if (v >= nv) throw fail("face " + std::to_string(f) + " uses vertex " + std::to_string(v) + " of " + std::to_string(nv));
            c = vertex[v];
        }
        std::string rest;  // a face colour
        std::getline(in, rest);
        for (uint64_t j = 1; j + 1 < k; ++j) m.triangles.insert(m.triangles.end(), {corner[0], corner[j], corner[j + 1]});
    }
    return m;
}

}  // namespace el_tools
