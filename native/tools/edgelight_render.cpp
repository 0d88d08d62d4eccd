// edgelight-render MESH --out OUT.png [options]
// Renders a mesh with EdgeLight's surface and edge-highlight passes offscreen (OSMesa, llvmpipe)
// from the same shaders/ sources the Blender add-on compiles, and writes a PNG.
#include "cli_args.hpp"
#include "mesh_batches.hpp"
#include "mesh_io.hpp"
#include "mesh_limits.hpp"
#include "osmesa_context.hpp"
#include "png_write.hpp"
#include "render_passes.hpp"
#include "tool_failure.hpp"

#include <edgelight/edgelight.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>

#ifndef EDGELIGHT_SHADER_DIR
#define EDGELIGHT_SHADER_DIR "shaders"
#endif

namespace {

const char* kUsage =
    "usage: edgelight-render MESH --out OUT.png [options]\n"
    "  MESH              any file assimp reads (OBJ, PLY, OFF, STL, ...; equal positions welded)\n"
    "  --size WxH        image size in pixels (default 640x480)\n"
    "  --eye X Y Z       camera position (default: bounding-box centre + 2.5 x its diagonal\n"
    "                    along (1, -0.85, 0.7))\n"
    "  --target X Y Z    point looked at (default: bounding-box centre); +Z is up\n"
    "  --fov DEG         field of view across the larger side (default 39.6: Blender's 50 mm)\n"
    "  --sun X Y Z       direction towards the sun (default: over the camera's left shoulder)\n"
    "  --sun-strength S  irradiance (default 3)\n"
    "  --color R G B     base colour, scene-linear (default 0.8 0.8 0.8)\n"
    "  --shininess N     Blinn exponent (default 30: Principled roughness 0.5)\n"
    "  --radius R        rounded-edge radius r_e in world units (default 0.01)\n"
    "  --K K             highlight gain K (default 1)\n"
    "  --crease DEG      edges whose face normals differ by more are rounded; also the\n"
    "                    auto-smooth angle of the surface normals (default 30)\n"
    "  --samples N       jittered surface samples (default 8, as the add-on)\n"
    "  --shaders DIR     shader sources (default: the repository's shaders/)\n";

struct Args {
    std::string mesh, out, shaders = EDGELIGHT_SHADER_DIR;
    int width = 640, height = 480, samples = 8;
    bool has_eye = false, has_target = false, has_sun = false;
    glm::dvec3 eye{0.0}, target{0.0}, sun{0.0}, color{0.8};
    double fov = 39.5977, strength = 3.0, shininess = 30.0, radius = 0.01, K = 1.0, crease = 30.0;
};

Args parse(int argc, char** argv) {
    Args a;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto need = [&](int n) {
            if (i + n >= argc) throw std::invalid_argument(arg + " needs " + std::to_string(n) + " value(s)");
        };
        auto vec3 = [&](glm::dvec3& v) {
            need(3);
            for (int k = 0; k < 3; ++k) v[k] = el_tools::cli_number(argv[++i]);
        };
        auto scalar = [&](double& v, double lo, double hi) {
            need(1);
            v = el_tools::cli_number(argv[++i]);
            if (!(v >= lo && v <= hi)) throw std::invalid_argument(arg + " out of range");
        };
        const double inf = std::numeric_limits<double>::infinity();
        if (arg == "--out") {
            need(1);
            a.out = argv[++i];
        } else if (arg == "--shaders") {
            need(1);
            a.shaders = argv[++i];
        } else if (arg == "--size") {
            need(1);
            if (std::sscanf(argv[++i], "%dx%d", &a.width, &a.height) != 2 || a.width < 1 || a.height < 1 ||
                a.width > 8192 || a.height > 8192) {
                throw std::invalid_argument("--size wants WxH, e.g. 640x480");
            }
        } else if (arg == "--eye") {
            vec3(a.eye);
            a.has_eye = true;
        } else if (arg == "--target") {
            vec3(a.target);
            a.has_target = true;
        } else if (arg == "--sun") {
            vec3(a.sun);
            a.has_sun = true;
            if (glm::length(a.sun) == 0.0) throw std::invalid_argument("--sun needs a non-zero direction");
        } else if (arg == "--color") {
            vec3(a.color);
        } else if (arg == "--fov") {
            scalar(a.fov, 1.0, 170.0);
        } else if (arg == "--sun-strength") {
            scalar(a.strength, 0.0, inf);
        } else if (arg == "--shininess") {
            scalar(a.shininess, 1.0, 10000.0);
        } else if (arg == "--radius") {
            scalar(a.radius, 0.0, inf);
        } else if (arg == "--K") {
            scalar(a.K, 0.0, inf);
        } else if (arg == "--crease") {
            scalar(a.crease, 0.0, 180.0);
        } else if (arg == "--samples") {
            double s = 0.0;
            scalar(s, 1.0, 256.0);
            a.samples = int(s);
        } else if (arg == "-h" || arg == "--help") {
            std::cout << kUsage << "  Refused (exit 1, one line on stderr): what assimp's validation rejects,\n"
                      << "  and more than " << el_tools::kMeshLimitsText << ".\n";
            std::exit(0);
        } else {
            el_tools::cli_mesh_path(arg, a.mesh);
        }
    }
    if (a.mesh.empty()) throw std::invalid_argument("no mesh given");
    if (a.out.empty()) throw std::invalid_argument("no --out given");
    return a;
}

