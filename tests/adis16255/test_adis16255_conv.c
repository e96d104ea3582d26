/*
 * ADIS16255 pure functions: raw -> physical conversions (exact vectors computed with rational
 * arithmetic, rounding half away from zero), their error bound over the whole input domain,
 * GYRO_OFF encoding with saturation, SMPL_PRD rate/SCLK rules, SENS_AVG encoding, STATUS
 * decoding, and the argument errors.
 */
#include "inclino/adis16255.h"
#include "unit.h"

#include <string.h>

/* Exact value * 65536 of n * num / den, as a double for the bound check (tests only). */
static double exact_q16(long n, double num, double den)
{
    return (double)n * num * 65536.0 / den;
}

static void test_gyro(void)
{
    int32_t q = 0;
    /* (word, range, Q16.16 °/s): n * range * 5/273 °/s. */
    static const struct {
        uint16_t w;
        enum adis16255_range r;
        int32_t q;
    } v[] = {
        {0x0555, ADIS16255_RANGE_320, 6553600},   /* 1365 -> 100 °/s exactly */
        {0x3556, ADIS16255_RANGE_320, -13107200}, /* -2730 -> -200 °/s */
        {0x0001, ADIS16255_RANGE_320, 4801},      /* 0.0732600 °/s */
        {0x3FFF, ADIS16255_RANGE_320, -4801},
        {0x1FFF, ADIS16255_RANGE_320, 39326401},  /* +8191: 600.07 °/s */
        {0x2000, ADIS16255_RANGE_320, -39331202}, /* -8192 */
        {0x1110, ADIS16255_RANGE_320, 20971520},  /* 4368 -> 320 °/s */
        {0x0AAA, ADIS16255_RANGE_80, 3276800},    /* 2730 at ±80 -> 50 °/s */
        {0x0001, ADIS16255_RANGE_80, 1200},
        {0x0001, ADIS16255_RANGE_160, 2401},
        {0x2000, ADIS16255_RANGE_80, -9832801},
        {0x0000, ADIS16255_RANGE_320, 0},
        {0xC555, ADIS16255_RANGE_320, 6553600}, /* ND and EA are not data */
    };
    unsigned i;
    long n;
    double worst = 0.0;
    for (i = 0; i < sizeof(v) / sizeof(v[0]); i++) {
        CHECK_OK(adis16255_gyro_dps_from_word(v[i].w, v[i].r, &q));
        CHECK_EQ_INT(q, v[i].q);
    }
    /* The whole domain, every range: |error| <= 0.5 LSB of Q16.16. */
    for (n = -8192; n <= 8191; n++) {
        static const enum adis16255_range rs[3] = {ADIS16255_RANGE_80, ADIS16255_RANGE_160,
                                                   ADIS16255_RANGE_320};
        unsigned k;
        for (k = 0; k < 3u; k++) {
            double e;
            CHECK_OK(
                adis16255_gyro_dps_from_word((uint16_t)((unsigned long)n & 0x3FFFu), rs[k], &q));
            e = (double)q - exact_q16(n, 5.0 * (double)rs[k], 273.0);
            if (e < 0) e = -e;
            if (e > worst) worst = e;
        }
    }
    CHECK(worst <= 0.5);
    CHECK_ERR(adis16255_gyro_dps_from_word(0x0555, (enum adis16255_range)3, &q), INC_ERR_INVAL);
    CHECK_EQ_INT(q, 0);
    CHECK_ERR(adis16255_gyro_dps_from_word(0x0555, ADIS16255_RANGE_320, NULL), INC_ERR_NULL);
}

