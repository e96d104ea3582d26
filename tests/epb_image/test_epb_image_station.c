/*
 * The EPB image without the on-device end of line (EPB_IMAGE_EOL 0, the S32K116 image's build,
 * boards/generic/epb_image.h) on the simulated board with an ADIS16405 carrying offsets and gain
 * errors: the station's end of line as docs/boards.md describes it.
 *   - FACE and SAVE are refused with INC_ERR_UNSUPPORTED, another request with INC_ERR_INVAL,
 *     and the loop goes on;
 *   - epb_identity is the part's identity;
 *   - uncalibrated, the station reads the block means (epb_output) on each of the six faces, the
 *     second result after each turn, and checks each against the face within the part's errors;
 *   - it fits offset, gain and gyro offset from them (app_eol_six_position, as the station's fit
 *     would) and programs the record bound to epb_identity into the data flash while the MCU is
 *     off (calstore_save on the board's store geometry: the two 2 KiB sectors and 8-byte phrases
 *     of the S32K1 images, calstation dflash's bytes);
 *   - power cycle: the image starts on the record: calibrated, and in the parked car on a 10 %
 *     grade the slope is within 0.1 deg of the truth and inside its bound.
 */
#include <math.h>
#include <setjmp.h>
#include <string.h>

#include "epb_image_test.h"
#include "inclino/sim/epb_rig_state.h"
#include "inclino/simflash.h"
#include "unit.h"

#if EPB_IMAGE_EOL
#error "this test is built with EPB_IMAGE_EOL=0"
#endif

#define PI 3.14159265358979323846
#define SECTOR 2048u
#define PHRASE 8u

static struct epb_rig rig;
static jmp_buf done_jmp;
static struct simflash dflash;
static uint8_t dflash_mem[2u * SECTOR];

enum step { S_FIRST, S_SAVE, S_OTHER, S_FACES, S_DONE, S_PARKED };

static enum step step = S_FIRST;
static int face_k;
static int after_turn;
static int32_t status_log[3];
static struct app_face faces[CAL_FACES];
static struct app_result first, parked;
static int parked_results;

static void request(uint32_t cmd, uint32_t face, uint32_t n)
{
    epb_diag.face = face;
    epb_diag.n = n;
    epb_diag.status = 1;
    epb_diag.cmd = cmd;
}

static void turn(int face)
{
    epb_rig_station(&rig, face, 25.0);
    after_turn = 0;
}

static void hook(void)
{
    CHECK_EQ_INT(epb_diag.cmd, EPB_DIAG_NONE);
    switch (step) {
    case S_FIRST:
        first = epb_output;
        request(EPB_DIAG_FACE, 0u, 256u);
        step = S_SAVE;
        break;
    case S_SAVE:
        status_log[0] = epb_diag.status;
        request(EPB_DIAG_SAVE, 0u, 0u);
        step = S_OTHER;
        break;
    case S_OTHER:
        status_log[1] = epb_diag.status;
        request(7u, 0u, 0u);
        step = S_FACES;
        face_k = 0;
        turn(face_k);
        break;
    case S_FACES:
        if (face_k == 0 && after_turn == 0) {
            status_log[2] = epb_diag.status;
        }
        /* the first result after a turn may have seen the part move: take the second */
        if (++after_turn == 2) {
            struct app_face *f = &faces[face_k];
            memcpy(f->accel_g, epb_output.accel_g, sizeof f->accel_g);
            memcpy(f->gyro_dps, epb_output.gyro_dps, sizeof f->gyro_dps);
            f->temp_c = epb_output.temp_c;
            f->n = epb_output.n;
            f->flags = SENSOR_S_HAVE_GYRO | SENSOR_S_HAVE_TEMP;
            CHECK_EQ_INT(epb_output.motion_windows, 0);
            CHECK_EQ_INT(epb_output.sensor_errors, 0);
            if (++face_k == CAL_FACES) {
                step = S_DONE;
                longjmp(done_jmp, 1); /* the station switches the MCU off */
            }
            turn(face_k);
        }
        break;
    case S_DONE: break;
    case S_PARKED:
        if (++parked_results == 2) {
            parked = epb_output;
            longjmp(done_jmp, 2);
        }
        break;
    }
}

