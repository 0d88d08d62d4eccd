// Errors inside the library are exceptions carrying an el_status; the C entry points turn them
// into a status and the thread-local last-error message (capi_common.hpp). Nothing escapes.
#pragma once

#include <edgelight/edgelight.h>

#include <stdexcept>
#include <string>

namespace el {

class Error : public std::runtime_error {
public:
    Error(el_status status, const std::string& message)
        : std::runtime_error(message), status_(status) {}
    el_status status() const noexcept { return status_; }

private:
    el_status status_;
};

[[noreturn]] void fail(el_status status, const std::string& message);

void set_last_error(const char* message) noexcept;
const char* last_error() noexcept;

}  // namespace el
