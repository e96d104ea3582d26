/*
 * A driver that breaks the part's timing is caught: a port whose SCLK runs at 4 MHz (the
 * ADIS16255 allows 2.5 MHz) reads a sample; the model reports every fast edge and the normal
 * end-of-test check (CHECK_NO_VIOLATIONS, used by every other test) fails, printing the log.
 *
 * Built twice:
 *   adis16255_timing_caught   checks, inside the run, that exactly this check failed, that the
 *                             log names the rule, the part and the numbers; passes.
 *   adis16255_timing_violation (EXPECT_FAIL) the plain test: it must fail (CTest WILL_FAIL),
 *                             which proves the harness turns a violation into a red test.
 */
#include "fixture.h"

#include <string.h>

static void test_fast_sclk(void)
{
    struct adis16255_sample s;
    fx_setup(true);
    fx_input(100.0, 40.0, 5.0);
    REQUIRE(adis16255_init(&fx.drv, &fx.cfg) == 0);
    REQUIRE(fx.board.log.total == 0u);
    hal_delay_ms(&fx.board.hal, 4);
    fx.drv.spi.cfg.timing.sclk_period_ns = 250; /* the bug: 4 MHz */
    (void)adis16255_read_sample(&fx.drv, &s);
#ifdef EXPECT_FAIL
    CHECK_NO_VIOLATIONS();
#else
    char line[160];
    {
        const unsigned before = unit_failures;
        CHECK_NO_VIOLATIONS(); /* fails and prints the log ... */
        if (unit_failures == before + 1u) {
            unit_failures = before; /* ... as it must: that failure is this test's pass */
            printf("(the failure above is expected: it is what every normal test does)\n");
        } else {
            CHECK(!"the zero-violation check did not fail");
        }
    }
    CHECK(sim_violation_count(&fx.board.log, SIM_VIOL_SCLK_FAST) >= 1u);
    CHECK_EQ_INT(fx.board.log.v[0].kind, SIM_VIOL_SCLK_FAST);
    CHECK_EQ_INT(fx.board.log.v[0].limit_ns, 400);
    CHECK_EQ_INT(fx.board.log.v[0].measured_ns, 250);
    CHECK(strcmp(fx.board.log.v[0].source, "adis16255") == 0);
    CHECK(sim_violation_format(&fx.board.log.v[0], line, sizeof(line)) > 0);
    CHECK(strstr(line, "sclk-too-fast: adis16255 measured 250 ns, required 400 ns") != NULL);
    /* Whatever the misaligned words said, they did not become a valid sample. */
    CHECK(!s.valid);
#endif
}

int main(void)
{
    UNIT_RUN(test_fast_sclk);
    return unit_report();
}
