/* hal/rt/mem.c compiled as rt_memcpy, rt_memset, rt_memmove and rt_memcmp, so the run-time's own
 * code runs next to the C library's (see mem.c's INC_RT_NAME). */
#define INC_RT_NAME(name) rt_##name
#include "../../hal/rt/mem.c"
