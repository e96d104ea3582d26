/*
 * The unit harness itself (tests/support): case selection and listing, driven from the command
 * line by run_harness.cmake. Each case says that it ran, so the script can tell which did.
 */
#include "unit.h"

#include <stdio.h>

static void case_alpha(void)
{
    printf("ran case_alpha\n");
    CHECK_EQ_INT(1 + 1, 2);
}

static void case_beta(void)
{
    printf("ran case_beta\n");
    CHECK_OK(INC_OK);
    CHECK_ERR(INC_ERR_BUS, INC_ERR_BUS);
}

static void case_gamma(void)
{
    printf("ran case_gamma\n");
    CHECK(inc_err_name(INC_ERR_RANGE)[0] == 'E');
}

int main(void)
{
    UNIT_RUN(case_alpha);
    UNIT_RUN(case_beta);
    UNIT_RUN(case_gamma);
    return unit_report();
}
