/* A library that looks like libedgelight but has another ABI version: the add-on must refuse it
 * with a clear message. */
#include <stdint.h>

__attribute__((visibility("default"))) uint32_t el_abi_version(void) { return 999u; }
