/*
 * A program whose only check fails on purpose: run_harness.cmake (MODE errname) checks that the
 * harness prints both error codes by name and value, and that the status is 1.
 */
#include "unit.h"

static int returns_bus_error(void)
{
    return INC_ERR_BUS;
}

static void case_mismatch(void)
{
    CHECK_ERR(returns_bus_error(), INC_ERR_RANGE);
}

int main(void)
{
    UNIT_RUN(case_mismatch);
    return unit_report();
}
