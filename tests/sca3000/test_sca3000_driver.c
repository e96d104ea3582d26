/*
 * The SCA3000 driver against the model on the simulated board, normal operation: init and the
 * REVID check, every measurement mode of every variant, X/Y/Z with exact counts for given
 * physical inputs per variant (and saturation), D01 temperature, the unlock sequence and the
 * indirect registers with their protected bits, the ring buffer with BUF_COUNT, INT_STATUS and
 * the INT line, the error-model hook. Every case ends with an empty violation log: the driver
 * keeps the part's timing and protocol.
 */
#include "fixture.h"

#include <string.h>

/* One sample period of the slowest normal mode (E04, 100 Hz) and a bit. */
#define SETTLE_NS 11000000u

static void test_init_each_variant(void)
{
    unsigned v;
    for (v = 0; v < 4u; v++) {
        REQUIRE(fx_setup((enum sim_sca3000_variant)v) == 0);
        CHECK(fx.dev.ready);
        CHECK_EQ_HEX(sca3000_revid(&fx.dev), SCA3000_REVID_DEFAULT);
        CHECK_EQ_INT(sca3000_get_mode(&fx.dev), SCA3000_MODE_NORMAL);
        CHECK_EQ_HEX(fx.part.mode, SIM_SCA3000_MODE_DEFAULT); /* reserved bit3 kept */
        CHECK_EQ_HEX(fx.dev.int_mask, SIM_SCA3000_INT_MASK_DEFAULT);
        CHECK_EQ_INT(fx.part.corrupt_frames, 0);
        CHECK_EQ_INT(fx.dev.bus_errors, 0);
        CHECK_NO_VIOLATIONS();
    }
    /* A part found in ring mode with option 1 is brought to normal, ring off, bit3 kept. */
    REQUIRE(fx_setup_part(SIM_SCA3000_E05, 0) == 0);
    fx.part.mode = SIM_SCA3000_MODE_DEFAULT | 0x80u | 0x01u;
    CHECK_OK(sca3000_init(&fx.dev, &fx.cfg));
    CHECK_EQ_HEX(fx.part.mode, SIM_SCA3000_MODE_DEFAULT);
    CHECK_NO_VIOLATIONS();
}

/* Expected counts computed by hand: round(a / LSB), LSB = 0.75, 1, 2, 6.25 mg. */
struct accel_case {
    double a[3];
    int16_t want[4][3]; /* D01, E02, E04, E05 */
};

static void test_xyz_exact_counts(void)
{
    static const struct accel_case cases[] = {
        {{0.5, -0.25, 1.0},
         {{667, -333, 1333}, {500, -250, 1000}, {250, -125, 500}, {80, -40, 160}}},
        {{0.1234, -0.9876, 2.5},
         {{165, -1317, 3333}, {123, -988, 2500}, {62, -494, 1250}, {20, -158, 400}}},
        {{0.0, 0.0, -1.0}, {{0, 0, -1333}, {0, 0, -1000}, {0, 0, -500}, {0, 0, -160}}},
        /* Beyond the 13-bit code range: saturation at 4095 / -4096 (E05: 5 g = 800 counts). */
        {{5.0, -5.0, 3.2},
         {{4095, -4096, 4095}, {4095, -4096, 3200}, {2500, -2500, 1600}, {800, -800, 512}}},
    };
    unsigned v, i;
    for (v = 0; v < 4u; v++) {
        REQUIRE(fx_setup((enum sim_sca3000_variant)v) == 0);
        for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
            int16_t xyz[3] = {0x7777, 0x7777, 0x7777};
            int32_t g;
            fx_input(cases[i].a[0], cases[i].a[1], cases[i].a[2], 25.0);
            fx_wait_ns(SETTLE_NS);
            CHECK_OK(sca3000_read_accel(&fx.dev, xyz));
            CHECK_EQ_INT(xyz[0], cases[i].want[v][0]);
            CHECK_EQ_INT(xyz[1], cases[i].want[v][1]);
            CHECK_EQ_INT(xyz[2], cases[i].want[v][2]);
            CHECK_OK(sca3000_accel_g_from_counts(xyz[2], fx.cfg.variant, &g));
            CHECK_NEAR(g / 65536.0,
                       (double)cases[i].want[v][2] * sca3000_ug_per_lsb(fx.cfg.variant) * 1e-6,
                       8e-6);
        }
        CHECK_EQ_INT(fx.part.corrupt_frames, 0);
        CHECK_NO_VIOLATIONS();
    }
}

