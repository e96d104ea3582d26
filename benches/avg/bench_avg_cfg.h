/*
 * bench_avg_cfg.h - the stillness and thermal detector configurations both averaging benchmarks
 * measure (bench_avg.c on the host, bench_avg_cm.c on Cortex-M), written once so the two sets of
 * figures in docs/benchmarks.md are of the same configuration.
 */
#ifndef INCLINO_BENCH_AVG_CFG_H
#define INCLINO_BENCH_AVG_CFG_H

#include <string.h>

#include "inclino/still.h"

/* W = 819 samples, every test enabled. */
static inline void bench_still_cfg(struct still_cfg *cfg)
{
    memset(cfg, 0, sizeof(*cfg));
    cfg->window = 819;
    cfg->windows_required = 3;
    cfg->gyro_var_max = 409;
    cfg->accel_var_max = 43;
    cfg->gyro_mean_max = 60;
    cfg->accel_one_g = 1000;
    cfg->accel_norm_tol = 50;
    cfg->accel_drift_max = 3;
}

/* avg_n = 819, span = 30. */
static const struct still_thermal_cfg bench_thermal_cfg = {819, 30, 1};

#endif /* INCLINO_BENCH_AVG_CFG_H */