static void test_temp_supply_angle(void)
{
    long n;
    double worst = 0.0;
    CHECK_EQ_INT(adis16255_temp_c_from_word(0x0000), 1638400);   /* 25 °C */
    CHECK_EQ_INT(adis16255_temp_c_from_word(0x0001), 1647922);   /* 25.1453 */
    CHECK_EQ_INT(adis16255_temp_c_from_word(0x0FFF), 1628878);   /* -1 */
    CHECK_EQ_INT(adis16255_temp_c_from_word(0x0067), 2619205);   /* 103 -> 39.9659 °C */
    CHECK_EQ_INT(adis16255_temp_c_from_word(0x07FF), 21130713);  /* +2047 */
    CHECK_EQ_INT(adis16255_temp_c_from_word(0x0800), -17863436); /* -2048 */
    CHECK_EQ_INT(adis16255_temp_c_from_word(0xFF0F), -656494);   /* -241, D13:D12/ND/EA ignored */
    CHECK_EQ_INT(adis16255_supply_v_from_word(0x0000), 0);
    CHECK_EQ_INT(adis16255_supply_v_from_word(0x0001), 120);
    CHECK_EQ_INT(adis16255_supply_v_from_word(0x0AAA), 327680); /* 2730 -> 5.0000 V */
    CHECK_EQ_INT(adis16255_supply_v_from_word(0x0FFF), 491520); /* 4095 -> 7.5000 V */
    CHECK_EQ_INT(adis16255_supply_v_from_word(0x89D0), 301513); /* 2512 -> 4.6007 V, ND set */
    CHECK_EQ_INT(adis16255_angle_deg_from_word(0x0000), 0);
    CHECK_EQ_INT(adis16255_angle_deg_from_word(0x0001), 2401);
    CHECK_EQ_INT(adis16255_angle_deg_from_word(0x0110), 652959);   /* 272 -> 9.9634 ° */
    CHECK_EQ_INT(adis16255_angle_deg_from_word(0xBFFF), 39328802); /* 16383 */
    for (n = -2048; n <= 2047; n++) {
        double e = (double)adis16255_temp_c_from_word((uint16_t)((unsigned long)n & 0xFFFu)) -
                   (25.0 * 65536.0 + exact_q16(n, 1453.0, 10000.0));
        if (e < 0) e = -e;
        if (e > worst) worst = e;
    }
    for (n = 0; n <= 4095; n++) {
        double e = (double)adis16255_supply_v_from_word((uint16_t)n) - exact_q16(n, 18315.0, 1e7);
        if (e < 0) e = -e;
        if (e > worst) worst = e;
    }
    for (n = 0; n <= 16383; n++) {
        double e = (double)adis16255_angle_deg_from_word((uint16_t)n) - exact_q16(n, 10.0, 273.0);
        if (e < 0) e = -e;
        if (e > worst) worst = e;
    }
    CHECK(worst <= 0.5);
}

static void test_gyro_off(void)
{
    static const struct {
        int32_t q;
        uint16_t w;
        bool sat;
    } v[] = {
        {0, 0x000, false},          {65536, 0x037, false}, /* 1 °/s -> 54.6 -> 55 */
        {-65536, 0xFC9, false},                            /* -55 */
        {131072, 0x06D, false},                            /* 2 °/s -> 109.2 -> 109 */
        {163840, 0x089, false},  /* 2.5 °/s -> 136.5: tie, away from zero -> 137 */
        {-163840, 0xF77, false}, /* -137 */
        {600, 0x000, false},        {1200, 0x001, false},
        {-1200, 0xFFF, false},      {37 * 65536, 0x7E4, false}, /* 2020 */
        {38 * 65536, 0x7FF, true},                              /* 2075 -> 2047 */
        {-38 * 65536, 0x800, true},                             /* -2048 */
        {INT32_MAX, 0x7FF, true},   {INT32_MIN, 0x800, true},
    };
    unsigned i;
    uint16_t w;
    bool sat;
    long n;
    double worst = 0.0;
    for (i = 0; i < sizeof(v) / sizeof(v[0]); i++) {
        w = 0xFFFF;
        sat = !v[i].sat;
        CHECK_OK(adis16255_gyro_off_word_from_dps(v[i].q, &w, &sat));
        CHECK_EQ_HEX(w, v[i].w);
        CHECK_EQ_INT(sat, v[i].sat);
    }
    CHECK_EQ_INT(adis16255_gyro_off_dps_from_word(0x001), 1200);
    CHECK_EQ_INT(adis16255_gyro_off_dps_from_word(0xFFF), -1200);
    CHECK_EQ_INT(adis16255_gyro_off_dps_from_word(0x7FF), 2457000);
    CHECK_EQ_INT(adis16255_gyro_off_dps_from_word(0x800), -2458200);
    CHECK_EQ_INT(adis16255_gyro_off_dps_from_word(0xF93), -130832); /* -109 */
    /* Round trip: every count survives count -> °/s -> count. */
    for (n = -2048; n <= 2047; n++) {
        const uint16_t word = (uint16_t)((unsigned long)n & 0xFFFu);
        double e = (double)adis16255_gyro_off_dps_from_word(word) - exact_q16(n, 5.0, 273.0);
        if (e < 0) e = -e;
        if (e > worst) worst = e;
        CHECK_OK(
            adis16255_gyro_off_word_from_dps(adis16255_gyro_off_dps_from_word(word), &w, &sat));
        if (w != word || sat) {
            CHECK_EQ_HEX(w, word);
            break;
        }
    }
    CHECK(worst <= 0.5);
    CHECK_ERR(adis16255_gyro_off_word_from_dps(0, NULL, &sat), INC_ERR_NULL);
    CHECK_ERR(adis16255_gyro_off_word_from_dps(0, &w, NULL), INC_ERR_NULL);
}

