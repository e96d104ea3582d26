/*
 * calrec.h - the calibration record: what is calibrated, for which sensor, and its byte image.
 *
 * One record belongs to ONE sensor part (an SCA3000, an ADIS1625x gyro or an ADIS1636x/1640x
 * IMU) and is bound to it by struct calrec_binding. A module with two parts keeps two records
 * (two calstore instances). Sections a part does not have (the gyro of an SCA3000, the
 * accelerometer of an ADIS16255) hold the identity values of calrec_set_default().
 *
 * Fixed-point conventions (docs/fixed-point.md was not on main when this was written; these are
 * the project conventions given for the record and are repeated in docs/calibration-storage.md):
 *   Q16.16  physical quantities: int32 = value * 2^16. g for acceleration, deg/s for rate,
 *           degC for temperature. Resolution 15.3 ug / 15.3 udeg/s / 15.3 udegC.
 *   Q30     unitless gains and ratios: int32 = value * 2^30, range [-2, 2), resolution 0.93e-9.
 * Every coefficient field is an int32 with one of these two formats, stated beside it. The
 * accelerometer terms act on the reading already converted to g with the part's NOMINAL
 * sensitivity, so gains are close to 1.0.
 *
 * Byte image (format version 2, CALREC_IMAGE_SIZE = 656 bytes; the full table is in
 * docs/calibration-storage.md): every field is a 32-bit little-endian word, in the order of the
 * struct declarations below (arrays row-major, i.e. last index fastest), preceded by the header
 * and followed by the CRC-32:
 *     0 magic "ICAL"   4 version   8 length   12 seq   16..39 binding   40..651 coefficients
 *   652 CRC-32 of bytes 0..651.
 * The struct is never copied to or from flash as memory: its byte order does not matter, the
 * codec writes each field explicitly as a little-endian word. (calrec.c walks the struct by word
 * index and asserts at compile time that it has no padding before `valid`.)
 *
 * Invariant of ALL format versions (so that any firmware can judge any record's integrity and
 * age): magic at 0, version at 4, length (total bytes including the CRC, a multiple of 4) at 8,
 * sequence number at 12, and the CRC-32 of bytes [0, length-4) stored at length-4.
 *
 * Version rule: CALREC_VERSION changes on ANY change of field order, count, width, unit, Q format
 * or meaning. A firmware accepts exactly the versions it has a decoder for (today: 2); any other
 * version is INC_ERR_VERSION and the sensor runs uncalibrated. See docs/calibration-storage.md.
 */
#ifndef INCLINO_CALREC_H
#define INCLINO_CALREC_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "inclino/error.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Image header -------------------------------------------------------------------------- */

#define CALREC_MAGIC 0x4C414349u /* bytes 'I' 'C' 'A' 'L' in little-endian order */
/* The format version this firmware writes and reads. History: 1 = first layout; 2 = the same
 * layout plus the temperature-model kind LORENTZ_CUBIC, and the polynomial kinds (LINEAR,
 * PARABOLA, LORENTZ_CUBIC) held at the ends of [t_ref - t_span, t_ref + t_span] (v1 left their
 * extrapolation unspecified). docs/calibration-storage.md 2.4. */
#define CALREC_VERSION 2u

#define CALREC_OFF_MAGIC 0u /* byte offsets of the header words, valid for every version */
#define CALREC_OFF_VERSION 4u
#define CALREC_OFF_LENGTH 8u
#define CALREC_OFF_SEQ 12u
#define CALREC_HEADER_SIZE 16u
#define CALREC_MIN_SIZE 20u /* header + CRC: the smallest length any version can declare */

/* Version-2 layout (unchanged from version 1): byte offset of each field group (every word
 * little-endian). */
#define CALREC_OFF_BINDING 16u    /* 6 words: family, product, revision, serial, lot_id1, lot_id2 */
#define CALREC_OFF_ACC_OFFSET 40u /* 3 words, x y z */
#define CALREC_OFF_ACC_GAIN 52u   /* 3 words */
#define CALREC_OFF_ACC_MISALIGN 64u /* 9 words, row-major [r][c] */
#define CALREC_OFF_ACC_NONLIN 100u  /* 12 words, [axis][c0..c3] */
#define CALREC_OFF_ACC_TBIAS 148u   /* 3 models of CALREC_TMODEL_SIZE bytes, x y z */
#define CALREC_OFF_ACC_TSCALE 388u  /* 3 models */
#define CALREC_OFF_GYRO_OFFSET 628u /* 3 words */
#define CALREC_OFF_GYRO_SCALE 640u  /* 3 words */
#define CALREC_OFF_CRC 652u         /* CRC-32 of bytes [0, 652) */
#define CALREC_IMAGE_SIZE 656u      /* bytes of a version-2 image, CRC included */
#define CALREC_TMODEL_SIZE 80u      /* kind, n, t_ref, t_span, p[16] */