// Frames the bounding box when no eye or target is given; clip planes from its size.
el_tools::Camera camera_for(const Args& a, const std::vector<float>& p) {
    const el_tools::Box box = el_tools::bounding_box(p);
    const glm::dvec3 centre = box.centre();
    const double diag = box.diagonal();
    // Framing divides by the box's size: a mesh that is one point (or not finite) has none.
    if (!a.has_eye && !(diag > 0.0 && std::isfinite(diag)))
        throw std::invalid_argument("the mesh has no extent to frame (all vertices at one point); give --eye");
    el_tools::Camera c;
    c.width = a.width;
    c.height = a.height;
    c.fov_deg = a.fov;
    c.target = a.has_target ? a.target : centre;
    c.eye = a.has_eye ? a.eye : centre + 2.5 * diag * glm::normalize(glm::dvec3(1.0, -0.85, 0.7));
    if (glm::length(c.eye - c.target) == 0.0) throw std::invalid_argument("--eye and --target coincide");
    const double dist = glm::length(c.eye - centre);
    c.clip_end = dist + diag + 1e-3;
    c.clip_start = std::max(c.clip_end * 1e-4, dist - diag);
    return c;
}

}  // namespace

int main(int argc, char** argv) {
    return el_tools::run_tool<Args>("edgelight-render", kUsage, argc, argv, parse, [](const Args& args) {
        const auto t0 = std::chrono::steady_clock::now();
        el_tools::LoadedMesh mesh = el_tools::load_mesh(args.mesh);
        // Drawn about its bounding box's centre: the passes compute in single precision, which
        // keeps about 7 digits of a world coordinate, so a part 1e7 from the origin would lose
        // its shape. The camera's points move with it; what is drawn is the same.
        const glm::dvec3 origin = el_tools::bounding_box(mesh.positions).centre();
        for (size_t i = 0; i < mesh.positions.size(); ++i)
            mesh.positions[i] = float(double(mesh.positions[i]) - origin[int(i % 3)]);
        Args local = args;
        local.eye -= origin;
        local.target -= origin;
        const el_tools::Camera camera = camera_for(local, mesh.positions);
        el_tools::Scene scene;
        scene.surface = el_tools::surface_corners(mesh, float(args.crease));
        scene.edges = el_tools::choose_edges(mesh, float(args.crease));
        scene.material.base_color = glm::vec3(args.color);
        scene.material.shininess = float(args.shininess);
        scene.material.radius = float(args.radius);
        scene.material.K = float(args.K);
        glm::dvec3 to_light = args.sun;
        if (!args.has_sun) {  // over the camera's left shoulder
            const glm::dvec3 back = glm::normalize(camera.eye - camera.target);
            const glm::dvec3 right = glm::normalize(glm::cross(-back, glm::dvec3(0.0, 0.0, 1.0)));
            to_light = back - 0.6 * right + glm::dvec3(0.0, 0.0, 0.8);
        }
        scene.suns.push_back({glm::normalize(to_light), glm::dvec3(args.strength)});

        el_tools::OsmesaContext context;
        el_tools::Renderer renderer(args.shaders);
        const el_tools::Images img = renderer.render(scene, camera, args.samples);
        el_tools::write_png(args.out, img.result, img.width, img.height);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        std::cout << "edgelight-render: " << args.out << " " << img.width << "x" << img.height << ", "
                  << mesh.triangles.size() / 3 << " triangles, " << scene.edges.size() << " rounded edges, "
                  << args.samples << " samples, " << long(ms) << " ms on " << context.description() << "\n";
        return 0;
    });
}
