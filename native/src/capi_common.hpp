// Entry guard and argument checks shared by the C entry points (capi_*.cpp).
#pragma once

#include "error.hpp"

#include <cmath>
#include <cstdint>
#include <new>
#include <string>

namespace el {

// Runs f; maps whatever it throws to a status and the last-error message. Never throws.
template <class F>
el_status guarded(const char* function, F&& f) noexcept {
    try {
        f();
        set_last_error("");
        return EL_OK;
    } catch (const Error& e) {
        set_last_error((std::string(function) + ": " + e.what()).c_str());
        return e.status();
    } catch (const std::bad_alloc&) {
        set_last_error((std::string(function) + ": out of memory").c_str());
        return EL_ERR_OUT_OF_MEMORY;
    } catch (const std::exception& e) {
        set_last_error((std::string(function) + ": internal error: " + e.what()).c_str());
        return EL_ERR_INTERNAL;
    } catch (...) {
        set_last_error((std::string(function) + ": internal error").c_str());
        return EL_ERR_INTERNAL;
    }
}

inline void require(const void* p, const char* name) {
    if (!p) fail(EL_ERR_NULL_POINTER, std::string(name) + " is NULL");
}

inline void require_capacity(uint64_t capacity, uint64_t needed, const char* what) {
    if (capacity < needed)
        fail(EL_ERR_BUFFER_TOO_SMALL, std::string(what) + ": capacity " + std::to_string(capacity) +
                                          " is below the " + std::to_string(needed) + " needed");
}

inline void require_finite(double v, const char* name) {
    if (!std::isfinite(v)) fail(EL_ERR_NON_FINITE, std::string(name) + " is not finite");
}

inline void require_finite3(const float* v, const char* name) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(v[i])) fail(EL_ERR_NON_FINITE, std::string(name) + " is not finite");
}

}  // namespace el
