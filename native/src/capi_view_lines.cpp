// C entry points for the view lines of many instances of one mesh (view_lines.hpp).
#include "capi_common.hpp"
#include "handles.hpp"
#include "view_lines.hpp"

#include <algorithm>
#include <memory>
#include <string>

using el::guarded;
using el::require;
using el::require_capacity;

extern "C" {

EL_API el_status el_view_lines_create(const el_view_lines_desc* desc, el_view_lines** out_lines) {
    if (out_lines) *out_lines = nullptr;
    return guarded("el_view_lines_create", [&] {
        require(desc, "desc");
        require(out_lines, "out_lines");
        require(desc->mesh, "desc->mesh");
        if (desc->view_count) require(desc->views, "desc->views");
        if (desc->flags & ~uint32_t(EL_VIEW_LINES_TAPER))
            el::fail(EL_ERR_INVALID_ARGUMENT, "desc->flags has unknown bits " + std::to_string(desc->flags));
        const el::MeshData& mesh = *desc->mesh->data;
        if (desc->edge_faces) {
            const size_t n = 2 * size_t(mesh.edge_count());
            for (size_t i = 0; i < n; ++i)
                if (!std::isfinite(desc->edge_faces[i]))
                    el::fail(EL_ERR_NON_FINITE, "desc->edge_faces[" + std::to_string(i) + "] is not finite");
        }
        // The cameras must be usable for every instance; only an instance's own transform may
        // leave it without lines (its status).
        if (desc->outline)
            for (uint32_t i = 0; i < desc->view_count; ++i) {
                el_outline_view v = desc->views[i];
                std::fill(v.object_to_world, v.object_to_world + 16, 0.0f);
                el::outline_camera(v);
            }
        auto out = std::make_unique<el_view_lines>();
        out->lines = el::view_lines(mesh, desc->outline ? &desc->outline->records : nullptr, desc->edge_faces,
                                    desc->views, desc->view_count, desc->flags);
        out->has_faces = desc->edge_faces != nullptr;
        *out_lines = out.release();
    });
}

EL_API void el_view_lines_destroy(el_view_lines* lines) { delete lines; }

EL_API el_status el_view_lines_get_offsets(const el_view_lines* lines, uint32_t* out_offsets, uint32_t capacity,
                                           int32_t* out_status) {
    return guarded("el_view_lines_get_offsets", [&] {
        require(lines, "lines");
        require(out_offsets, "out_offsets");
        const auto& inst = lines->lines.instances;
        require_capacity(capacity, inst.size() + 1, "capacity");
        uint64_t total = 0;
        out_offsets[0] = 0;
        for (size_t i = 0; i < inst.size(); ++i) {
            total += inst[i].size();
            if (total > UINT32_MAX) el::fail(EL_ERR_OVERFLOW, "more than 2^32 - 1 segments");
            out_offsets[i + 1] = uint32_t(total);
        }
        if (out_status)
            for (size_t i = 0; i < inst.size(); ++i) out_status[i] = int32_t(lines->lines.status[i]);
    });
}

EL_API el_status el_view_lines_get_message(const el_view_lines* lines, uint32_t view, const char** out_message) {
    if (out_message) *out_message = nullptr;
    return guarded("el_view_lines_get_message", [&] {
        require(lines, "lines");
        require(out_message, "out_message");
        if (view >= lines->lines.message.size())
            el::fail(EL_ERR_INDEX_OUT_OF_RANGE, "view " + std::to_string(view) + " is not below the view count " +
                                                    std::to_string(lines->lines.message.size()));
        *out_message = lines->lines.message[view].c_str();
    });
}

EL_API el_status el_view_lines_copy(const el_view_lines* lines, el_outline_out* out) {
    return guarded("el_view_lines_copy", [&] {
        require(lines, "lines");
        require(out, "out");
        size_t total = 0;
        for (const auto& s : lines->lines.instances) total += s.size();
        require_capacity(out->capacity, total, "out->capacity");
        if (total == 0) return;
        for (auto [p, name] : {std::pair{out->p0, "out->p0"}, {out->p1, "out->p1"}, {out->n1, "out->n1"}, {out->n2, "out->n2"}, {out->taper, "out->taper"}})
            require(p, name);
        require(out->links, "out->links");
        if (lines->has_faces) require(out->faces, "out->faces");
        size_t at = 0;
        for (const auto& s : lines->lines.instances) {
            std::copy(s.p0.begin(), s.p0.end(), out->p0 + 3 * at);
            std::copy(s.p1.begin(), s.p1.end(), out->p1 + 3 * at);
            std::copy(s.n1.begin(), s.n1.end(), out->n1 + 3 * at);
            std::copy(s.n2.begin(), s.n2.end(), out->n2 + 3 * at);
            std::copy(s.taper.begin(), s.taper.end(), out->taper + 2 * at);
            if (lines->has_faces) std::copy(s.faces.begin(), s.faces.end(), out->faces + 2 * at);
            std::copy(s.links.begin(), s.links.end(), out->links + at);
            at += s.size();
        }
    });
}

}  // extern "C"
