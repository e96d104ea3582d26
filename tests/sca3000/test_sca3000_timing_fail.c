/*
 * Proof that a timing violation by the driver fails a test: the same init + read as a normal run,
 * with the driver's SCLK at 1 MHz against the part's 500 kHz, ends with the check every normal
 * run makes (CHECK_NO_VIOLATIONS). That check must fail and print the violation log; CTest
 * registers this test as WILL_FAIL, so it passes only if the failure happens.
 */
#include "fixture.h"

static void test_driver_too_fast_fails(void)
{
    REQUIRE(fx_setup_part(SIM_SCA3000_E04, 0) == 0);
    if (sca3000_init(&fx.dev, &fx.cfg) == 0) {
        int16_t xyz[3];
        fx.dev.spi.cfg.timing.sclk_period_ns = 1000; /* the bug: 1 MHz */
        (void)sca3000_read_accel(&fx.dev, xyz);
    }
    CHECK_NO_VIOLATIONS();
}

int main(void)
{
    UNIT_RUN(test_driver_too_fast_fails);
    return unit_report();
}
