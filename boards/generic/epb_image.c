/*
 * epb_image.c - the EPB application as the firmware image runs it (see epb_image.h).
 *
 * Sensor: an ADIS1640x on the bit-banged SPI engine, data-ready on DIO1, the part's own filter
 * off (SENS_AVG M = 0, +-300 deg/s): the application averages, and white samples keep the noise
 * term of the bound right (docs/epb-demo.md). Calibration: calstore over the MCU's flash.
 *
 * Two seams stay placeholders until a board port exists, like the GPIO seam of the Cortex-M
 * HAL port (README, "Porting to a new MCU"): the pin numbers below and the flash driver
 * (epb_flash_none: every access fails with INC_ERR_IO, so the application runs uncalibrated and
 * says so). The results go to epb_output, where the vehicle-network layer will pick them up;
 * the end-of-line steps are run on request through epb_diag (set by the diagnostic layer).
 */
#include "epb_image.h"

#include <stddef.h>

#include "inclino/adis_imu.h"
#include "inclino/app.h"
#include "inclino/calstore.h"
#include "inclino/compiler.h"
#include "inclino/spi_bitbang.h"

/* Pin numbers of the board (placeholders; the MCU family port numbers its pins). */
#define EPB_PIN_SCLK 0u
#define EPB_PIN_MOSI 1u
#define EPB_PIN_MISO 2u
#define EPB_PIN_CS 3u
#define EPB_PIN_DR 4u

/* Calibration flash: two slots of one 1 KiB page each, programmed in 8-byte units (typical MCU
 * data-flash geometry; placeholders until the board port gives the real ones). */
#define EPB_FLASH_PAGE 1024u
#define EPB_FLASH_PROG 8u
#define EPB_FLASH_SLOT0 0u
#define EPB_FLASH_SLOT1 1024u

/* Retry period after a failed sensor bring-up, ms. */
#define EPB_RETRY_MS 100u

static int flash_none_read(void *ctx, uint32_t addr, uint8_t *buf, uint32_t len)
{
    (void)ctx;
    (void)addr;
    (void)buf;
    (void)len;
    return INC_ERR_IO;
}

static int flash_none_program(void *ctx, uint32_t addr, const uint8_t *buf, uint32_t len)
{
    (void)ctx;
    (void)addr;
    (void)buf;
    (void)len;
    return INC_ERR_IO;
}

static int flash_none_erase(void *ctx, uint32_t addr)
{
    (void)ctx;
    (void)addr;
    return INC_ERR_IO;
}

static const struct calstore_flash_ops epb_flash_none = {flash_none_read, flash_none_program,
                                                         flash_none_erase};

const struct calstore_config *epb_image_no_flash(void)
{
    static const struct calstore_config fc = {&epb_flash_none, NULL,
                                              EPB_FLASH_PAGE,  EPB_FLASH_PROG,
                                              CALSTORE_ERASED, {EPB_FLASH_SLOT0, EPB_FLASH_SLOT1},
                                              EPB_FLASH_PAGE};
    return &fc;
}

volatile struct epb_diag epb_diag;
/* The newest result, written in place by app_measure when a block completes (no copy of it: the
 * small images' RAM); epb_output_count counts the complete results. Readers run in the main loop
 * after a result (the board's per_result hook): app_measure writes it while a block completes,
 * so a reader in another context (an interrupt) would need its own copy taken here. */
struct app_result epb_output;
volatile uint32_t epb_output_count;

struct calrec_binding epb_identity;

static struct spi_bitbang spi;
static struct adis_imu imu;
static struct calstore store;
static struct app app;

#if EPB_IMAGE_EOL
/* The end-of-line faces stay static: they live from the first FACE request to the SAVE, across
 * the measurements in between and across a sensor re-init. faces_done has bit f set while
 * faces[f] holds a face measured since the last SAVE. The record the SAVE builds lives in the
 * application's own record (app_eol_fit_save), not on a stack. */
static struct app_face faces[CAL_FACES];
static uint32_t faces_done;

#define EPB_FACES_ALL ((1u << CAL_FACES) - 1u)
#endif

/* INC_NOINLINE (the diagnostic steps, app_start, measure): their locals must not join the frame
 * of the main loop, which is on every path, nor each other's (link-time optimisation inlines
 * across modules; docs/build.md, "Stack analysis"). */