static void test_temperature_d01(void)
{
    static const double t_c[] = {25.0, -10.0, 60.0, 85.0, -40.0};
    static const uint16_t want[] = {260, 197, 323, 368, 143}; /* round(T * 1.8 + 214.6) */
    struct sca3000_sample s;
    uint16_t raw = 0;
    unsigned i;
    REQUIRE(fx_setup(SIM_SCA3000_D01) == 0);
    for (i = 0; i < sizeof(t_c) / sizeof(t_c[0]); i++) {
        int32_t c;
        fx_input(0.0, 0.0, 1.0, t_c[i]);
        fx_wait_ns(SETTLE_NS);
        CHECK_OK(sca3000_read_temp(&fx.dev, &raw));
        CHECK_EQ_INT(raw, want[i]);
        CHECK_OK(sca3000_temp_c_from_counts(raw, &c));
        CHECK_NEAR(c / 65536.0, t_c[i], 0.3); /* one count is 0.56 degC */
    }
    memset(&s, 0, sizeof(s));
    CHECK_OK(sca3000_read_sample(&fx.dev, &s));
    CHECK(s.temp_valid);
    CHECK_EQ_INT(s.temp_raw, 143);
    CHECK_EQ_INT(s.xyz[2], 1333);
    CHECK_NO_VIOLATIONS();

    REQUIRE(fx_setup(SIM_SCA3000_E02) == 0);
    CHECK_ERR(sca3000_read_temp(&fx.dev, &raw), INC_ERR_UNSUPPORTED);
    CHECK_OK(sca3000_read_sample(&fx.dev, &s));
    CHECK(!s.temp_valid);
    CHECK_EQ_INT(s.xyz[2], 1000);
    CHECK_NO_VIOLATIONS();
}

static void test_modes_each_variant(void)
{
    static const uint32_t odr[4][3] = {
        {250000, 250000, 0}, {125000, 62500, 0}, {100000, 50000, 400000}, {200000, 50000, 400000}};
    unsigned v, m;
    for (v = 0; v < 4u; v++) {
        int16_t xyz[3];
        REQUIRE(fx_setup((enum sim_sca3000_variant)v) == 0);
        for (m = 0; m < 3u; m++) {
            if (odr[v][m] == 0u) {
                const uint8_t before = fx.part.mode;
                CHECK_ERR(sca3000_set_mode(&fx.dev, (enum sca3000_mode)m), INC_ERR_UNSUPPORTED);
                CHECK_EQ_HEX(fx.part.mode, before); /* nothing was sent */
                continue;
            }
            CHECK_OK(sca3000_set_mode(&fx.dev, (enum sca3000_mode)m));
            CHECK_EQ_HEX(fx.part.mode, SIM_SCA3000_MODE_DEFAULT | m);
            CHECK_EQ_INT(sca3000_odr_mhz(&fx.dev), odr[v][m]);
            CHECK_EQ_INT(sim_sca3000_odr_mhz(&fx.part), odr[v][m]);
            fx_wait_ns(2u * SETTLE_NS);
            CHECK_OK(sca3000_read_accel(&fx.dev, xyz));
            CHECK_EQ_INT(xyz[2], (int)(1000000u / sca3000_ug_per_lsb(fx.cfg.variant)));
        }
        /* Motion detection: acceleration is not available, and the driver says so. */
        CHECK_OK(sca3000_set_mode(&fx.dev, SCA3000_MODE_MOTION));
        CHECK_EQ_HEX(fx.part.mode, SIM_SCA3000_MODE_DEFAULT | 3u);
        CHECK_EQ_INT(sca3000_odr_mhz(&fx.dev), 0);
        xyz[0] = 0x1234;
        CHECK_ERR(sca3000_read_accel(&fx.dev, xyz), INC_ERR_STATE);
        CHECK_EQ_INT(xyz[0], 0x1234);
        CHECK_OK(sca3000_set_mode(&fx.dev, SCA3000_MODE_NORMAL));
        fx_wait_ns(2u * SETTLE_NS);
        CHECK_OK(sca3000_read_accel(&fx.dev, xyz));
        CHECK_ERR(sca3000_set_mode(&fx.dev, (enum sca3000_mode)4), INC_ERR_INVAL);
        CHECK_NO_VIOLATIONS();
    }
}

