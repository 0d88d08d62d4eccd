#include "error.hpp"

namespace el {

namespace {
thread_local std::string t_last_error;
}

void fail(el_status status, const std::string& message) { throw Error(status, message); }

void set_last_error(const char* message) noexcept {
    try {
        t_last_error = message;
    } catch (...) {
        t_last_error.clear();  // out of memory for the message itself: leave it empty
    }
}

const char* last_error() noexcept { return t_last_error.c_str(); }

}  // namespace el
