// edgelight-info MESH [--crease DEG] [--eye X Y Z | --view-dir X Y Z]
// Prints what the library sees in a mesh, as JSON: the quickest check of a model's edges.
#include "cli_args.hpp"
#include "mesh_io.hpp"
#include "mesh_limits.hpp"
#include "tool_failure.hpp"

#include <edgelight/edgelight.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

namespace {

const char* kUsage =
    "usage: edgelight-info MESH [--crease DEG] [--eye X Y Z | --view-dir X Y Z]\n"
    "  MESH        any file assimp reads (OFF, PLY, OBJ, STL, ...)\n"
    "  --crease    crease threshold in degrees between face normals (default 30; Freestyle's\n"
    "              crease angle is 180 minus this)\n"
    "  --eye       perspective eye point for silhouettes and contours\n"
    "  --view-dir  orthographic view direction instead\n"
    "  Without a view, the eye is at the bounding-box centre + 2.5 x its diagonal along (1,1,1).\n";

struct Args {
    std::string mesh;
    float crease = 30.0f;
    bool has_eye = false, has_dir = false;
    std::array<float, 3> eye{}, dir{};
};

float number(const char* s) {
    const double v = el_tools::cli_number(s);
    if (std::abs(v) > std::numeric_limits<float>::max()) throw std::invalid_argument(std::string("not a float: ") + s);
    return float(v);
}

Args parse(int argc, char** argv) {
    Args a;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto need = [&](int n) {
            if (i + n >= argc) throw std::invalid_argument(arg + " needs " + std::to_string(n) + " value(s)");
        };
        if (arg == "--crease") {
            need(1);
            a.crease = number(argv[++i]);
        } else if (arg == "--eye" || arg == "--view-dir") {
            need(3);
            auto& v = arg == "--eye" ? a.eye : a.dir;
            for (int k = 0; k < 3; ++k) v[k] = number(argv[++i]);
            (arg == "--eye" ? a.has_eye : a.has_dir) = true;
        } else if (arg == "-h" || arg == "--help") {
            std::cout << kUsage << "  Refused (exit 1, one line on stderr): what assimp's validation rejects,\n"
                      << "  and more than " << el_tools::kMeshLimitsText << ".\n";
            std::exit(0);
        } else {
            el_tools::cli_mesh_path(arg, a.mesh);
        }
    }
    if (a.mesh.empty()) throw std::invalid_argument("no mesh given");
    if (a.has_eye && a.has_dir) throw std::invalid_argument("give --eye or --view-dir, not both");
    return a;
}

void check(el_status s) {
    if (s != EL_OK) throw std::runtime_error(std::string(el_status_name(s)) + ": " + el_last_error());
}

std::array<float, 3> default_eye(const std::vector<float>& p) {
    std::array<float, 3> lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < p.size(); ++i) {
        lo[i % 3] = std::min(lo[i % 3], p[i]);
        hi[i % 3] = std::max(hi[i % 3], p[i]);
    }
    const float diag = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                 (hi[2] - lo[2]) * (hi[2] - lo[2]));
    const float step = 2.5f * diag / std::sqrt(3.0f);
    return {0.5f * (lo[0] + hi[0]) + step, 0.5f * (lo[1] + hi[1]) + step, 0.5f * (lo[2] + hi[2]) + step};
}

}  // namespace

int main(int argc, char** argv) {
    return el_tools::run_tool<Args>("edgelight-info", kUsage, argc, argv, parse, [](const Args& args) {
        const el_tools::LoadedMesh loaded = el_tools::load_mesh(args.mesh);
        el_mesh_desc d{};
        d.positions = loaded.positions.data();
        d.vertex_count = uint32_t(loaded.positions.size() / 3);
        d.triangles = loaded.triangles.data();
        d.triangle_count = uint32_t(loaded.triangles.size() / 3);
        el_mesh* mesh = nullptr;
        check(el_mesh_create(&d, &mesh));
        std::unique_ptr<el_mesh, void (*)(el_mesh*)> mesh_owner(mesh, el_mesh_destroy);
        check(el_mesh_classify(mesh, args.crease));
        el_mesh_info info{};
        check(el_mesh_get_info(mesh, &info));

        el_camera cam{};
        for (int i = 0; i < 16; ++i) cam.object_to_world[i] = (i % 5 == 0) ? 1.0f : 0.0f;
        nlohmann::ordered_json view;
        if (args.has_dir) {
            cam.projection = EL_ORTHOGRAPHIC;
            std::copy(args.dir.begin(), args.dir.end(), cam.view_dir);
            view = {{"projection", "orthographic"}, {"view_dir", args.dir}};
        } else {
            const auto eye = args.has_eye ? args.eye : default_eye(loaded.positions);
            cam.projection = EL_PERSPECTIVE;
            std::copy(eye.begin(), eye.end(), cam.eye);
            view = {{"projection", "perspective"}, {"eye", eye}, {"default", !args.has_eye}};
        }
        el_view* v = nullptr;
        check(el_view_create(mesh, &v));
        std::unique_ptr<el_view, void (*)(el_view*)> view_owner(v, el_view_destroy);
        check(el_view_update(v, &cam, EL_VIEW_SILHOUETTES | EL_VIEW_CONTOURS, nullptr));
        el_view_stats stats{};
        check(el_view_get_stats(v, &stats));

        const nlohmann::ordered_json out = {
            {"file", args.mesh},
            {"vertices", info.vertex_count},
            {"triangles", info.triangle_count},
            {"unique_edges", info.edge_count},
            {"border_edges", info.border_edges},
            {"manifold_edges", info.manifold_edges},
            {"non_manifold_edges", info.non_manifold_edges},
            {"flipped_winding_edges", info.flipped_winding_edges},
            {"reoriented_triangles", info.reoriented_triangles},
            {"degenerate_faces", info.degenerate_triangles},
            {"crease_angle_deg", info.crease_angle_deg},
            {"crease_edges", info.crease_edges},
            {"convex_edges", info.convex_edges},
            {"concave_edges", info.concave_edges},
            {"view", view},
            {"silhouette_edges", stats.silhouette_edges},
            {"contour_segments", stats.contour_segments},
        };
        std::cout << out.dump(2) << "\n";
        return 0;
    });
}
