// How both tools report a failure after their arguments parsed: one line on stderr naming the
// mesh file and the reason, and exit code 1, whatever was thrown.
#pragma once

#include <algorithm>
#include <exception>
#include <iostream>
#include <new>
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
    std::replace_if(reason.begin(), reason.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    // load_mesh's messages name the file already; later stages' do not.
    if (reason.find("'" + mesh + "'") == std::string::npos) reason = "'" + mesh + "': " + reason;
    std::cerr << tool << ": " << reason << std::endl;
    return 1;
}

}  // namespace el_tools
