/* A library with libedgelight's ABI version (read from the header, so it follows the real one)
 * but almost none of its functions: the add-on must refuse it naming what is missing instead of
 * failing on the first call. */
#include "edgelight/edgelight.h"

uint32_t el_abi_version(void) { return EL_ABI_VERSION; }
const char* el_last_error(void) { return ""; }