static void test_unlock_and_indirect(void)
{
    uint8_t v = 0;
    REQUIRE(fx_setup(SIM_SCA3000_D01) == 0);
    CHECK(!fx.part.unlocked);
    CHECK_OK(sca3000_ind_read(&fx.dev, SCA3000_IND_OUT_CTRL, &v));
    CHECK(fx.part.unlocked);
    CHECK_EQ_HEX(v, SIM_SCA3000_OUT_CTRL_DEFAULT);
    /* MD_CTRL: the caller's bits 7:6 are ignored, the part's (0x40) are kept. */
    CHECK_OK(sca3000_ind_write(&fx.dev, SCA3000_IND_MD_CTRL, 0x80u | 0x3Fu));
    CHECK_EQ_HEX(fx.part.ind[SCA3000_IND_MD_CTRL], 0x7F);
    CHECK_OK(sca3000_ind_read(&fx.dev, SCA3000_IND_MD_CTRL, &v));
    CHECK_EQ_HEX(v, 0x7F);
    /* OUT_CTRL through the ring API: X and Z, divide by 4, bits 7:5 kept. */
    CHECK_OK(sca3000_ring_config(&fx.dev, SCA3000_OUT_CTRL_X | SCA3000_OUT_CTRL_Z, 4));
    CHECK_EQ_HEX(fx.part.ind[SCA3000_IND_OUT_CTRL], 0xE0 | 0x14 | 0x02);
    CHECK_OK(sca3000_ind_write(&fx.dev, SCA3000_IND_MD_X_TH, 0x12));
    CHECK_EQ_HEX(fx.part.ind[SCA3000_IND_MD_X_TH], 0x12);
    CHECK_OK(sca3000_ind_write(&fx.dev, SCA3000_IND_I2C_DISABLE, 0x01));
    CHECK_EQ_HEX(fx.part.ind[SCA3000_IND_I2C_DISABLE], 0x01);
    /* A part that relocked (power cycle) is unlocked again on the next access. */
    sim_sca3000_power_cycle(&fx.part);
    CHECK_OK(sca3000_ind_read(&fx.dev, SCA3000_IND_MD_CTRL, &v));
    CHECK_EQ_HEX(v, SIM_SCA3000_MD_CTRL_DEFAULT);
    CHECK(!fx.part.locked_up);
    CHECK_NO_VIOLATIONS();

    /* Bad selectors are refused before anything reaches the bus. */
    CHECK_ERR(sca3000_ind_write(&fx.dev, 0x07, 0x00), INC_ERR_INVAL);
    CHECK_ERR(sca3000_ind_read(&fx.dev, 0x00, &v), INC_ERR_INVAL);
    REQUIRE(fx_setup(SIM_SCA3000_E02) == 0);
    CHECK_ERR(sca3000_ind_write(&fx.dev, SCA3000_IND_I2C_DISABLE, 0x01), INC_ERR_INVAL);
    CHECK_NO_VIOLATIONS();
}

