// What native/tools/typedef_spec.cpp makes of a typedef spec, printed as JSON for
// test_shader_specs.py to compare with the add-on's Python (addon/bridge/shader_specs.py):
//   typedef_spec_dump SHADER_DIR FILE -> {"glsl": ..., "size": n, "defines": {...},
//                                         "members": {name: [offset, count, floats]}}
#include "typedef_spec.hpp"

#include <nlohmann/json.hpp>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: typedef_spec_dump SHADER_DIR FILE\n";
        return 2;
    }
    try {
        const el_tools::Block block(argv[1], argv[2]);
        nlohmann::json out;
        out["glsl"] = el_tools::typedef_glsl(argv[1], argv[2]);
        out["size"] = block.size();
        out["defines"] = block.defines();
        out["members"] = nlohmann::json::object();
        for (const auto& [name, m] : block.members()) out["members"][name] = {m.offset, m.count, m.floats};
        std::cout << out.dump() << "\n";
    } catch (const std::exception& e) {
        std::cerr << "typedef_spec_dump: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
