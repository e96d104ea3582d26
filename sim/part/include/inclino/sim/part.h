/*
 * sim/part.h - the one interface of a simulated part (module inclino_sim_part, layer sim).
 *
 * Every device model (sim/models/adis16255, adis_imu, sca3000) fills a const struct
 * sim_part_ops and binds its instance to a struct sim_part (sim_<model>_part()). Through it a
 * test, a rig or the conformance suite (tests/conformance) drives any part the same way:
 *
 *   - the physical world: a static input (true rate, specific force, temperature, supply), a
 *     physics hook that gives it at each internal sample, an error-model hook that distorts it
 *     (sim/inertial.h);
 *   - faults by name (enum sim_fault), injected and cleared at run time;
 *   - the register file, through back doors that bypass the bus (peek: no read side effects;
 *     poke: the model's own write path).
 *
 * Faults come in three kinds, each done once:
 *   - on the wire, in the part's SPI slave (sim/spi_slave.h): MISO stuck high or low, every
 *     word the part shifts out XORed with a mask (corrupt frame);
 *   - in the physics, by an error-model stage the part installs in front of the model while one
 *     of these faults is active (otherwise the user's hook is installed unchanged, so a run
 *     without faults is the run it always was): frozen output, bias jump, noise burst,
 *     saturation;
 *   - in the model (ops->fault): wrong identity, busy part, data-ready never comes, device error
 *     flag, stuck bit. A model that cannot show a fault returns INC_ERR_UNSUPPORTED.
 * docs/sim.md ("The part interface") has the table of which model shows which fault and how.
 */
#ifndef INCLINO_SIM_PART_H
#define INCLINO_SIM_PART_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/sim/inertial.h"
#include "inclino/sim/spi_slave.h"

