/* lf_calrec.c - libFuzzer target: the calibration record image (firmware/signal/calrec,
 * calrec_decode). The first byte chooses whether the CRC is made right before decoding (so the
 * mutations reach the version, binding and range checks behind it) and which binding is
 * expected (the image's own, or a fixed one). Properties: a refused image leaves the safe
 * default (valid false, seq 0); an accepted one is valid, re-encodes to the same bytes, and
 * calrec_check_image agrees with calrec_decode. */
#include "inclino/calrec.h"
#include "inclino/crc32.h"
#include "inclino/error.h"

#include <stdlib.h>
#include <string.h>

static uint8_t img[CALREC_IMAGE_SIZE + 64u];
static uint8_t again[CALREC_IMAGE_SIZE];
static struct calrec rec;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct calrec_binding b;
    uint32_t seq = 12345u;
    size_t len;
    int err, check;
    if (size < 1) return 0;
    len = size - 1u;
    if (len > sizeof img) len = sizeof img;
    memset(img, 0, sizeof img);
    memcpy(img, data + 1, len);
    if ((data[0] & 1u) && len >= CALREC_IMAGE_SIZE) {
        calrec_put_le32(&img[CALREC_OFF_CRC], crc32_update(0, img, CALREC_OFF_CRC));
    }
    if ((data[0] & 2u) == 0u || calrec_image_binding(img, len, &b) != INC_OK) {
        memset(&b, 0, sizeof b);
        b.family = CALREC_FAMILY_ADIS163XX;
        b.product = 16405u;
    }
    err = calrec_decode(img, len, &b, &rec, &seq);
    check = calrec_check_image(img, len, &b);
    if ((err == INC_OK) != (check == INC_OK)) abort();
    if (err != INC_OK) {
        if (rec.valid || seq != 0u) abort();
        return 0;
    }
    if (!rec.valid) abort();
    if (calrec_encode(&rec, seq, again, sizeof again) != INC_OK) abort();
    if (memcmp(again, img, CALREC_IMAGE_SIZE) != 0) abort();
    return 0;
}
