// How both tools run and fail: arguments refused -> the usage, exit 2; after that one line on
// stderr naming the mesh file and the reason, and exit code 1, whatever was thrown.
#pragma once

#include <edgelight/edgelight.h>

#include <algorithm>
#include <exception>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>

namespace el_tools {

// Call from a catch block: rethrows the exception in flight to name it.
inline int report_failure(const char* tool, const std::string& mesh) {
    std::string reason;
    try {
        throw;
    } catch (const std::bad_alloc&) {
        reason = "out of memory";
    } catch (const std::exception& e) {
        reason = e.what();
    } catch (...) {
        reason = "unknown error";
    }
    std::replace_if(
        reason.begin(), reason.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    // load_mesh's messages name the file already; later stages' do not.
    if (reason.find("'" + mesh + "'") == std::string::npos) reason = "'" + mesh + "': " + reason;
    std::cerr << tool << ": " << reason << std::endl;
    return 1;
}

// Both tools' main(): `parse` the arguments (a refusal prints it and the usage: exit 2), check
// the library's ABI, run `body(args)`; anything thrown after parsing is reported as above.
template <class Args, class Parse, class Body>
int run_tool(const char* tool, const char* usage, int argc, char** argv, Parse parse, Body body) {
    Args args;
    try {
        args = parse(argc, argv);
    } catch (const std::exception& e) {
        std::cerr << tool << ": " << e.what() << "\n"
                  << usage;
        return 2;
    }
    try {
        if (el_abi_version() != EL_ABI_VERSION) throw std::runtime_error("libedgelight ABI mismatch");
        return body(args);
    } catch (...) {
        return report_failure(tool, args.mesh);
    }
}

}  // namespace el_tools
