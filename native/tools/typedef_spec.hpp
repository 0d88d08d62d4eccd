// Typedef specs: JSON files in shaders/ (frame_data.json, surface_modes.json) that are the one
// description of a contract between GLSL and its hosts. A program that lists one in its typedefs
// gets the GLSL written from it (the same text addon/bridge/shader_specs.py writes, checked by
// tests/addon/test_shader_specs.py), and a host packs a spec's struct by member name (Block).
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace el_tools {

// The GLSL of the spec shaders/`file_name` in `shader_dir`: its defines and enum values as
// #define lines, then its struct if it has one. Throws std::runtime_error naming the file.
std::string typedef_glsl(const std::string& shader_dir, const std::string& file_name);

// A spec's struct in std140 (a spec without one: just its defines), counted in floats. Members
// are vec4 or mat4 only, so each starts where the one before ends.
class Block {
public:
    struct Member {
        size_t offset = 0;  // floats from the block's start
        size_t count = 1;   // array length (1 for a plain member)
        size_t floats = 4;  // per element: 4 (vec4) or 16 (mat4)
    };
    Block(const std::string& shader_dir, const std::string& file_name);

    size_t size() const { return size_; }  // floats
    const std::map<std::string, Member>& members() const { return members_; }
    // Its defines and enum values (ENUM_KEY); throws if it has no such name.
    int define(const std::string& name) const;
    const std::map<std::string, int>& defines() const { return defines_; }

    std::vector<float> zeros() const { return std::vector<float>(size_, 0.0f); }
    // Writes `values` into element `index` of member `name` of `block` (from zeros()); throws if
    // the member is unknown or they do not fit the element.
    void set(std::vector<float>& block, const std::string& name, const std::vector<float>& values, size_t index = 0) const;

private:
    std::string file_;
    std::map<std::string, Member> members_;
    std::map<std::string, int> defines_;
    size_t size_ = 0;
};

}  // namespace el_tools
