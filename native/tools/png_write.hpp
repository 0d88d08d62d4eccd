// Scene-linear float RGBA -> 8-bit sRGB PNG, as Blender's 'Standard' view transform saves it.
#pragma once

#include <string>
#include <vector>

namespace el_tools {

// rgba: width x height x 4 floats, rows bottom-up (GL order); alpha is kept as coverage.
// Throws std::runtime_error if the file cannot be written.
void write_png(const std::string& path, const std::vector<float>& rgba, int width, int height);

}  // namespace el_tools
