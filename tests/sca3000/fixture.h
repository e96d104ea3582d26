/*
 * fixture.h - the SCA3000 test bench: the standard simulated board, the SCA3000 model on cs0
 * (INT on dr0) and the driver configured with its safe timing, plus the check every normal run
 * makes: no timing or protocol violation in the log (printed when there is one).
 */
#ifndef SCA3000_FIXTURE_H
#define SCA3000_FIXTURE_H

#include "inclino/sca3000.h"
#include "sca3000_regs.h" /* white-box: the driver's register map */
#include "inclino/sim/board.h"
#include "inclino/sim/sca3000.h"
#include "unit.h"

struct fx {
    struct sim_board board;
    struct sim_sca3000 part;
    struct sca3000 dev;
    struct sca3000_cfg cfg;
};

extern struct fx fx;

#define FX_CS SIM_BOARD_CS(0)
#define FX_INT SIM_BOARD_DR(0)

/* The driver variant that matches a model variant (the two enums are independent). */
enum sca3000_variant fx_driver_variant(enum sim_sca3000_variant v);

/* Board + model (variant v, REVID revid or 0 for the default); the driver config in fx.cfg.
 * Returns 0 or the first error. The driver is not initialised. */
int fx_setup_part(enum sim_sca3000_variant v, uint8_t revid);
/* fx_setup_part() then sca3000_init(); returns the init result. */
int fx_setup(enum sim_sca3000_variant v);

/* Advance virtual time by ns (the model samples on the way). */
void fx_wait_ns(uint64_t ns);

/* Print the violation log when it is not empty; true when empty. */
bool fx_log_clean(void);
#define CHECK_NO_VIOLATIONS() CHECK(fx_log_clean())

/* Set the static input: accelerations in g, temperature in degC. */
void fx_input(double ax, double ay, double az, double temp_c);

#endif
