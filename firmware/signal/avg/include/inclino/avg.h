/*
 * avg.h - averaging and decimation filters (module inclino_avg, prefix avg_). Freestanding C11,
 * integer only, caller-allocated state, no heap.
 *
 * SAMPLES are int32 in any one Q format (raw register counts, Q16.16 deg/s or g...). Every
 * output is in the SAME format as the input. Sums are kept exactly in int64; each filter rounds
 * exactly once, at its output:
 *   ROUNDING  round(sum / divisor) to nearest, ties away from zero (fx_sum_mean /
 *             fx_rshift_round64 of the fixed-point core), so filter(-x) == -filter(x) exactly.
 *   MAX ERROR |output - exact weighted mean| <= 0.5 LSB of the input format, for every input
 *             (the intermediate sums are exact). No saturation is ever needed: a mean of int32
 *             values is an int32 value.
 *   OVERFLOW  impossible by construction: each init rejects (INC_ERR_OVERFLOW) a length whose
 *             worst-case sum |x| * divisor could leave int64, i.e. divisor > 2^31
 *             (2^31 * 2^31 = 2^62 < 2^63).
 * Bad lengths are rejected at init (INC_ERR_INVAL for 0 or a length the filter cannot take,
 * INC_ERR_OVERFLOW as above); a state whose init failed refuses every call (INC_ERR_STATE).
 *
 * Noise (white input of rms s): block and moving average of N -> s / sqrt(N); P cascaded moving
 * averages of W -> s * sqrt(sum h^2) with h the P-fold convolution of a W-boxcar / W^P
 * (avg_cascade_*); Bartlett of N taps per stage -> s * sqrt((2N^2 + 1) / (3N^3)).
 * tests/avg proves the exact kernels and the 1/sqrt(N) law on white noise within 5 %.
 */
#ifndef INCLINO_AVG_H
#define INCLINO_AVG_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/fx.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest divisor of any filter here: 2^31 samples (the exact int64 sum bound, FX_SUM_MAX_COUNT).
 * 100 s at 819.2 SPS is 81 920 samples ([ADI-IMU-QS] manual calibration: 82 000), far inside. */
#define AVG_MAX_DIVISOR 0x80000000u

/* ---- Block average ------------------------------------------------------------------------
 * Mean of N consecutive samples; then it starts the next block. N in 1..2^31.
 * Cost per sample: one int64 add and a compare; one rounding division per block. */
struct avg_block {
    struct fx_sum acc; /* sum and count of the current block */
    uint32_t n;        /* block length; 0 = not initialised */
};

/* N == 0 -> INC_ERR_INVAL, N > 2^31 -> INC_ERR_OVERFLOW, NULL -> INC_ERR_NULL (state unusable). */
int avg_block_init(struct avg_block *b, uint32_t n);

/* Add x. When it completes a block: *mean = round(sum / N), *done = true, next block starts.
 * Otherwise *done = false and *mean is untouched. */
int avg_block_push(struct avg_block *b, int32_t x, int32_t *mean, bool *done);

/* Mean of the samples of the current, incomplete block (round(sum / count)). INC_ERR_STATE when it
 * holds none. For aborting a long average and still reporting what was seen. */
int avg_block_partial(const struct avg_block *b, int32_t *mean, uint32_t *count);

/* Drop the current block (the length is kept). */
void avg_block_restart(struct avg_block *b);

/* ---- Moving average -----------------------------------------------------------------------
 * Mean of the last W samples, one output per input, O(1) per sample (running int64 sum: the new
 * sample added, the one leaving the window subtracted; exact, so it never drifts). The delay line
 * is the caller's: an int32 array of capacity >= W (static or on the stack; AVG_MOVING_DEFINE).
 * While fewer than W samples have arrived the output is the mean of those (*full = false).
 * W a power of two divides by a rounding shift; another W costs one 64-bit division per output. */
struct avg_moving {
    int32_t *line;  /* caller's delay line, capacity >= w */
    uint32_t w;     /* window; 0 = not initialised */
    uint32_t head;  /* next slot to overwrite */
    uint32_t count; /* samples in the window (<= w) */
    int64_t sum;    /* exact sum of the window */
    unsigned shift; /* log2(w) when w is a power of two */
    bool pow2;
};

/* Storage for a moving average of window up to cap: `AVG_MOVING_DEFINE(gyro_ma, 64);` declares
 * int32_t gyro_ma_line[64] and struct avg_moving gyro_ma (file scope or function scope). */
#define AVG_MOVING_DEFINE(name, cap) \
    int32_t name##_line[(cap)];      \
    struct avg_moving name

/* w in 1..capacity (capacity <= 2^31): else INC_ERR_INVAL (w == 0 or w > capacity) or
 * INC_ERR_OVERFLOW (w > 2^31). */
int avg_moving_init(struct avg_moving *m, int32_t *line, uint32_t capacity, uint32_t w);

/* Add x; *mean = round(window sum / samples in window); *full = (window filled). */
int avg_moving_push(struct avg_moving *m, int32_t x, int32_t *mean, bool *full);

/* Empty the window (the length and buffer are kept). */
void avg_moving_restart(struct avg_moving *m);

