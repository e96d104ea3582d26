/*
 * epb_image.h - the part of the inclino_epb firmware image shared by every target: board
 * wiring placeholders, the flash seam, and the EPB main loop on top of a HAL (epb_image.c).
 * Each target's main() brings up its HAL and calls epb_image_run().
 */
#ifndef INCLINO_EPB_IMAGE_H
#define INCLINO_EPB_IMAGE_H

#include "inclino/adis_imu.h"
#include "inclino/app.h"
#include "inclino/calstore.h"
#include "inclino/hal.h"
#include "inclino/spi.h"

/* What a board gives the EPB application: its HAL, the SPI bus the ADIS part is on (any engine),
 * the part's chip select and data-ready pins, a hook called once per result (NULL: none;
 * the S32K1 boards refresh their watchdog there), and the calibration store's flash (NULL: the
 * placeholder whose every access fails, so the application runs uncalibrated and says so; the
 * S32K1 boards give the FTFC data flash). */
struct epb_image_board {
    const struct hal *hal;
    const struct spi_bus *spi;
    hal_pin_t cs;
    hal_pin_t dr;
    void (*per_result)(void);
    const struct calstore_config *store;
};

/* The ADIS part of a board up as the images run it: any 1636x/1640x variant on the board's SPI
 * bus, chip select and data-ready (DIO1, active high), self-test at init, no filter, +-300 deg/s
 * (the application averages). 0 or the driver's error. */
int epb_image_adis_up(struct adis_imu *dev, const struct epb_image_board *b);

/* The placeholder flash of the calibration store: two 1 KiB slots whose every access fails with
 * INC_ERR_IO (the application runs uncalibrated and flags it). */
const struct calstore_config *epb_image_no_flash(void);

/*
 * EPB_IMAGE_EOL (a compile definition of the image, default 1): 1 gives the on-device end of
 * line below; 0 leaves it out (the S32K116 image: its flash budget, docs/boards.md). Without it
 * the record comes from the station: it reads the block means of an uncalibrated part from
 * epb_output face by face and soak by soak, and epb_identity; calstation fits the record and
 * writes it as a data-flash image (`calstation dflash`) that the probe programs
 * (docs/calibration.md, 4.6).
 *
 * The end-of-line requests the diagnostic layer makes (epb_diag), served by the main loop after
 * the next result, one at a time: the requester writes face and n, then cmd; the loop writes
 * status, then clears cmd.
 *   EPB_DIAG_FACE  average face `face` (enum cal_face) for n samples held still (50 mg / 2 deg/s
 *                  span at most): status app_eol_face's code (INC_ERR_INVAL also for a face out of
 *                  range); a failed measurement forgets that face.
 *   EPB_DIAG_SAVE  with all six faces measured since the last save: offset, gain and gyro offset
 *                  from them, stored in the calibration store (app_eol_fit_save); the faces are
 *                  then forgotten and the application starts again on what the store holds (the
 *                  new record; after a failed save the one before). INC_ERR_STATE (faces kept) when
 *                  a face is missing.
 * With EPB_IMAGE_EOL 0 both are refused with INC_ERR_UNSUPPORTED. Any other cmd: INC_ERR_INVAL.
 * A sensor re-init keeps the faces.
 */
#ifndef EPB_IMAGE_EOL
#define EPB_IMAGE_EOL 1
#endif

enum epb_diag_cmd {
    EPB_DIAG_NONE = 0,
    EPB_DIAG_FACE = 1,
    EPB_DIAG_SAVE = 2,
};

struct epb_diag {
    uint32_t cmd; /* enum epb_diag_cmd; cleared when done */
    uint32_t face;
    uint32_t n;
    int32_t status; /* result of the last request */
};

extern volatile struct epb_diag epb_diag;
/* The identity of the part the application last started on (zero before the first start): the
 * binding a record must carry (calrec.h), six little-endian words as struct calrec_binding. */
extern struct calrec_binding epb_identity;
/* The newest result (see epb_image.c) and the count of results so far. */
extern struct app_result epb_output;
extern volatile uint32_t epb_output_count;

/* Run the EPB application on a board; never returns. */
void epb_image_run_on(const struct epb_image_board *board);

/* Run the EPB application on hal with the generic board's placeholder pins and the bit-banged
 * engine; never returns. */
void epb_image_run(const struct hal *hal);

#endif /* INCLINO_EPB_IMAGE_H */
