/*
 * image_main.c - the calibration-storage measurement image (cross targets only; never run).
 *
 * Links what a product links to use the store: calstore_init, calstore_load at boot and
 * calstore_save after calibration, over a trivial flash driver. The build's size report
 * (calstore_image.size.txt: flash per module) and stack report (calstore_image.stack.txt:
 * deepest static call chain from main) are the figures quoted in docs/benchmarks.md,
 * "Calibration storage". The driver's own frames are not included there (calls through the
 * ops table are not followed by the stack report); this one is a leaf of a few bytes.
 */
#include <stddef.h>
#include <stdint.h>

#include "inclino/calstore.h"

#define IMG_PAGE 1024u

static uint8_t flash_array[2u * IMG_PAGE]; /* stands in for the MCU's flash */

static int drv_read(void *ctx, uint32_t addr, uint8_t *buf, uint32_t len)
{
    uint32_t i;
    (void)ctx;
    for (i = 0; i < len; i++) {
        buf[i] = flash_array[addr + i];
    }
    return 0;
}

static int drv_program(void *ctx, uint32_t addr, const uint8_t *buf, uint32_t len)
{
    uint32_t i;
    (void)ctx;
    for (i = 0; i < len; i++) {
        flash_array[addr + i] &= buf[i];
    }
    return 0;
}

static int drv_erase(void *ctx, uint32_t addr)
{
    uint32_t i;
    (void)ctx;
    for (i = 0; i < IMG_PAGE; i++) {
        flash_array[addr + i] = 0xFFu;
    }
    return 0;
}

static const struct calstore_flash_ops drv = {drv_read, drv_program, drv_erase};

/* What an application holds: the store and the loaded record (both in .bss). */
static struct calstore store;
static struct calrec cal;

int main(void);

int main(void)
{
    struct calstore_config cfg = {
        .ops = &drv,
        .ctx = NULL,
        .page_size = IMG_PAGE,
        .prog_size = 8u,
        .erased_value = CALSTORE_ERASED,
        .slot_addr = {0u, IMG_PAGE},
        .slot_size = IMG_PAGE,
    };
    struct calrec_binding id = {CALREC_FAMILY_ADIS163XX, 16364u, 0u, 1u, 2u, 3u};
    int err = calstore_init(&store, &cfg);
    if (err == 0) {
        err = calstore_load(&store, &id, &cal, NULL);
        if (err != 0) {
            cal.binding = id;
            err = calstore_save(&store, &cal, NULL);
        }
    }
    return err;
}