/* ---- Fixed-point helpers for constants ----------------------------------------------------- */

#define CALREC_Q16_ONE 65536      /* 1.0 in Q16.16 */
#define CALREC_Q30_ONE 1073741824 /* 1.0 in Q30 */

/* ---- Sensor binding ------------------------------------------------------------------------ */

/* Part family (binding.family). 0 is never valid. */
enum calrec_family {
    CALREC_FAMILY_SCA3000 = 1,   /* Murata/VTI SCA3000 accelerometer */
    CALREC_FAMILY_ADIS1625X = 2, /* ADI ADIS16250/16255 (and 16260/16265) single-axis gyro */
    CALREC_FAMILY_ADIS163XX = 3, /* ADI ADIS1636x / ADIS1640x six-axis IMU */
    CALREC_FAMILY_GENERIC = 4,   /* an IMU no firmware driver reads: host use (calstation apply);
                                    no driver reports this family, so no part ever loads it */
};

/* SCA3000 variant codes for binding.product (the part has no product-id register). */
#define CALREC_SCA3000_D01 0x0D01u
#define CALREC_SCA3000_E02 0x0E02u
#define CALREC_SCA3000_E04 0x0E04u
#define CALREC_SCA3000_E05 0x0E05u

/*
 * Identity of the sensor part the record was made for, as read from the part at calibration
 * time (docs/sensor-facts.md §1.3, 2.3, 3.2, 3.5). A record is used only when every field equals what the
 * part reports at boot. Fields a part does not have are 0.
 *
 *   family       product                              revision       serial        lot_id1/2
 *   SCA3000      variant code CALREC_SCA3000_*        REVID (0x00)   0             0
 *   ADIS1625X    PROD_ID (16260/5, reg 0x56); the     0              SERIAL_NUM    LOT_ID1/2
 *                part number 16250/16255 (no ID                      (16260/5)     (16260/5)
 *                register on those parts)                            else 0        else 0
 *   ADIS163XX    PROD_ID (reg 0x56), e.g. 16364,      0              SERIAL_NUM    LOT_ID1/2
 *                16405                                               (1636x, 0x58) (1636x) else 0
 *                                                                    else 0
 *   GENERIC      any 1..0xFFFF the user chooses         0..0xFF        0..0xFFFF     0..0xFFFF
 * Ranges (calrec_check_binding): family one of enum calrec_family; product 1..0xFFFF; revision
 * 0..0xFF and 0 for the ADIS families; serial and lot ids 0..0xFFFF and 0 for the SCA3000.
 * Parts without a serial number (SCA3000, ADIS16250/55, ADIS1640x) cannot be told apart from
 * another part of the same type and revision; see docs/calibration-storage.md.
 */
struct calrec_binding {
    uint32_t family;
    uint32_t product;
    uint32_t revision;
    uint32_t serial;
    uint32_t lot_id1;
    uint32_t lot_id2;
};

/* ---- Temperature models -------------------------------------------------------------------- */

enum calrec_tmodel_kind {
    CALREC_TM_NONE = 0,     /* y(T) = 0 */
    CALREC_TM_LINEAR = 1,   /* y = p0 + p1*u,            u = (Th - t_ref) / t_span */
    CALREC_TM_PARABOLA = 2, /* y = p0 + p1*u + p2*u^2    (three-point, in u: not a, b, c) */
    CALREC_TM_LORENTZ = 3,  /* y = p0 + p1 / (1 + ((T - p3) / (p2 / 2))^2)  ([TEMP-LORENTZ]) */
    CALREC_TM_PWL = 4,      /* n knots at T_i = t_ref + i*t_span, y_i = p[i]; held at the ends */
    CALREC_TM_LORENTZ_CUBIC = 5, /* y = LORENTZ(Th) + p4*u + p5*u^2 + p6*u^3 (since version 2) */
};
#define CALREC_TM_KIND_COUNT 6

#define CALREC_TM_PARAMS 16 /* parameter words per model; also the maximum PWL knot count */

