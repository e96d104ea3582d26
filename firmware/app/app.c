/* app.c - see app.h. A stub until the EPB pipeline lands. */
#include "inclino/app.h"

int app_init(const struct hal *hal)
{
    return hal_check(hal);
}
