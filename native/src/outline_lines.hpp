// Silhouette lines on the rounded outline (docs/lines.md, "Silhouettes of rounded edges"): per
// view, the silhouettes along convex rounded edges move onto their fillets' outline, their
// corners join (round a corner patch's ball by an arc of its circle), and an unmoved silhouette
// they run on into ends at the fillet's foot. The ink's side of what the surface pass draws
// (shaders/rounded_outline.glsl).
#pragma once

#include <edgelight/edgelight.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace el {

// A mesh's convex rounded edges and corner patches (el_outline_desc), indexed by vertex.
struct OutlineRecords {
    std::vector<float> edges;             // EL_OUTLINE_EDGE_TEXELS vec4s per edge
    std::vector<float> corners;           // EL_OUTLINE_CORNER_TEXELS vec4s per corner
    std::vector<uint64_t> edge_keys;      // sorted unordered vertex pairs
    std::vector<uint32_t> edge_at_key;    // the record of each key
    std::vector<uint32_t> corner_keys;    // sorted corner vertices
    std::vector<uint32_t> corner_at_key;  // the record of each
};

OutlineRecords make_outline_records(const el_outline_desc& desc);

// Row-major 4x4, column vectors (el_camera's layout), in double.
struct Mat4 {
    double m[16];
};

struct OutlineCamera {
    bool orthographic = false;
    glm::dvec3 eye{0.0}, view_dir{0.0, 0.0, -1.0};
    Mat4 object_to_world{}, world_to_view{}, view_to_clip{};
    double width = 1.0, height = 1.0;
};

// Segments of one line type, object space (el_outline_segments' arrays, owned).
struct OutlineSegments {
    std::vector<float> p0, p1, n1, n2;  // 3 per segment
    std::vector<float> taper;           // 2 per segment
    std::vector<float> faces;           // 2 per segment, or empty
    std::vector<el_chain_link> links;   // 1 per segment, or empty
    bool has_faces = false, has_links = false;

    size_t size() const { return taper.size() / 2; }
};

struct FilletOutline {
    glm::dvec3 p;  // unit, axis -> outline point, turned towards the sharp edge; 0: no silhouette
    glm::dvec3 c;  // axis -> the sharp edge, over the radius
    bool silhouette;
};

// rounded_outline.glsl's el_fillet_outline, in double.
FilletOutline fillet_outline(const glm::dvec3& na, const glm::dvec3& nb, const glm::dvec3& v);

// `seg` (vertices: 2 per segment) on the rounded outline as `camera` sees it.
OutlineSegments outline_lines(const OutlineRecords& records, const OutlineCamera& camera, const uint32_t* vertices,
                              OutlineSegments seg);

}  // namespace el
