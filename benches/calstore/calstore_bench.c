/*
 * calstore_bench.c - host benchmark driver for the calibration storage (docs/benchmarks.md,
 * "Calibration storage"). Not a test: it measures, the tests assert.
 *
 * Sets up the reference geometry (1 KiB pages, 8-byte program unit, one page per slot), fills
 * both slots, then calls each measured function once through a noinline wrapper, so that
 *     valgrind --tool=callgrind --collect-atstart=no --toggle-collect=bench_<x> calstore_bench
 * counts the instructions of exactly one call: bench_crc = crc32_update over one record image
 * (652 bytes), bench_load = calstore_load, bench_save = calstore_save, both slots full (the last
 * two include the emulated flash driver's copying), on the reference geometry. It also prints
 * the flash operations of one load and one save for each geometry of the power-cut test.
 */
#include <stdio.h>
#include <string.h>

#include "inclino/calrec.h"
#include "inclino/calstore.h"
#include "inclino/crc32.h"
#include "inclino/simflash.h"

static uint8_t mem[2048];

/* The measured calls; noinline so callgrind can toggle on exactly these. */
__attribute__((noinline)) uint32_t bench_crc(const uint8_t *img);
__attribute__((noinline)) int bench_load(struct calstore *st, const struct calrec_binding *b,
                                         struct calrec *out);
__attribute__((noinline)) int bench_save(struct calstore *st, const struct calrec *rec);

uint32_t bench_crc(const uint8_t *img)
{
    return crc32_update(0, img, CALREC_OFF_CRC);
}

int bench_load(struct calstore *st, const struct calrec_binding *b, struct calrec *out)
{
    return calstore_load(st, b, out, NULL);
}

int bench_save(struct calstore *st, const struct calrec *rec)
{
    return calstore_save(st, rec, NULL);
}

static void print_ops(const char *what, const struct simflash_stats *s)
{
    printf("%-6s erases %u, program calls %u, program units %u, read calls %u, read bytes %u\n",
           what, (unsigned)s->erases, (unsigned)s->prog_calls, (unsigned)s->prog_units,
           (unsigned)s->read_calls, (unsigned)s->read_bytes);
}

struct bench_geo {
    uint32_t page, prog, pages;
};

/* Set up store + flash for g, fill both slots; 0 or an error. */
static int bench_setup(struct simflash *flash, struct calstore *store, const struct bench_geo *g,
                       const struct calrec *rec)
{
    struct simflash_geometry geo;
    struct calstore_config cfg;

    geo.page_size = g->page;
    geo.page_count = 2u * g->pages;
    geo.prog_size = g->prog;
    if (simflash_init(flash, mem, sizeof mem, &geo) != 0) {
        return 1;
    }
    memset(&cfg, 0, sizeof cfg);
    cfg.ops = &simflash_calstore_ops;
    cfg.ctx = flash;
    cfg.page_size = g->page;
    cfg.prog_size = g->prog;
    cfg.erased_value = CALSTORE_ERASED;
    cfg.slot_addr[0] = 0;
    cfg.slot_addr[1] = g->page * g->pages;
    cfg.slot_size = g->page * g->pages;
    if (calstore_init(store, &cfg) != 0 || calstore_save(store, rec, NULL) != 0 ||
        calstore_save(store, rec, NULL) != 0) {
        return 1;
    }
    return 0;
}

int main(void)
{
    /* The geometries of tests/calstore/test_powercut.c; the first is the reference. */
    static const struct bench_geo geos[] = {
        {1024u, 8u, 1u}, {256u, 4u, 3u}, {1024u, 2u, 1u}, {512u, 1u, 2u}, {1024u, 32u, 1u},
    };
    static struct simflash flash;
    static struct calstore store;
    static struct calrec rec, out;
    static uint8_t img[CALREC_IMAGE_SIZE];
    uint32_t crc = 0;
    unsigned i;
    int err = 0;

    calrec_set_default(&rec);
    rec.binding.family = CALREC_FAMILY_ADIS163XX;
    rec.binding.product = 16364u;
    rec.binding.serial = 0x1234u;
    if (calrec_encode(&rec, 1u, img, sizeof img) != 0) {
        return 1;
    }
    crc = bench_crc(img);

    for (i = 0; i < sizeof geos / sizeof geos[0]; i++) {
        if (bench_setup(&flash, &store, &geos[i], &rec) != 0) {
            return 1;
        }
        printf("page %u B, program unit %u B, %u page(s) per slot, both slots full:\n",
               (unsigned)geos[i].page, (unsigned)geos[i].prog, (unsigned)geos[i].pages);
        simflash_reset_stats(&flash);
        /* Only the first geometry goes through the measured wrappers (one call each). */
        err |= (i == 0) ? bench_load(&store, &rec.binding, &out)
                        : calstore_load(&store, &rec.binding, &out, NULL);
        print_ops("  load", simflash_get_stats(&flash));
        simflash_reset_stats(&flash);
        err |= (i == 0) ? bench_save(&store, &rec) : calstore_save(&store, &rec, NULL);
        print_ops("  save", simflash_get_stats(&flash));
    }
    printf(
        "record image %u bytes, CRC 0x%08X, sizeof(struct calstore) %u, sizeof(struct calrec) %u\n",
        (unsigned)CALREC_IMAGE_SIZE, (unsigned)crc, (unsigned)sizeof store, (unsigned)sizeof rec);
    return err != 0;
}
