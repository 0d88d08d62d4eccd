// C entry points for chains of mesh edges and of contour segments.
#include "capi_common.hpp"
#include "chains.hpp"
#include "handles.hpp"

#include <algorithm>
#include <string>

using el::guarded;
using el::require;
using el::require_capacity;

namespace {

void copy_out(const el::Chains& c, el_chain_link* out_links, el_chain* out_chains, uint32_t capacity_chains,
              uint32_t* out_chain_count) {
    *out_chain_count = uint32_t(c.chains.size());
    require_capacity(capacity_chains, c.chains.size(), "capacity_chains");
    std::copy(c.links.begin(), c.links.end(), out_links);
    std::copy(c.chains.begin(), c.chains.end(), out_chains);
}

}  // namespace

extern "C" {

EL_API el_status el_mesh_chain_edges(const el_mesh* mesh, const uint32_t* edges, uint32_t edge_count,
                                     el_chain_link* out_links, el_chain* out_chains, uint32_t capacity_chains,
                                     uint32_t* out_chain_count) {
    if (out_chain_count) *out_chain_count = 0;
    return guarded("el_mesh_chain_edges", [&] {
        require(mesh, "mesh");
        require(out_chain_count, "out_chain_count");
        if (edge_count == 0) return;
        require(edges, "edges");
        require(out_links, "out_links");
        require(out_chains, "out_chains");
        const el::MeshData& m = *mesh->data;
        const uint32_t n = m.edge_count();
        std::vector<uint8_t> seen(n, 0);
        std::vector<el::ChainItem> items(edge_count);
        for (uint32_t i = 0; i < edge_count; ++i) {
            const uint32_t e = edges[i];
            if (e >= n)
                el::fail(EL_ERR_INDEX_OUT_OF_RANGE, "edges[" + std::to_string(i) + "] = " + std::to_string(e) +
                                                        " is not below the edge count " + std::to_string(n));
            if (seen[e]) el::fail(EL_ERR_INVALID_ARGUMENT, "edge " + std::to_string(e) + " is listed twice");
            seen[e] = 1;
            const uint32_t a = m.topo.edge_vertices[2 * size_t(e)], b = m.topo.edge_vertices[2 * size_t(e) + 1];
            items[i] = el::ChainItem{{a, b}, {m.positions[a], m.positions[b]}};
        }
        copy_out(el::build_chains(items), out_links, out_chains, capacity_chains, out_chain_count);
    });
}

EL_API el_status el_view_chain_contours(const el_view* view, el_chain_link* out_links, uint32_t capacity_links,
                                        el_chain* out_chains, uint32_t capacity_chains, uint32_t* out_chain_count) {
    if (out_chain_count) *out_chain_count = 0;
    return guarded("el_view_chain_contours", [&] {
        require(view, "view");
        require(out_chain_count, "out_chain_count");
        const el::ViewCache& c = view->cache;
        const size_t n = c.contour_triangles.size();
        if (n == 0) return;
        require(out_links, "out_links");
        require(out_chains, "out_chains");
        require_capacity(capacity_links, n, "capacity_links");
        std::vector<el::ChainItem> items(n);
        for (size_t i = 0; i < n; ++i) {
            const float* p = &c.contour_points[6 * i];
            items[i] = el::ChainItem{{c.contour_keys[2 * i], c.contour_keys[2 * i + 1]},
                                     {glm::vec3(p[0], p[1], p[2]), glm::vec3(p[3], p[4], p[5])}};
        }
        copy_out(el::build_chains(items), out_links, out_chains, capacity_chains, out_chain_count);
    });
}

EL_API el_status el_line_nodes(const float* p0, const float* p1, const float* taper, const el_chain_link* links,
                               uint32_t count, uint32_t flags, float* out_nodes, uint32_t capacity_nodes,
                               uint32_t* out_order) {
    return guarded("el_line_nodes", [&] {
        if (count == 0) return;
        require(p0, "p0");
        require(p1, "p1");
        require(taper, "taper");
        require(out_nodes, "out_nodes");
        require(out_order, "out_order");
        if (count >= (1u << 24))
            el::fail(EL_ERR_INVALID_COUNT, "count " + std::to_string(count) + " is not below 2^24");
        if (flags & ~EL_LINE_NODES_CHAIN_SPHERES)
            el::fail(EL_ERR_INVALID_ARGUMENT, "unknown flags " + std::to_string(flags));
        require_capacity(capacity_nodes, count, "capacity_nodes");
        for (uint32_t i = 0; i < count; ++i) {
            el::require_finite3(p0 + 3 * size_t(i), "p0");
            el::require_finite3(p1 + 3 * size_t(i), "p1");
        }
        const el::LineNodes r =
            el::build_line_nodes(p0, p1, taper, links, count, (flags & EL_LINE_NODES_CHAIN_SPHERES) != 0);
        std::copy(r.nodes.begin(), r.nodes.end(), out_nodes);
        std::copy(r.order.begin(), r.order.end(), out_order);
    });
}

}  // extern "C"
