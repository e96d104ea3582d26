/* inttypes.h - rv32 test shim (see stdio.h): <stdint.h> and the PRI macros of ILP32. */
#ifndef INCLINO_RV32_INTTYPES_H
#define INCLINO_RV32_INTTYPES_H

#include <stdint.h>

#define PRId8 "d"
#define PRId16 "d"
#define PRId32 "ld"
#define PRId64 "lld"
#define PRIi32 "ld"
#define PRIi64 "lld"
#define PRIu8 "u"
#define PRIu16 "u"
#define PRIu32 "lu"
#define PRIu64 "llu"
#define PRIx32 "lx"
#define PRIx64 "llx"
#define PRIX32 "lX"
#define PRIX64 "llX"

#endif /* INCLINO_RV32_INTTYPES_H */
