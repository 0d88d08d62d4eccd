// What the opaque C handles are. A view holds its mesh's data by shared ownership, so the host
// may destroy handles in any order.
#pragma once

#include "mesh_data.hpp"
#include "outline_lines.hpp"
#include "view_cache.hpp"
#include "view_lines.hpp"

#include <memory>

struct el_mesh {
    std::shared_ptr<el::MeshData> data;
};

struct el_view {
    el::ViewCache cache;
};

struct el_outline {
    el::OutlineRecords records;
};

struct el_view_lines {
    el::ViewLines lines;
    bool has_faces = false;
};