static void test_ring_buffer(void)
{
    int16_t vals[SCA3000_RING_CAPACITY];
    size_t n = 0, i;
    unsigned count = 99;
    uint8_t st = 0;
    uint64_t t0;
    REQUIRE(fx_setup(SIM_SCA3000_D01) == 0);
    fx_input(0.5, -0.25, 1.0, 25.0);
    fx_wait_ns(SETTLE_NS);
    CHECK_OK(sca3000_ring_config(&fx.dev,
                                 SCA3000_OUT_CTRL_X | SCA3000_OUT_CTRL_Y | SCA3000_OUT_CTRL_Z, 1));
    CHECK_OK(sca3000_int_config(&fx.dev, SCA3000_INT_RING_1_2, true));
    CHECK_EQ_HEX(fx.part.int_mask, 0x14 | 0x40 | 0x01); /* protected bits kept */
    CHECK_OK(sca3000_ring_enable(&fx.dev, true));
    CHECK_EQ_HEX(fx.part.mode, SIM_SCA3000_MODE_DEFAULT | 0x80u);
    t0 = fx.board.clk.now_ns;
    /* Half full = 96 values = 32 samples of 3 axes at 250 Hz: the 32nd sample after the enable
     * (t0 is taken after the enable's read-back, up to 1 ms late). */
    CHECK_OK(sca3000_wait_int(&fx.dev, t0 + 1000000000u));
    CHECK(fx.board.clk.now_ns - t0 <= 32u * 4000000u);
    CHECK(fx.board.clk.now_ns - t0 > 31u * 4000000u - 1000000u);
    CHECK_OK(sca3000_int_status(&fx.dev, &st));
    CHECK_EQ_HEX(st, SCA3000_INT_RING_1_2);
    CHECK_OK(sca3000_ring_count(&fx.dev, &count));
    CHECK_EQ_INT(count, 96);
    CHECK_OK(sca3000_ring_read(&fx.dev, vals, SCA3000_RING_CAPACITY, &n));
    CHECK_EQ_INT(n, 96);
    /* 11-bit values in 13-bit units: floor(667/4)*4 = 664, floor(-333/4)*4 = -336, 1332. */
    for (i = 0; i + 2u < n; i += 3u) {
        CHECK_EQ_INT(vals[i], 664);
        CHECK_EQ_INT(vals[i + 1u], -336);
        CHECK_EQ_INT(vals[i + 2u], 1332);
    }
    CHECK_OK(sca3000_ring_count(&fx.dev, &count));
    CHECK_EQ_INT(count, 0);
    /* Nothing pending: the wait times out (INT was acknowledged). */
    CHECK_ERR(sca3000_wait_int(&fx.dev, fx.board.clk.now_ns + 10000000u), INC_ERR_TIMEOUT);
    /* A read of fewer values than stored leaves the rest. */
    fx_wait_ns(40000000u); /* 10 samples */
    CHECK_OK(sca3000_ring_read(&fx.dev, vals, 4, &n));
    CHECK_EQ_INT(n, 4);
    CHECK_EQ_INT(vals[3], 664);
    CHECK_OK(sca3000_ring_count(&fx.dev, &count));
    CHECK(count >= 26u);
    CHECK_OK(sca3000_ring_enable(&fx.dev, false));
    CHECK_EQ_HEX(fx.part.mode, SIM_SCA3000_MODE_DEFAULT);
    CHECK_NO_VIOLATIONS();

    /* One axis, divide by 2: one value every second sample; active-low INT. */
    REQUIRE(fx_setup(SIM_SCA3000_E04) == 0);
    fx_input(-0.3, 0.0, 1.0, 25.0);
    CHECK_OK(sca3000_ring_config(&fx.dev, SCA3000_OUT_CTRL_X, 2));
    CHECK_OK(sca3000_int_config(&fx.dev, SCA3000_INT_RING_3_4, false));
    CHECK_OK(sca3000_ring_enable(&fx.dev, true));
    t0 = fx.board.clk.now_ns;
    CHECK_OK(sca3000_wait_int(&fx.dev, t0 + 5000000000u));
    /* 144 values at 100 Hz / 2 = 2.88 s. */
    CHECK(fx.board.clk.now_ns - t0 > 2860000000u);
    CHECK(fx.board.clk.now_ns - t0 <= 2880000000u);
    CHECK_OK(sca3000_ring_read(&fx.dev, vals, SCA3000_RING_CAPACITY, &n));
    CHECK_EQ_INT(n, 144);
    CHECK_EQ_INT(vals[0], -152); /* -0.3 g = -150 counts -> floor(-37.5) = -38 */
    CHECK_EQ_INT(vals[143], -152);
    CHECK_OK(sca3000_int_status(&fx.dev, &st));
    CHECK_EQ_HEX(st, SCA3000_INT_RING_3_4 | SCA3000_INT_RING_1_2);
    CHECK_NO_VIOLATIONS();
}