static double q16(int32_t v)
{
    return (double)v / 65536.0;
}

static void test_station_end_of_line(void)
{
    static struct calstore_config sc;
    static struct epb_image_board b;
    static struct calstore probe;
    static struct calrec rec;
    struct sim_calpart_params part;
    struct simflash_geometry g;
    struct epb_rig_vehicle v;
    double truth;
    int i, k;
    epb_test_part(&part);
    REQUIRE(epb_rig_init(&rig, EPB_RIG_ADIS16405, &part, 12u) == INC_OK);
    g.page_size = SECTOR;
    g.page_count = 2u;
    g.prog_size = PHRASE;
    REQUIRE(simflash_init(&dflash, dflash_mem, sizeof dflash_mem, &g) == INC_OK);
    REQUIRE(simflash_calstore_config(&dflash, &sc) == INC_OK); /* a slot per sector */
    epb_test_board(&b, &rig, hook, &sc);
    if (setjmp(done_jmp) == 0) {
        epb_image_run_on(&b); /* never returns; the hook jumps back when the faces are read */
    }
    REQUIRE(step == S_DONE);
    CHECK((first.flags & APP_F_NOT_CALIBRATED) != 0u);
    CHECK(!first.valid);
    CHECK_ERR(status_log[0], INC_ERR_UNSUPPORTED); /* FACE */
    CHECK_ERR(status_log[1], INC_ERR_UNSUPPORTED); /* SAVE */
    CHECK_ERR(status_log[2], INC_ERR_INVAL);       /* cmd 7 */
    CHECK_EQ_INT(epb_identity.family, CALREC_FAMILY_ADIS163XX);
    CHECK_EQ_INT(epb_identity.product, 16405);
    /* The raw face means: the face's +-1 g on its axis through the part's offset and gain,
     * about 0 g on the others (the offsets), each within 2 mg (noise over a block, the ideal
     * part's other errors). */
    for (k = 0; k < CAL_FACES; k++) {
        double dir[3];
        epb_rig_face_dir(k, dir);
        for (i = 0; i < 3; i++) {
            const double scale = i == 0 ? 1.02 : i == 2 ? 0.99 : 1.0;
            const double bias = i == 0 ? 0.02 : i == 1 ? -0.01 : 0.015;
            CHECK(fabs(q16(faces[k].accel_g[i]) - (scale * dir[i] + bias)) < 0.002);
        }
        CHECK(faces[k].n >= 1024u);
    }
    /* The station's fit and the probe: the record into the data flash, MCU off. */
    calrec_set_default(&rec);
    REQUIRE(app_eol_six_position(faces, &rec) == INC_OK);
    rec.binding = epb_identity;
    REQUIRE(calstore_init(&probe, &sc) == INC_OK);
    REQUIRE(calstore_save(&probe, &rec, NULL) == INC_OK);
    /* Power cycle onto the record, the car parked on a 10 % grade. */
    truth = atan(0.1) * 180.0 / PI;
    epb_rig_vehicle_default(&v);
    v.slope_deg = truth;
    v.idle_rpm = 0.0;
    v.bump_rate_hz = 0.0;
    epb_rig_park(&rig, &v);
    step = S_PARKED;
    if (setjmp(done_jmp) == 0) {
        epb_image_run_on(&b);
    }
    REQUIRE(parked_results == 2);
    CHECK_EQ_INT(parked.cal_status, INC_OK);
    /* one temperature (this fit): no temperature model, flagged so, as on-device (the
     * station's three-point record loads the same way: tests/ftfc, ftfc_dflash) */
    CHECK_EQ_HEX(parked.flags, APP_F_TEMP_UNCOMP);
    CHECK_EQ_INT(epb_rig_violations(&rig), 0);
    /* uncorrected, the 20 mg x offset alone would be 1.1 deg of slope error */
    CHECK(fabs(q16(parked.slope.slope_deg) - truth) <= q16(parked.slope.bound_deg));
    CHECK(fabs(q16(parked.slope.slope_deg) - truth) < 0.1);
}

int main(void)
{
    UNIT_RUN(test_station_end_of_line);
    return unit_report();
}
