/*
 * A test that fails on purpose (registered WILL_FAIL): it proves that a failing check reaches
 * CTest on every target, through the harness's exit status and, on the QEMU boards, through
 * semihosting and QEMU's exit status.
 *
 * The failing check depends on an initialised .data variable: with a startup that does not copy
 * .data, board_fail_marker reads 0 (QEMU's RAM starts zeroed), the check passes, the program
 * exits 0 and CTest reports this WILL_FAIL test as failed. A startup that skips the .data copy
 * can therefore not make failures pass in silence. The twin test board_will_fail_status also
 * demands the exact status 1 (one failed check), so a crash is not mistaken for the failure.
 */
#include <stdint.h>

#include "unit.h"

static volatile uint32_t board_fail_marker = 0x600DF00Du;

static void test_fails_on_purpose(void)
{
    /* Deliberately wrong: the marker is 0x600DF00D whenever .data was initialised. */
    CHECK_EQ_HEX(board_fail_marker, 0u);
}

int main(void)
{
    UNIT_RUN(test_fails_on_purpose);
    return unit_report();
}
