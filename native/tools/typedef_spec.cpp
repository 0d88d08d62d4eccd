#include "typedef_spec.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace el_tools {
namespace {

// File order matters: the #define lines come out in it, as in the add-on's Python.
using nlohmann::ordered_json;

struct MemberType {
    const char* glsl;
    size_t floats;
};

// vec4 and mat4 only: std140 pads nothing between them (see Block).
const std::map<std::string, MemberType> kTypes = {{"VEC4", {"vec4", 4}}, {"MAT4", {"mat4", 16}}};

ordered_json read_spec(const std::string& shader_dir, const std::string& file_name) {
    const std::string path = shader_dir + "/" + file_name;
    std::ifstream f(path, std::ios::binary);
    if (!f) throw std::runtime_error("cannot read " + path);
    try {
        return ordered_json::parse(f);
    } catch (const ordered_json::exception& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
}

// Defines, then each enum's values as ENUM_KEY, in file order.
std::vector<std::pair<std::string, ordered_json>> define_list(const ordered_json& spec) {
    std::vector<std::pair<std::string, ordered_json>> out;
    const ordered_json defines = spec.value("defines", ordered_json::object());  // items() refers into it
    const ordered_json enums = spec.value("enums", ordered_json::object());
    for (const auto& [name, value] : defines.items()) out.emplace_back(name, value);
    for (const auto& [enum_name, values] : enums.items()) {
        for (const auto& [key, value] : values.items()) out.emplace_back(enum_name + "_" + key, value);
    }
    return out;
}

const MemberType& member_type(const ordered_json& m, const std::string& file_name) {
    const std::string type = m.at("type").get<std::string>();
    const auto it = kTypes.find(type);
    if (it == kTypes.end()) {
        throw std::runtime_error(file_name + ": member " + m.at("name").get<std::string>() + " is " + type +
                                 "; only VEC4 and MAT4 are packed");
    }
    return it->second;
}

}  // namespace

std::string typedef_glsl(const std::string& shader_dir, const std::string& file_name) {
    const ordered_json spec = read_spec(shader_dir, file_name);
    std::ostringstream s;
    try {
        s << "/* generated from " << file_name << " */\n";
        for (const auto& [name, value] : define_list(spec)) s << "#define " << name << " " << value.dump() << "\n";
        if (spec.contains("struct")) {
            s << "struct " << spec.at("struct").get<std::string>() << " {\n";
            for (const auto& m : spec.at("members")) {
                s << "  " << member_type(m, file_name).glsl << " " << m.at("name").get<std::string>();
                if (m.contains("count")) {
                    const auto& c = m.at("count");
                    s << "[" << (c.is_string() ? c.get<std::string>() : c.dump()) << "]";
                }
                s << ";\n";
            }
            s << "};\n";
        }
    } catch (const ordered_json::exception& e) {
        throw std::runtime_error(file_name + ": " + e.what());
    }
    return s.str();
}

Block::Block(const std::string& shader_dir, const std::string& file_name) : file_(file_name) {
    const ordered_json spec = read_spec(shader_dir, file_name);
    try {
        for (const auto& [name, value] : define_list(spec)) {
            if (!value.is_number_integer()) throw std::runtime_error(file_name + ": " + name + " is not an integer");
            defines_[name] = value.get<int>();
        }
        const ordered_json members = spec.value("members", ordered_json::array());  // none: defines only
        for (const auto& m : members) {
            Member member;
            member.floats = member_type(m, file_name).floats;
            if (m.contains("count")) {
                const auto& c = m.at("count");
                member.count = c.is_string() ? size_t(define(c.get<std::string>())) : c.get<size_t>();
            }
            member.offset = size_;
            size_ += member.count * member.floats;
            members_[m.at("name").get<std::string>()] = member;
        }
    } catch (const ordered_json::exception& e) {
        throw std::runtime_error(file_name + ": " + e.what());
    }
}

int Block::define(const std::string& name) const {
    const auto it = defines_.find(name);
    if (it == defines_.end()) throw std::runtime_error(file_ + " defines no " + name);
    return it->second;
}

void Block::set(std::vector<float>& block, const std::string& name, const std::vector<float>& values, size_t index) const {
    const auto it = members_.find(name);
    if (it == members_.end()) throw std::runtime_error(file_ + " has no member " + name);
    const Member& m = it->second;
    if (index >= m.count || values.size() > m.floats || block.size() != size_) {
        throw std::runtime_error(file_ + ": " + name + "[" + std::to_string(index) + "] does not hold " +
                                 std::to_string(values.size()) + " floats");
    }
    std::copy(values.begin(), values.end(), block.begin() + std::ptrdiff_t(m.offset + index * m.floats));
}

}  // namespace el_tools
