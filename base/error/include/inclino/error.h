/*
 * error.h - the one error convention of Inclino.
 *
 * Every function that can fail returns int: 0 (INC_OK) on success, or one negative code from
 * enum inc_err. Results travel through pointer arguments. A function never returns a plausible
 * value together with an error: on error its outputs are either untouched or explicitly set to a
 * documented safe state (and any validity flag is false).
 *
 * New codes are appended at the end; existing values never change (they are stored in traces and
 * logs).
 */
#ifndef INCLINO_ERROR_H
#define INCLINO_ERROR_H

#ifdef __cplusplus
extern "C" {
#endif

enum inc_err {
    INC_OK = 0,
    INC_ERR_NULL = -1,      /* a required pointer argument was NULL */
    INC_ERR_INVAL = -2,     /* an argument or configuration field is outside its documented range */
    INC_ERR_STATE = -3,     /* not initialised, or the call is not allowed in the current state */
    INC_ERR_BUS = -4,       /* bus fault: no device, MISO stuck at 0 or 1, implausible reply */
    INC_ERR_ID = -5,        /* the part answered with an unexpected identity (PROD_ID, REVID) */
    INC_ERR_TIMEOUT = -6,   /* an expected event did not happen in time */
    INC_ERR_DEVICE = -7,    /* the part reports an error or alarm (EA, DIAG_STAT, STATUS) */
    INC_ERR_STALE = -8,     /* the part had no new data (ND clear); the sample is not used */
    INC_ERR_BUSY = -9,      /* the part or resource is busy; the request was not lost, retry */
    INC_ERR_RANGE = -10,    /* a value is outside its representable or physical range */
    INC_ERR_OVERFLOW = -11, /* a parameter would let an accumulator overflow */
    INC_ERR_CRC = -12,      /* a checksum did not match */
    INC_ERR_VERSION = -13,  /* a record or file has an unsupported version */
    INC_ERR_MISMATCH = -14, /* data belongs to another sensor, or replayed traffic diverged */
    INC_ERR_NOT_CALIBRATED = -15, /* no valid calibration; outputs are uncalibrated */
    INC_ERR_MOTION = -16,         /* the sensor is moving; a still-only procedure refused to run */
    INC_ERR_THERMAL = -17,        /* temperature not settled */
    INC_ERR_DEGENERATE =
        -18,              /* the data cannot determine the result (singular fit, swapped points) */
    INC_ERR_FORMAT = -19, /* malformed input text (CSV, trace file) */
    INC_ERR_IO = -20,     /* storage or file read/program/erase failure */
    INC_ERR_NO_SPACE = -21,    /* a fixed-size buffer or table is full */
    INC_ERR_TIMING = -22,      /* a timing requirement cannot be met */
    INC_ERR_UNSUPPORTED = -23, /* the feature does not exist on this part or port */
    INC_ERR_REJECTED = -24,    /* a measurement was rejected (implausible); the filter coasts */
    INC_ERR_ABORTED = -25,     /* a procedure was aborted; its previous result is kept */
};

typedef enum inc_err inc_err_t;

/* The enumerator's name without the INC_ prefix ("OK", "ERR_BUS", ...), or "ERR_UNKNOWN". */
const char *inc_err_name(int err);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_ERROR_H */