/*
 * One temperature model y(T), T in degC Q16.16. "y format" is the format of the quantity the
 * model corrects: g Q16.16 for accelerometer bias, unitless Q30 for the relative scale-factor
 * deviation (scale = 1 + y).
 *   kind    enum calrec_tmodel_kind
 *   n       PWL: knot count 2..CALREC_TM_PARAMS; every other kind: 0
 *   t_ref   LINEAR/PARABOLA/LORENTZ_CUBIC: centre temperature; PWL: first knot; degC Q16.16
 *           in [-100, 200]; NONE/LORENTZ: 0
 *   t_span  LINEAR/PARABOLA/LORENTZ_CUBIC: half width of the calibrated range; PWL: knot
 *           spacing; degC Q16.16 in [1, 200]; NONE/LORENTZ: 0. The last PWL knot must lie at or
 *           below 200 degC.
 *   p[]     LINEAR p0..p1, PARABOLA p0..p2, PWL p0..p(n-1): y format, |p| <= the quantity's
 *           limit; LORENTZ: p0 = y0 and p1 = peak height above y0 (y format), p2 = full width at
 *           half maximum w (degC Q16.16, [1, 400]), p3 = centre Tc (degC Q16.16, [-100, 200]);
 *           LORENTZ_CUBIC: p0..p3 as LORENTZ, p4..p6 the u, u^2, u^3 coefficients (y format).
 *           Every parameter word a kind does not use is 0.
 * Th is T held in the calibrated range: LINEAR, PARABOLA and LORENTZ_CUBIC are evaluated at
 * Th = clamp(T, t_ref - t_span, t_ref + t_span) (|u| <= 1), PWL at clamp(T, first, last knot);
 * a fitted polynomial is never extrapolated beyond the chamber range. LORENTZ is bounded by
 * itself (between p0 and p0 + p1) and is evaluated at T.
 * Normalising the polynomial argument by t_span keeps every polynomial coefficient in the y
 * format and its resolution, instead of needing y/degC^2 with a different Q format.
 */
struct calrec_tmodel {
    int32_t kind;
    int32_t n;
    int32_t t_ref;
    int32_t t_span;
    int32_t p[CALREC_TM_PARAMS];
};

/* ---- The record ---------------------------------------------------------------------------- */

#define CALREC_AXES 3         /* x, y, z, in this order everywhere */
#define CALREC_NONLIN_TERMS 4 /* c0..c3 */

/*
 * The calibration coefficients. Order of declaration = order in the image.
 *
 *   acc_offset[a]      g, Q16.16. |v| <= CALREC_LIM_ACC_OFFSET (0.5 g). Two-point flip:
 *                      offset = (A(+1g) + A(-1g)) / 2.
 *   acc_gain[a]        unitless Q30, [CALREC_LIM_GAIN_MIN, CALREC_LIM_GAIN_MAX] = [0.75, 1.25].
 *                      gain = (A(+1g) - A(-1g)) / 2 in g per g (no extra 0.5, see docs/references.md);
 *                      a_true = (a_out - offset) / gain.
 *   acc_misalign[r][c] unitless Q30, 3x3 cross-axis correction applied after offset and gain;
 *                      diagonal in [0.75, 1.25], off-diagonal |v| <= 0.125.
 *   acc_nonlin[a][k]   unitless Q30 (x, y in g): y = x + c0 + c1*x + c2*x^2 + c3*x^3;
 *                      |c0| <= 0.0625 g, |c1| <= 0.0625, |c2| <= 0.25 /g, |c3| <= 0.25 /g^2.
 *   acc_tbias[a]       temperature model of the bias, y in g Q16.16, |y params| <= 0.5 g.
 *   acc_tscale[a]      temperature model of the relative scale-factor deviation, y unitless
 *                      Q30, |y params| <= 0.125.
 *   gyro_offset[a]     deg/s, Q16.16, |v| <= 30 deg/s.
 *   gyro_scale[a]      unitless Q30, [0.75, 1.25].
 *   valid              NOT stored. True only when the record came out of calrec_decode() /
 *                      calstore_load() with every check passed; false in the safe default.
 *
 * How the stages combine the terms is the calibration module's contract (docs/calibration.md);
 * the record only fixes what each number means.
 */
struct calrec {
    struct calrec_binding binding;
    int32_t acc_offset[CALREC_AXES];
    int32_t acc_gain[CALREC_AXES];
    int32_t acc_misalign[CALREC_AXES][CALREC_AXES];
    int32_t acc_nonlin[CALREC_AXES][CALREC_NONLIN_TERMS];
    struct calrec_tmodel acc_tbias[CALREC_AXES];
    struct calrec_tmodel acc_tscale[CALREC_AXES];
    int32_t gyro_offset[CALREC_AXES];
    int32_t gyro_scale[CALREC_AXES];
    bool valid;
};

/* ---- Range limits (inclusive), in the field's own format ----------------------------------- */