static void test_rate_and_sclk(void)
{
    CHECK_EQ_INT(adis16255_sample_period_us(0x00), 1953);  /* 512 SPS */
    CHECK_EQ_INT(adis16255_sample_period_us(0x01), 3906);  /* 256 SPS default */
    CHECK_EQ_INT(adis16255_sample_period_us(0x07), 15624); /* 64 SPS (A4's example) */
    CHECK_EQ_INT(adis16255_sample_period_us(0x08), 17577);
    CHECK_EQ_INT(adis16255_sample_period_us(0x7F), 249984);
    CHECK_EQ_INT(adis16255_sample_period_us(0x80), 60540);
    CHECK_EQ_INT(adis16255_sample_period_us(0xFF), 7749120);
    CHECK(adis16255_sclk_fast_allowed(0x00));
    CHECK(adis16255_sclk_fast_allowed(0x07));
    CHECK(!adis16255_sclk_fast_allowed(0x08));
    CHECK(!adis16255_sclk_fast_allowed(0x80));
    CHECK(!adis16255_sclk_fast_allowed(0x81));
}

static void test_sens_avg_status(void)
{
    uint16_t w = 0x1234;
    struct adis16255_status s;
    unsigned b;
    CHECK_OK(adis16255_sens_avg_encode(ADIS16255_RANGE_320, 0, &w));
    CHECK_EQ_HEX(w, 0x0400);
    CHECK_OK(adis16255_sens_avg_encode(ADIS16255_RANGE_320, 6, &w));
    CHECK_EQ_HEX(w, 0x0406);
    CHECK_OK(adis16255_sens_avg_encode(ADIS16255_RANGE_160, 2, &w));
    CHECK_EQ_HEX(w, 0x0202);
    CHECK_OK(adis16255_sens_avg_encode(ADIS16255_RANGE_80, 4, &w));
    CHECK_EQ_HEX(w, 0x0104);
    w = 0x1234;
    CHECK_ERR(adis16255_sens_avg_encode(ADIS16255_RANGE_320, 7, &w), INC_ERR_INVAL);
    CHECK_ERR(adis16255_sens_avg_encode(ADIS16255_RANGE_160, 1, &w), INC_ERR_INVAL);
    CHECK_ERR(adis16255_sens_avg_encode(ADIS16255_RANGE_80, 3, &w), INC_ERR_INVAL);
    CHECK_ERR(adis16255_sens_avg_encode((enum adis16255_range)0, 4, &w), INC_ERR_INVAL);
    CHECK_EQ_HEX(w, 0x1234); /* untouched on error */
    CHECK_ERR(adis16255_sens_avg_encode(ADIS16255_RANGE_320, 2, NULL), INC_ERR_NULL);

    CHECK_OK(adis16255_status_decode(0x0000, &s));
    CHECK(!s.supply_low && !s.supply_high && !s.spi_fail && !s.overrange && !s.self_test_fail);
    CHECK_OK(adis16255_status_decode(0x0023, &s)); /* the staging driver's mask */
    CHECK(s.supply_low && s.supply_high && s.self_test_fail && !s.overrange && !s.spi_fail);
    CHECK_OK(adis16255_status_decode(0x035C, &s));
    CHECK(s.flash_update_fail && s.spi_fail && s.overrange && s.flash_checksum && s.alarm1 &&
          s.alarm2 && !s.supply_low && !s.self_test_fail);
    CHECK_EQ_HEX(s.raw, 0x035C);
    CHECK_ERR(adis16255_status_decode(0xFFFF, &s), INC_ERR_BUS); /* MISO stuck at 1 */
    CHECK_EQ_HEX(s.raw, 0xFFFF);
    CHECK_ERR(adis16255_status_decode(0x0080, &s), INC_ERR_BUS);
    CHECK_ERR(adis16255_status_decode(0x0400, &s), INC_ERR_BUS);
    CHECK_ERR(adis16255_status_decode(0, NULL), INC_ERR_NULL);
    CHECK(strcmp(adis16255_status_bit_name(0), "supply<4.75V") == 0);
    CHECK(strcmp(adis16255_status_bit_name(5), "self-test-fail") == 0);
    CHECK(strcmp(adis16255_status_bit_name(9), "alarm2") == 0);
    for (b = 10; b < 20; b++) {
        CHECK(strcmp(adis16255_status_bit_name(b), "reserved") == 0);
    }
}

int main(void)
{
    UNIT_RUN(test_gyro);
    UNIT_RUN(test_temp_supply_angle);
    UNIT_RUN(test_gyro_off);
    UNIT_RUN(test_rate_and_sclk);
    UNIT_RUN(test_sens_avg_status);
    return unit_report();
}
