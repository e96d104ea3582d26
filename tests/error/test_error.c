/* Error codes: distinct, negative, named. */
#include "inclino/error.h"
#include "unit.h"

#include <string.h>

static void test_names_are_distinct_and_known(void)
{
    int a, b;
    CHECK(strcmp(inc_err_name(INC_OK), "OK") == 0);
    CHECK(strcmp(inc_err_name(INC_ERR_BUS), "ERR_BUS") == 0);
    CHECK(strcmp(inc_err_name(1), "ERR_UNKNOWN") == 0);
    CHECK(strcmp(inc_err_name(-1000), "ERR_UNKNOWN") == 0);
    for (a = INC_ERR_ABORTED; a < 0; a++) {
        CHECK(strcmp(inc_err_name(a), "ERR_UNKNOWN") != 0);
        for (b = a + 1; b < 0; b++) {
            CHECK(strcmp(inc_err_name(a), inc_err_name(b)) != 0);
        }
    }
}

int main(void)
{
    UNIT_RUN(test_names_are_distinct_and_known);
    return unit_report();
}