/* Error model: a constant bias on X, seen exactly in the counts. */
static void bias_apply(void *ctx, const struct sim_inertial_input *in,
                       struct sim_inertial_input *out, uint64_t t_ns, double dt_s)
{
    const double *bias = ctx;
    (void)t_ns;
    (void)dt_s;
    *out = *in;
    out->accel_g[0] += bias[0];
}

/* Physics: a slow tilt about y, x = sin(theta) with theta growing 1 degree per 100 ms. */
static void tilt_sample(void *ctx, uint64_t t_ns, struct sim_inertial_input *in)
{
    (void)ctx;
    sim_inertial_at_rest(in);
    in->accel_g[0] = (double)(t_ns / 100000000u) * 0.01; /* 0.01 g per 100 ms step */
}

static void test_error_model_and_physics_hooks(void)
{
    static double bias[1] = {0.15};
    struct sim_error_model em = {bias_apply, bias};
    struct sim_physics ph = {tilt_sample, NULL};
    int16_t xyz[3];
    REQUIRE(fx_setup(SIM_SCA3000_D01) == 0);
    fx_input(0.5, 0.0, 1.0, 25.0);
    fx_wait_ns(SETTLE_NS);
    CHECK_OK(sca3000_read_accel(&fx.dev, xyz));
    CHECK_EQ_INT(xyz[0], 667); /* 0.5 g / 0.75 mg */
    sim_sca3000_set_error_model(&fx.part, &em);
    fx_wait_ns(SETTLE_NS);
    CHECK_OK(sca3000_read_accel(&fx.dev, xyz));
    CHECK_EQ_INT(xyz[0], 867);  /* (0.5 + 0.15) g / 0.75 mg = 866.67 */
    CHECK_EQ_INT(xyz[2], 1333); /* other axes untouched */
    sim_sca3000_set_error_model(&fx.part, NULL);
    sim_sca3000_set_physics(&fx.part, &ph);
    sim_clock_advance_to(&fx.board.clk, 1000000000u); /* t = 1 s: step 10 -> 0.10 g */
    CHECK_OK(sca3000_read_accel(&fx.dev, xyz));
    CHECK_EQ_INT(xyz[0], 133);                        /* 0.10 / 0.00075 = 133.3 */
    sim_clock_advance_to(&fx.board.clk, 2500000000u); /* step 25 -> 0.25 g */
    CHECK_OK(sca3000_read_accel(&fx.dev, xyz));
    CHECK_EQ_INT(xyz[0], 333);
    CHECK_NO_VIOLATIONS();
}

int main(void)
{
    UNIT_RUN(test_init_each_variant);
    UNIT_RUN(test_xyz_exact_counts);
    UNIT_RUN(test_temperature_d01);
    UNIT_RUN(test_modes_each_variant);
    UNIT_RUN(test_unlock_and_indirect);
    UNIT_RUN(test_ring_buffer);
    UNIT_RUN(test_error_model_and_physics_hooks);
    return unit_report();
}
