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

inline void require_finite_array(const float* a, size_t count, const char* name) {
    for (size_t i = 0; i < count; ++i)
        if (!std::isfinite(a[i])) fail(EL_ERR_NON_FINITE, std::string(name) + "[" + std::to_string(i) + "] is not finite");
}

// Every a[i] below limit (`what`: the count it indexes, for the message).
inline void require_below(const uint32_t* a, size_t count, uint32_t limit, const char* name, const char* what) {
    for (size_t i = 0; i < count; ++i)
        if (a[i] >= limit)
            fail(EL_ERR_INDEX_OUT_OF_RANGE, std::string(name) + "[" + std::to_string(i) + "] = " + std::to_string(a[i]) +
                                                " is not below the " + what + " " + std::to_string(limit));
}

// Every a[i] below limit, or -1 for none.
inline void require_index_or_none(const int32_t* a, size_t count, uint32_t limit, const char* name, const char* what) {
    for (size_t i = 0; i < count; ++i)
        if (a[i] < -1 || (a[i] >= 0 && uint32_t(a[i]) >= limit))
            fail(EL_ERR_INDEX_OUT_OF_RANGE, std::string(name) + "[" + std::to_string(i) + "] = " + std::to_string(a[i]) +
                                                " is no " + what + " (nor -1)");
}

inline void require_finite3(const float* v, const char* name) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(v[i])) fail(EL_ERR_NON_FINITE, std::string(name) + " is not finite");
}

}  // namespace el