#ifdef __cplusplus
extern "C" {
#endif

enum sim_fault {
    SIM_FAULT_MISO_STUCK_HIGH = 0, /* MISO driven high while selected (wire) */
    SIM_FAULT_MISO_STUCK_LOW,      /* MISO driven low while selected (wire) */
    SIM_FAULT_WRONG_ID,            /* the part identifies as another one (model) */
    SIM_FAULT_BUSY,                /* the part is busy for arg.duration_ns (model) */
    SIM_FAULT_NO_DATA_READY,       /* no data-ready / INT pulse ever comes (model) */
    SIM_FAULT_CORRUPT_FRAME,       /* each word shifted out XOR arg.mask (wire) */
    SIM_FAULT_DEVICE_ERROR,        /* the part's error/alarm flag set, arg.mask bits (model) */
    SIM_FAULT_FROZEN_OUTPUT,       /* the sensing element repeats its last value (physics) */
    SIM_FAULT_STUCK_BIT,           /* bit arg.bit of register arg.addr reads arg.level (model) */
    SIM_FAULT_BIAS_JUMP,           /* + arg.value on the channels of arg.channels (physics) */
    SIM_FAULT_NOISE_BURST,         /* + arg.value x N(0,1) for arg.duration_ns (physics) */
    SIM_FAULT_SATURATION,          /* the channels of arg.channels at arg.value (physics) */
    SIM_FAULT_EXTRA_DATA_READY,    /* a spurious data-ready / INT pulse halfway through every
                                      sample period, no new sample behind it (model) */
    SIM_FAULT_COUNT
};

/* Physical channels of struct sim_inertial_input, as bits of sim_fault_arg.channels. */
enum sim_part_channel {
    SIM_PART_RATE_X = 0,
    SIM_PART_RATE_Y,
    SIM_PART_RATE_Z,
    SIM_PART_ACCEL_X,
    SIM_PART_ACCEL_Y,
    SIM_PART_ACCEL_Z,
    SIM_PART_TEMP,
    SIM_PART_SUPPLY,
    SIM_PART_CHANNELS
};
#define SIM_PART_CH(c) (1u << (unsigned)(c))
#define SIM_PART_INERTIAL 0x3Fu /* the three rates and the three specific forces */

/* Parameters of a fault; sim_fault_default() gives the ones the conformance suite uses. */
struct sim_fault_arg {
    uint32_t channels;    /* physics faults: SIM_PART_CH() bits (0: SIM_PART_INERTIAL) */
    double value;         /* bias jump (deg/s, g, degC, V), noise sigma, saturation value */
    uint16_t mask;        /* corrupt frame: XOR of each MISO word; device error: flag bits
                             (0: the model's own choice) */
    uint8_t addr;         /* stuck bit: register address (the model's addressing) */
    uint8_t bit;          /* stuck bit: 0..15 (0..7 on 8-bit parts) */
    bool level;           /* stuck bit: the level it reads */
    uint64_t duration_ns; /* busy, noise burst: how long from injection (0: until cleared) */
    uint64_t seed;        /* noise burst */
};

struct sim_part_ops {
    const char *kind; /* "adis16255", "adis_imu", "sca3000" */
    void (*set_input)(void *model, const struct sim_inertial_input *in);
    /* NULL removes the hook (static input / ideal part). The pointer is not kept. */
    void (*set_physics)(void *model, const struct sim_physics *p);
    void (*set_error_model)(void *model, const struct sim_error_model *e);
    /* The error-model hook in force when the part is bound (zeroed: none). */
    void (*get_error_model)(const void *model, struct sim_error_model *e);
    /* The SPI slave the part answers through (wire faults). */
    struct sim_spi_slave *(*slave)(void *model);
    /* Model faults: on = inject with *arg (never NULL), off = clear. INC_ERR_UNSUPPORTED when
     * the model cannot show it. */
    int (*fault)(void *model, enum sim_fault f, const struct sim_fault_arg *arg, bool on);
    /* A register as stored (no read side effects) and a back-door write. */
    uint16_t (*peek)(const void *model, uint8_t addr);
    void (*poke)(void *model, uint8_t addr, uint16_t value);
};

struct sim_part {
    const struct sim_part_ops *ops;
    void *model;
    struct sim_clock *clk;
    struct sim_error_model user;  /* the error model the user installed (apply NULL: none) */
    struct sim_error_model stage; /* the fault stage, installed while a physics fault is on */
    uint32_t active;              /* bit f: fault f injected */
    struct sim_fault_arg arg[SIM_FAULT_COUNT];
    uint64_t since_ns[SIM_FAULT_COUNT]; /* virtual time of the injection */
    bool frozen_valid;
    struct sim_inertial_input frozen;
    struct sim_rng rng;
};

/* Bind an instance to its ops (clk: the model's clock, for fault durations). */
void sim_part_bind(struct sim_part *p, const struct sim_part_ops *ops, void *model,
                   struct sim_clock *clk);

void sim_part_set_input(struct sim_part *p, const struct sim_inertial_input *in);
void sim_part_set_physics(struct sim_part *p, const struct sim_physics *phys);
/* Installs e (NULL: ideal part); while a physics fault is active it runs before the fault. */
void sim_part_set_error_model(struct sim_part *p, const struct sim_error_model *e);

/*
 * Inject fault f with *arg (NULL: sim_fault_default(f)). Returns 0, INC_ERR_NULL,
 * INC_ERR_INVAL (f out of range) or INC_ERR_UNSUPPORTED (the model cannot show it: nothing
 * changed). Injecting an active fault again replaces its parameters.
 */
int sim_part_inject(struct sim_part *p, enum sim_fault f, const struct sim_fault_arg *arg);
/* Clear one fault (0 also when it was not active), or all of them. */
int sim_part_clear(struct sim_part *p, enum sim_fault f);
void sim_part_clear_all(struct sim_part *p);
bool sim_part_fault_active(const struct sim_part *p, enum sim_fault f);

uint16_t sim_part_peek(const struct sim_part *p, uint8_t addr);
void sim_part_poke(struct sim_part *p, uint8_t addr, uint16_t value);

/* A stuck data bit (SIM_FAULT_STUCK_BIT), the state every model keeps for it: one register
 * (the model's addressing) whose bit reads a fixed level. mask 0: no bit stuck. */
struct sim_stuck_bit {
    uint8_t addr;
    uint16_t mask, set; /* the bit, and the level it reads (mask or 0) */
};

/* Inject (on) or clear the stuck bit of *arg: the address masked with addr_mask, a bit below
 * width (8 or 16). INC_ERR_INVAL for a bit beyond the width (nothing changes). */
int sim_stuck_bit_fault(struct sim_stuck_bit *s, const struct sim_fault_arg *arg, bool on,
                        uint8_t addr_mask, unsigned width);

/* v as the bus reads register addr: the stuck bit applied when it is that register's. */
static inline uint16_t sim_stuck_bit_apply(const struct sim_stuck_bit *s, uint8_t addr, uint16_t v)
{
    return s->mask != 0u && addr == s->addr ? (uint16_t)((v & ~s->mask) | s->set) : v;
}

/* The parameters the conformance suite uses for each fault (docs/sim.md). */
struct sim_fault_arg sim_fault_default(enum sim_fault f);
/* "miso_stuck_high", ...; "?" out of range. */
const char *sim_fault_name(enum sim_fault f);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_PART_H */
