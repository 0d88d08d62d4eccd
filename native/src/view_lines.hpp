// View lines of many instances of one mesh: each instance's silhouettes as chained, tapered line
// segments, on the rounded outline where an outline is given (outline_lines.hpp), instances in
// parallel. What the add-on's line pass draws per instance, in one call per mesh.
#pragma once

#include "mesh_data.hpp"
#include "outline_lines.hpp"

#include <edgelight/edgelight.h>

#include <string>
#include <vector>

namespace el {

struct ViewLines {
    std::vector<OutlineSegments> instances;  // per view
    std::vector<el_status> status;           // per view: EL_OK, or why it has no segments
    std::vector<std::string> message;        // per view: "", or what went wrong
};

// taper: per end, the distance to the chain's nearest free end over the chain's length, or
// EL_NO_TAPER (2 per link).
std::vector<float> taper_values(const std::vector<el_chain_link>& links, const std::vector<el_chain>& chains);

ViewLines view_lines(const MeshData& mesh, const OutlineRecords* outline, const float* edge_faces,
                     const el_outline_view* views, uint32_t view_count, uint32_t flags);

// The camera el_outline_lines sees with (checked: finite, a known projection, a positive size).
OutlineCamera outline_camera(const el_outline_view& v);

}  // namespace el
