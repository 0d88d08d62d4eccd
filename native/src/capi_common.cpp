// Version, status names and the last-error accessor.
#include "capi_common.hpp"

extern "C" {

EL_API uint32_t el_abi_version(void) { return EL_ABI_VERSION; }

EL_API const char* el_last_error(void) { return el::last_error(); }

EL_API const char* el_status_name(el_status status) {
    switch (status) {
        case EL_OK: return "EL_OK";
        case EL_ERR_NULL_POINTER: return "EL_ERR_NULL_POINTER";
        case EL_ERR_INVALID_COUNT: return "EL_ERR_INVALID_COUNT";
        case EL_ERR_INDEX_OUT_OF_RANGE: return "EL_ERR_INDEX_OUT_OF_RANGE";
        case EL_ERR_NON_FINITE: return "EL_ERR_NON_FINITE";
        case EL_ERR_OVERFLOW: return "EL_ERR_OVERFLOW";
        case EL_ERR_INVALID_ARGUMENT: return "EL_ERR_INVALID_ARGUMENT";
        case EL_ERR_BUFFER_TOO_SMALL: return "EL_ERR_BUFFER_TOO_SMALL";
        case EL_ERR_OUT_OF_MEMORY: return "EL_ERR_OUT_OF_MEMORY";
        case EL_ERR_INTERNAL: return "EL_ERR_INTERNAL";
    }
    return "EL_ERR_UNKNOWN";
}

}  // extern "C"
