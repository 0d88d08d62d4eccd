// A command-line number for the tools (edgelight-info, edgelight-render): the whole argument must
// be a finite number, or std::invalid_argument says which argument was not.
#pragma once

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace el_tools {

inline double cli_number(const char* s) {
    char* end = nullptr;
    const double v = std::strtod(s, &end);
    if (end == s || *end != '\0' || !std::isfinite(v)) throw std::invalid_argument(std::string("not a number: ") + s);
    return v;
}

}  // namespace el_tools
