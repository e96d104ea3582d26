/*
 * sim/s32k_lpit.h - the simulated S32K1 time base.
 *
 * LPIT0 (4 channels, 32-bit periodic mode only: MODE = 0, no chaining or triggers): MCR, MSR
 * (TIFn, w1c), MIER, TVALn, CVALn, TCTRLn. A running channel's CVAL is computed from the
 * simulated clock at the functional clock hz (TVAL down to 0, then reload); at each expiry the
 * model sets TIFn and, when MIER enables it, raises the channel's NVIC interrupt (S32K144: 48 + n;
 * S32K116: 20 for all channels) in the simulated core (inclino/sim/s32k_core.h).
 *
 * Access time: the model installs the bus hook (s32k_bus_set_hook). Every register access of
 * the main line advances the simulated clock by access_ns (firing the device models' events on
 * the way), so busy-waits on a status register or on CVAL end in simulated time and a
 * bit-banged SPI has realistic edge spacing. Accesses from an interrupt handler are charged
 * nothing (the core model runs handlers at one instant).
 */
#ifndef INCLINO_SIM_S32K_LPIT_H
#define INCLINO_SIM_S32K_LPIT_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/s32k1_regs.h"
#include "inclino/sim/clock.h"
#include "inclino/sim/s32k_core.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SIM_S32K_LPIT_CHANNELS 4u
#define SIM_S32K_ACCESS_NS_DEFAULT 25u /* two core cycles at 80 MHz, one bus cycle at 40 MHz */

struct sim_s32k_lpit {
    struct sim_clock *clk;
    struct sim_s32k_core *core;
    enum s32k_part part;
    uint32_t hz;
    uint32_t access_ns;
    uint32_t mcr, msr, mier;
    uint32_t tval[SIM_S32K_LPIT_CHANNELS], tctrl[SIM_S32K_LPIT_CHANNELS];
    uint64_t start_ns[SIM_S32K_LPIT_CHANNELS]; /* when the current period began */
    int event[SIM_S32K_LPIT_CHANNELS];         /* clock handle of the next expiry, 0 none */
    uint64_t accesses;                         /* charged accesses */
};

/*
 * Map LPIT0, install the access hook. hz: the functional clock (24 MHz: FIRCDIV2 of the port);
 * access_ns: simulated time per main-line register access. 0 or an error.
 */
int sim_s32k_lpit_init(struct sim_s32k_lpit *m, struct sim_clock *clk, struct sim_s32k_core *core,
                       enum s32k_part part, uint32_t hz, uint32_t access_ns);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_S32K_LPIT_H */
