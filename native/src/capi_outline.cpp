// C entry points for silhouettes on the rounded outline (outline_lines.hpp).
#include "capi_common.hpp"
#include "handles.hpp"
#include "outline_fans.hpp"
#include "outline_lines.hpp"
#include "view_lines.hpp"

#include <algorithm>
#include <memory>
#include <string>

using el::guarded;
using el::require;
using el::require_capacity;
using el::require_finite_array;

namespace {

}  // namespace

extern "C" {

EL_API el_status el_outline_create(const el_outline_desc* desc, el_outline** out_outline) {
    if (out_outline) *out_outline = nullptr;
    return guarded("el_outline_create", [&] {
        require(desc, "desc");
        require(out_outline, "out_outline");
        if (desc->edge_count) {
            require(desc->edges, "desc->edges");
            require(desc->edge_vertices, "desc->edge_vertices");
            require_finite_array(desc->edges, size_t(desc->edge_count) * 4 * EL_OUTLINE_EDGE_TEXELS, "desc->edges");
        }
        if (desc->corner_count) {
            require(desc->corners, "desc->corners");
            require(desc->corner_vertices, "desc->corner_vertices");
            require_finite_array(desc->corners, size_t(desc->corner_count) * 4 * EL_OUTLINE_CORNER_TEXELS, "desc->corners");
        }
        auto o = std::make_unique<el_outline>();
        o->records = el::make_outline_records(*desc);
        *out_outline = o.release();
    });
}

EL_API void el_outline_destroy(el_outline* outline) { delete outline; }

EL_API el_status el_outline_lines(const el_outline* outline, const el_outline_view* view, const el_outline_segments* in,
                                  el_outline_out* out, uint32_t* out_count) {
    if (out_count) *out_count = 0;
    return guarded("el_outline_lines", [&] {
        require(outline, "outline");
        require(view, "view");
        require(in, "in");
        require(out, "out");
        require(out_count, "out_count");
        const el::OutlineCamera camera = el::outline_camera(*view);
        const size_t n = in->count;
        el::OutlineSegments seg;
        seg.has_faces = in->faces != nullptr;
        seg.has_links = in->links != nullptr;
        if (n) {
            require(in->vertices, "in->vertices");
            require(in->p0, "in->p0");
            require(in->p1, "in->p1");
            require(in->n1, "in->n1");
            require(in->n2, "in->n2");
            require(in->taper, "in->taper");
            require_finite_array(in->p0, 3 * n, "in->p0");
            require_finite_array(in->p1, 3 * n, "in->p1");
            require_finite_array(in->n1, 3 * n, "in->n1");
            require_finite_array(in->n2, 3 * n, "in->n2");
            seg.p0.assign(in->p0, in->p0 + 3 * n);
            seg.p1.assign(in->p1, in->p1 + 3 * n);
            seg.n1.assign(in->n1, in->n1 + 3 * n);
            seg.n2.assign(in->n2, in->n2 + 3 * n);
            seg.taper.assign(in->taper, in->taper + 2 * n);
            if (seg.has_faces) seg.faces.assign(in->faces, in->faces + 2 * n);
            if (seg.has_links) seg.links.assign(in->links, in->links + n);
        }
        const el::OutlineSegments res = n ? el::outline_lines(outline->records, camera, in->vertices, std::move(seg)) : seg;
        const size_t m = res.size();
        *out_count = uint32_t(m);
        require_capacity(out->capacity, m, "out->capacity");
        if (m == 0) return;
        for (auto [p, name] : {std::pair{out->p0, "out->p0"}, {out->p1, "out->p1"}, {out->n1, "out->n1"}, {out->n2, "out->n2"}, {out->taper, "out->taper"}})
            require(p, name);
        if (res.has_faces) require(out->faces, "out->faces");
        if (res.has_links) require(out->links, "out->links");
        std::copy(res.p0.begin(), res.p0.end(), out->p0);
        std::copy(res.p1.begin(), res.p1.end(), out->p1);
        std::copy(res.n1.begin(), res.n1.end(), out->n1);
        std::copy(res.n2.begin(), res.n2.end(), out->n2);
        std::copy(res.taper.begin(), res.taper.end(), out->taper);
        if (res.has_faces) std::copy(res.faces.begin(), res.faces.end(), out->faces);
        if (res.has_links) std::copy(res.links.begin(), res.links.end(), out->links);
    });
}

EL_API el_status el_outline_fans(const uint32_t* tri_verts, const float* tri_normals, uint32_t triangle_count,
                                 const int32_t* item_verts, uint32_t verts_per_item, const float* item_normals,
                                 uint32_t normals_per_item, uint32_t item_count, uint32_t flags, float cos_max,
                                 uint32_t per, float* out) {
    return guarded("el_outline_fans", [&] {
        if (flags & ~uint32_t(EL_OUTLINE_FANS_OWN_SIDES))
            el::fail(EL_ERR_INVALID_ARGUMENT, "flags has unknown bits " + std::to_string(flags));
        const bool own = (flags & EL_OUTLINE_FANS_OWN_SIDES) != 0;
        if (verts_per_item < 1 || verts_per_item > 4 || (own && verts_per_item != 2))
            el::fail(EL_ERR_INVALID_ARGUMENT, "verts_per_item " + std::to_string(verts_per_item) +
                                                  " (1 to 4; 2 with EL_OUTLINE_FANS_OWN_SIDES)");
        if (normals_per_item < 1 || normals_per_item > 4)
            el::fail(EL_ERR_INVALID_ARGUMENT, "normals_per_item " + std::to_string(normals_per_item) + " (1 to 4)");
        el::require_finite(cos_max, "cos_max");
        if (triangle_count == 0 || per == 0) return;
        require(tri_verts, "tri_verts");
        require(tri_normals, "tri_normals");
        require(out, "out");
        if (item_count) {
            require(item_verts, "item_verts");
            require(item_normals, "item_normals");
        }
        require_finite_array(tri_normals, 3 * size_t(triangle_count), "tri_normals");
        require_finite_array(item_normals, 3 * size_t(item_count) * normals_per_item, "item_normals");
        for (size_t k = 0; k < size_t(item_count) * verts_per_item; ++k)
            if (item_verts[k] < -1)
                el::fail(EL_ERR_INVALID_ARGUMENT, "item_verts[" + std::to_string(k) + "] = " +
                                                      std::to_string(item_verts[k]) + " (a vertex, or -1)");
        el::outline_fans(tri_verts, tri_normals, triangle_count,
                         el::FanItems{item_verts, verts_per_item, item_normals, normals_per_item, item_count, own},
                         cos_max, per, out);
    });
}

EL_API el_status el_fillet_outline(const float* na, const float* nb, const float* v, uint32_t count, float* out_p,
                                   float* out_c, uint8_t* out_silhouette) {
    return guarded("el_fillet_outline", [&] {
        if (count == 0) return;
        for (auto [p, name] : {std::pair{na, "na"}, {nb, "nb"}, {v, "v"}}) require(p, name);
        require(out_p, "out_p");
        require(out_c, "out_c");
        require(out_silhouette, "out_silhouette");
        for (uint32_t i = 0; i < count; ++i) {
            const size_t k = 3 * size_t(i);
            const auto f = el::fillet_outline(glm::dvec3(na[k], na[k + 1], na[k + 2]), glm::dvec3(nb[k], nb[k + 1], nb[k + 2]),
                                              glm::dvec3(v[k], v[k + 1], v[k + 2]));
            for (int j = 0; j < 3; ++j) {
                out_p[k + size_t(j)] = float(f.p[j]);
                out_c[k + size_t(j)] = float(f.c[j]);
            }
            out_silhouette[i] = f.silhouette ? 1 : 0;
        }
    });
}

}  // extern "C"