int epb_image_adis_up(struct adis_imu *dev, const struct epb_image_board *b)
{
    struct adis_imu_cfg ic;
    int err;
    ic.hal = b->hal;
    ic.bus = b->spi;
    ic.cs = b->cs;
    ic.variant = (uint8_t)ADIS_IMU_ANY;
    ic.dr_pin = b->dr;
    ic.dr_line = (uint8_t)ADIS_IMU_DR_DIO1;
    ic.dr_active_low = false;
    ic.reset_at_init = false;
    ic.self_test_at_init = true;
    err = adis_imu_init(dev, &ic);
    if (err == INC_OK) {
        err = adis_imu_set_filter(dev, 0u, ADIS_IMU_RANGE_300);
    }
    return err;
}

#if EPB_IMAGE_EOL
/* The end-of-line requests (epb_image.h, epb_diag). The application, not ready after a save,
 * makes the main loop start it again on what the store now holds. */
static INC_NOINLINE int diag_face(uint32_t face, uint32_t n)
{
    int err;
    faces_done &= ~(1u << face);
    err = app_eol_face(&app, n, 3277, FX_Q16_INT(2), &faces[face]);
    if (err == INC_OK) {
        faces_done |= 1u << face;
    }
    return err;
}

static INC_NOINLINE int diag_save(void)
{
    int err = INC_ERR_STATE;
    if (faces_done == EPB_FACES_ALL) {
        err = app_eol_fit_save(&app, faces, &store, NULL);
        faces_done = 0u;
    }
    return err;
}

/* Each request in a frame of its own (diag_face, diag_save): neither joins the other's path. */
static void diag_serve(void)
{
    const uint32_t cmd = epb_diag.cmd;
    const uint32_t face = epb_diag.face;
    int err = INC_ERR_INVAL;
    if (cmd == EPB_DIAG_FACE && face < CAL_FACES) {
        err = diag_face(face, epb_diag.n);
    } else if (cmd == EPB_DIAG_SAVE) {
        err = diag_save();
    }
    epb_diag.status = err;
    epb_diag.cmd = EPB_DIAG_NONE;
}
#else
/* No end of line on the device (epb_image.h): FACE and SAVE are refused, the rest as above. */
static void diag_serve(void)
{
    const uint32_t cmd = epb_diag.cmd;
    epb_diag.status = cmd == EPB_DIAG_FACE || cmd == EPB_DIAG_SAVE ? INC_ERR_UNSUPPORTED
                                                                   : INC_ERR_INVAL;
    epb_diag.cmd = EPB_DIAG_NONE;
}
#endif

void epb_image_run(const struct hal *hal)
{
    static const struct spi_bitbang_cfg sc = {NULL, EPB_PIN_SCLK, EPB_PIN_MOSI, EPB_PIN_MISO};
    struct spi_bitbang_cfg c = sc;
    struct epb_image_board b;
    c.hal = hal;
    b.hal = hal;
    b.spi = &spi.bus;
    b.cs = EPB_PIN_CS;
    b.dr = EPB_PIN_DR;
    b.per_result = NULL;
    b.store = NULL;
    if (spi_bitbang_init(&spi, &c) != INC_OK) {
        for (;;) {
        }
    }
    epb_image_run_on(&b);
}

/* The application started on the store: app_init copies the configuration, so it lives here
 * only ([ADI-EPB]'s budget and the default stillness thresholds at the ADIS default 819.2 SPS,
 * the same on every start). */
static INC_NOINLINE int app_start(void)
{
    struct app_cfg cfg;
    const struct sensor sensor = {&adis_imu_sensor_ops, &imu}; /* app_init copies it too */
    int err;
    (void)app_cfg_default(&cfg, adis_imu_sample_rate_msps(ADIS_IMU_SMPL_PRD_DEFAULT));
    err = app_init(&app, &cfg, &sensor, &store);
    if (err == INC_OK) {
        epb_identity = app.id;
    }
    return err;
}

/* One result: its own frame (below the main loop's, not inside it). */
static INC_NOINLINE int measure(struct app_result *r)
{
    return app_measure(&app, r);
}

void epb_image_run_on(const struct epb_image_board *board)
{
    const struct hal *hal = board->hal;
    for (;;) {
        if (epb_image_adis_up(&imu, board) != INC_OK ||
            calstore_init(&store, board->store != NULL ? board->store : epb_image_no_flash()) !=
                INC_OK ||
            app_start() != INC_OK) {
            hal_delay_ms(hal, EPB_RETRY_MS);
            continue;
        }
        while (measure(&epb_output) == INC_OK) {
            epb_output_count = epb_output_count + 1u;
            if (board->per_result != NULL) {
                board->per_result();
            }
            if (epb_diag.cmd != EPB_DIAG_NONE) {
                diag_serve();
                app_restart(&app);
            }
        }
    }
}
