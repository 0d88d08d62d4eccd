// Per-view results and the cache that keeps an unchanged view free.
#pragma once

#include "mesh_data.hpp"
#include "view_point.hpp"

#include <edgelight/edgelight.h>

#include <memory>
#include <vector>

namespace el {

struct ViewCache {
    std::shared_ptr<const MeshData> mesh;
    bool valid = false;
    ViewPoint view;
    uint32_t what = 0;
    std::vector<uint8_t> facing;
    std::vector<uint8_t> scratch;
    std::vector<uint32_t> silhouettes;
    std::vector<float> contour_points;
    std::vector<uint32_t> contour_triangles;
    std::vector<uint64_t> contour_keys;  // 2 per segment: the triangle side of each end
    el_view_stats stats{};

    // Returns true when the outputs changed.
    bool update(const ViewPoint& view, uint32_t what);
};

// Object-space view point of a camera; throws on a singular or non-finite transform.
ViewPoint object_view_point(const el_camera& camera);

}  // namespace el