/* ---- Cascaded multi-pass moving average ([KF-SCA3000]: 1 to 4 passes) ---------------------------
 * P passes of a W-sample moving average, each pass averaging the previous pass's output. The
 * passes keep exact int64 sums (pass k holds sums of W^k samples) and the output is rounded once:
 *   y[n] = round( sum_j h_P[j] x[n - j] / W^P ),  h_P = P-fold convolution of W ones,
 * a kernel of P (W - 1) + 1 taps (P = 2: triangle; P = 4: near-Gaussian), group delay
 * P (W - 1) / 2 samples, white-noise rms gain sqrt(sum h_P^2) / W^P.
 * The history is seeded with the first sample (the output starts at x[0], no zero-padding
 * transient); *full turns true once the kernel spans only real samples (P (W - 1) + 1 inputs).
 * Delay lines: caller int64 array of P * W entries (AVG_CASCADE_DEFINE).
 * Limits: P in 1..AVG_CASCADE_MAX_PASSES, W >= 1, W^P <= 2^31 (e.g. P = 4: W <= 215;
 * P = 2: W <= 46340), else INC_ERR_INVAL / INC_ERR_OVERFLOW at init. */
#define AVG_CASCADE_MAX_PASSES 4u

struct avg_cascade {
    int64_t *lines; /* P delay lines of W entries: pass k's inputs at lines[k * W ..] */
    int64_t sum[AVG_CASCADE_MAX_PASSES]; /* running sum of each pass */
    uint32_t w;                          /* 0 = not initialised */
    unsigned passes;
    uint32_t head;    /* slot shared by all lines */
    uint32_t seen;    /* inputs so far, saturating at the kernel length */
    uint32_t divisor; /* W^P */
    unsigned shift;   /* log2(W^P) when W is a power of two */
    bool pow2;
    bool primed; /* history seeded with the first sample */
};

#define AVG_CASCADE_DEFINE(name, w, passes) \
    int64_t name##_lines[(w) * (passes)];   \
    struct avg_cascade name

/* lines: capacity entries (>= passes * w). Errors: INC_ERR_NULL; INC_ERR_INVAL (w == 0, passes
 * outside 1..4, capacity too small); INC_ERR_OVERFLOW (w^passes > 2^31). */
int avg_cascade_init(struct avg_cascade *c, int64_t *lines, uint32_t capacity, uint32_t w,
                     unsigned passes);

/* Add x; *y = the cascade output for this input; *full as above. */
int avg_cascade_push(struct avg_cascade *c, int32_t x, int32_t *y, bool *full);

/* Kernel length P (W - 1) + 1 of the configured cascade (0 if not initialised). */
uint32_t avg_cascade_taps(const struct avg_cascade *c);

/* Forget the history (the next sample seeds it again). */
void avg_cascade_restart(struct avg_cascade *c);

/* ---- Bartlett decimator (ADIS SENS_AVG filter) ----------------------------------------------
 * The ADIS1636x/1640x digital filter ([ADI-IMU-QS], docs/sensor-facts.md §3.4 SENS_AVG): two cascaded N-tap
 * moving averages, N = 2^M, M = SENS_AVG[2:0] in 0..6, i.e. a triangular (Bartlett) window of
 * 2N - 1 taps: y[n] = round( sum_j t[j] x[n - j] / N^2 ), t = 1, 2, .., N, .., 2, 1.
 * Group delay N - 1 samples; white-noise rms gain sqrt((2N^2 + 1) / (3N^3)).
 * Decimation by D: an output every D-th input, D in 1..N ([ADI-IMU-QS]: divide the rate by any
 * integer 2..N, N the taps per stage; a larger D would alias, so it is rejected). This is both
 * the firmware twin of the part's own filter (feed it raw samples taken with SENS_AVG M = 0) and
 * the host-side "count data-ready and keep every D-th" decimation of [ADI-IMU-QS], done in firmware.
 * The two stages update every input (O(1)); the rounding shift by 2M runs only per output.
 * Fixed storage: AVG_BARTLETT_MAX_TAPS per stage inside the struct. History seeded with the first
 * sample as for the cascade; *full after 2N - 1 inputs. */
#define AVG_BARTLETT_MAX_M 6u
#define AVG_BARTLETT_MAX_TAPS (1u << AVG_BARTLETT_MAX_M) /* 64 */

struct avg_bartlett {
    int32_t x_line[AVG_BARTLETT_MAX_TAPS]; /* stage-1 inputs */
    int64_t s_line[AVG_BARTLETT_MAX_TAPS]; /* stage-2 inputs (stage-1 sums) */
    int64_t s1, s2;                        /* running sums of the stages */
    uint32_t n;                            /* taps per stage, 2^m; 0 = not initialised */
    unsigned m;
    uint32_t d;     /* decimation factor */
    uint32_t phase; /* inputs since the last output */
    uint32_t head;
    uint32_t seen;
    bool primed;
};

/* m in 0..6 (SENS_AVG[2:0]; 7 is "not a valid setting" on the part), d in 1..2^m: else
 * INC_ERR_INVAL. */
int avg_bartlett_init(struct avg_bartlett *b, unsigned m, uint32_t d);

/* Add x. Every d-th input: *y = filter output, *ready = true; otherwise *ready = false, *y
 * untouched. *full as above. (full may be NULL.) */
int avg_bartlett_push(struct avg_bartlett *b, int32_t x, int32_t *y, bool *ready, bool *full);

void avg_bartlett_restart(struct avg_bartlett *b);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_AVG_H */
