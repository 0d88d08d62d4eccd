// Checks a mesh file before any importer reads it, against what importers would do with it
// unchecked: read a device or a huge file whole, or size arrays from a header's counts before
// seeing whether the file holds them. Each refusal is a std::runtime_error giving the reason.
#pragma once

#include <string>

namespace el_tools {

// `assimp_knows_extension`: whether assimp picks an importer by the file's extension; if not it
// guesses from the contents, so an OFF header is checked wherever it appears.
void precheck_mesh_file(const std::string& path, bool assimp_knows_extension);

}  // namespace el_tools
