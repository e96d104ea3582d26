/*
 * The calibration record image as the host tools read it from a file (imu_replay --record,
 * calstation show): the committed example_adis16405.rec, mutated. tests/calstore already proves
 * every single-bit flip and the one-byte-short image; this adds what a file brings: every
 * truncation length, and every byte replaced by each interesting byte (multi-bit changes).
 * Each must be refused with INC_ERR_INVAL (short), INC_ERR_VERSION (version/length word) or
 * INC_ERR_CRC (anything else, the magic included), leaving the safe default (valid = false,
 * seq 0) - never a valid record from a changed image.
 */
#include "fuzz_mut.h"
#include "inclino/calrec.h"
#include "unit.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef REPLAY_DIR
#error "REPLAY_DIR must be defined (tests/epb/replay)"
#endif

static struct calrec def;

static void binding_of(const uint8_t *img, struct calrec_binding *b)
{
    b->family = calrec_get_le32(&img[CALREC_OFF_BINDING]);
    b->product = calrec_get_le32(&img[CALREC_OFF_BINDING + 4u]);
    b->revision = calrec_get_le32(&img[CALREC_OFF_BINDING + 8u]);
    b->serial = calrec_get_le32(&img[CALREC_OFF_BINDING + 12u]);
    b->lot_id1 = calrec_get_le32(&img[CALREC_OFF_BINDING + 16u]);
    b->lot_id2 = calrec_get_le32(&img[CALREC_OFF_BINDING + 20u]);
}

static bool is_default(const struct calrec *r)
{
    return !r->valid && memcmp(&r->acc_offset, &def.acc_offset, sizeof r->acc_offset) == 0 &&
           memcmp(&r->acc_gain, &def.acc_gain, sizeof r->acc_gain) == 0 &&
           memcmp(&r->binding, &def.binding, sizeof r->binding) == 0;
}

static void test_image_file(void)
{
    size_t len = 0, i, cases = 0;
    uint8_t *seed = (uint8_t *)fuzz_read_file(REPLAY_DIR "/example_adis16405.rec", &len);
    static uint8_t img[CALREC_IMAGE_SIZE];
    struct calrec_binding b;
    struct calrec out;
    uint32_t seq = 0;
    unsigned v;
    calrec_set_default(&def);
    REQUIRE(seed != NULL && len == CALREC_IMAGE_SIZE);
    binding_of(seed, &b);
    REQUIRE(calrec_decode(seed, len, &b, &out, &seq) == INC_OK);
    CHECK(out.valid);
    CHECK(seq > 0u);
    /* Every truncation (what a short file gives). */
    for (i = 0; i < CALREC_IMAGE_SIZE; i++) {
        out.valid = true;
        seq = 77u;
        CHECK_ERR(calrec_decode(seed, i, &b, &out, &seq), INC_ERR_INVAL);
        CHECK(is_default(&out));
        CHECK_EQ_INT(seq, 0);
        cases++;
    }
    /* Every byte replaced by each interesting byte. */
    for (i = 0; i < CALREC_IMAGE_SIZE; i++) {
        for (v = 0; v < FUZZ_N_BYTES; v++) {
            int err, want;
            if (seed[i] == fuzz_bytes[v]) continue;
            memcpy(img, seed, sizeof img);
            img[i] = fuzz_bytes[v];
            out.valid = true;
            seq = 77u;
            err = calrec_decode(img, sizeof img, &b, &out, &seq);
            want = (i >= CALREC_OFF_VERSION && i < CALREC_OFF_SEQ) ? INC_ERR_VERSION : INC_ERR_CRC;
            if (err != want) {
                unit_fail(__FILE__, __LINE__, "byte %zu := 0x%02X gave %d, want %d", i,
                          fuzz_bytes[v], err, want);
            }
            unit_checks++;
            CHECK(is_default(&out));
            CHECK_EQ_INT(seq, 0);
            CHECK_ERR(calrec_check_image(img, sizeof img, &b), want);
            cases++;
        }
    }
    printf("calrec image: %zu cases\n", cases);
    CHECK(cases > 6000u);
    free(seed);
}

int main(void)
{
    UNIT_RUN(test_image_file);
    return unit_report();
}