#define CALREC_LIM_ACC_OFFSET 32768           /* 0.5 g, Q16.16 */
#define CALREC_LIM_GAIN_MIN 805306368         /* 0.75, Q30 */
#define CALREC_LIM_GAIN_MAX 1342177280        /* 1.25, Q30 */
#define CALREC_LIM_MISALIGN_OFFDIAG 134217728 /* 0.125 (7.2 deg of cross-axis), Q30 */
#define CALREC_LIM_NONLIN_C01 67108864        /* 0.0625, Q30 */
#define CALREC_LIM_NONLIN_C23 268435456       /* 0.25, Q30 */
#define CALREC_LIM_TBIAS 32768                /* 0.5 g, Q16.16 */
#define CALREC_LIM_TSCALE 134217728           /* 0.125, Q30 */
#define CALREC_LIM_T_MIN (-6553600)           /* -100 degC, Q16.16 */
#define CALREC_LIM_T_MAX 13107200             /* +200 degC, Q16.16 */
#define CALREC_LIM_SPAN_MIN 65536             /* 1 degC, Q16.16 */
#define CALREC_LIM_SPAN_MAX 13107200          /* 200 degC, Q16.16 */
#define CALREC_LIM_WIDTH_MAX 26214400         /* 400 degC, Q16.16 (Lorentz w; minimum is 1 degC) */
#define CALREC_LIM_GYRO_OFFSET 1966080        /* 30 deg/s, Q16.16 */

/* ---- Functions ----------------------------------------------------------------------------- */

/*
 * The safe default, which is what every consumer sees when no valid calibration exists: binding
 * all 0 (matches no part), offsets 0, gains and scales 1.0, misalignment identity, nonlinearity
 * 0, every temperature model CALREC_TM_NONE with all words 0, valid = false. Applying it leaves
 * the nominal-scaled reading unchanged. rec == NULL does nothing.
 */
void calrec_set_default(struct calrec *rec);

/* 0 if every binding field is in the range given above; INC_ERR_NULL, INC_ERR_INVAL otherwise. */
int calrec_check_binding(const struct calrec_binding *b);

/* True when all six binding fields are equal (both non-NULL). */
bool calrec_binding_equal(const struct calrec_binding *a, const struct calrec_binding *b);

/*
 * Check a record before it is stored or used: INC_ERR_NULL; INC_ERR_INVAL when the binding is
 * invalid; INC_ERR_RANGE when any coefficient, temperature-model kind, knot count, temperature
 * or unused parameter word is outside the limits above. 0 otherwise. `valid` is not looked at.
 */
int calrec_check(const struct calrec *rec);

/*
 * Write the version-2 image of rec with sequence number seq to img[0..CALREC_IMAGE_SIZE).
 * Refuses (and writes nothing) when calrec_check(rec) fails: INC_ERR_NULL, INC_ERR_INVAL,
 * INC_ERR_RANGE; INC_ERR_NO_SPACE when cap < CALREC_IMAGE_SIZE.
 */
int calrec_encode(const struct calrec *rec, uint32_t seq, uint8_t *img, size_t cap);

/*
 * Check a version-2 image in place, without decoding it: the same checks, order and codes as
 * calrec_decode below (which calls it). Needs no record buffer, so the store can judge both
 * slots with only the image buffer. INC_ERR_NULL for NULL img/expect.
 */
int calrec_check_image(const uint8_t *img, size_t len, const struct calrec_binding *expect);

/*
 * Read a version-2 image of len bytes into *out and its sequence number into *seq (seq may be
 * NULL). Checks, in this order: magic (INC_ERR_CRC: not a record), version field
 * (INC_ERR_VERSION), length field == CALREC_IMAGE_SIZE (INC_ERR_VERSION) and len >= that
 * (INC_ERR_INVAL), CRC-32 (INC_ERR_CRC), binding equal to *expect (INC_ERR_MISMATCH), coefficient
 * ranges (INC_ERR_RANGE). expect must itself pass calrec_check_binding (INC_ERR_INVAL).
 * On success out->valid = true. On ANY error *out is the safe default (valid = false) and *seq
 * is 0, so no field of a rejected image ever reaches the caller.
 */
int calrec_decode(const uint8_t *img, size_t len, const struct calrec_binding *expect,
                  struct calrec *out, uint32_t *seq);

/* Little-endian 32-bit load and store, byte by byte (alignment- and host-order-independent). */
/*
 * The binding an image carries (its six words at CALREC_OFF_BINDING), not checked: what a tool
 * shows of a record, or decodes it against. 0; INC_ERR_NULL; INC_ERR_INVAL (len too short for the
 * binding, *out untouched).
 */
int calrec_image_binding(const uint8_t *img, size_t len, struct calrec_binding *out);

uint32_t calrec_get_le32(const uint8_t *p);
void calrec_put_le32(uint8_t *p, uint32_t v);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_CALREC_H */
