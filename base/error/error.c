/* error.c - names of the error codes, for logs and test output. */
#include "inclino/error.h"

const char *inc_err_name(int err)
{
    switch (err) {
    case INC_OK: return "OK";
    case INC_ERR_NULL: return "ERR_NULL";
    case INC_ERR_INVAL: return "ERR_INVAL";
    case INC_ERR_STATE: return "ERR_STATE";
    case INC_ERR_BUS: return "ERR_BUS";
    case INC_ERR_ID: return "ERR_ID";
    case INC_ERR_TIMEOUT: return "ERR_TIMEOUT";
    case INC_ERR_DEVICE: return "ERR_DEVICE";
    case INC_ERR_STALE: return "ERR_STALE";
    case INC_ERR_BUSY: return "ERR_BUSY";
    case INC_ERR_RANGE: return "ERR_RANGE";
    case INC_ERR_OVERFLOW: return "ERR_OVERFLOW";
    case INC_ERR_CRC: return "ERR_CRC";
    case INC_ERR_VERSION: return "ERR_VERSION";
    case INC_ERR_MISMATCH: return "ERR_MISMATCH";
    case INC_ERR_NOT_CALIBRATED: return "ERR_NOT_CALIBRATED";
    case INC_ERR_MOTION: return "ERR_MOTION";
    case INC_ERR_THERMAL: return "ERR_THERMAL";
    case INC_ERR_DEGENERATE: return "ERR_DEGENERATE";
    case INC_ERR_FORMAT: return "ERR_FORMAT";
    case INC_ERR_IO: return "ERR_IO";
    case INC_ERR_NO_SPACE: return "ERR_NO_SPACE";
    case INC_ERR_TIMING: return "ERR_TIMING";
    case INC_ERR_UNSUPPORTED: return "ERR_UNSUPPORTED";
    case INC_ERR_REJECTED: return "ERR_REJECTED";
    case INC_ERR_ABORTED: return "ERR_ABORTED";
    default: return "ERR_UNKNOWN";
    }
}
