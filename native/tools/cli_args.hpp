// Command-line pieces both tools (edgelight-info, edgelight-render) parse the same way; each
// refusal is a std::invalid_argument that says what was wrong.
#pragma once

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace el_tools {

// The whole argument must be a finite number.
inline double cli_number(const char* s) {
    char* end = nullptr;
    const double v = std::strtod(s, &end);
    if (end == s || *end != '\0' || !std::isfinite(v)) throw std::invalid_argument(std::string("not a number: ") + s);
    return v;
}

// An argument no option took: the one mesh path, or an error for an unknown option or a second
// path.
inline void cli_mesh_path(const std::string& arg, std::string& mesh) {
    if (!arg.empty() && arg[0] == '-') throw std::invalid_argument("unknown option " + arg);
    if (!mesh.empty()) throw std::invalid_argument("more than one mesh given");
    mesh = arg;
}

}  // namespace el_tools
