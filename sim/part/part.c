/* part.c - the simulated-part interface and its fault engine (see sim/part.h). */
#include "inclino/sim/part.h"

#include "inclino/error.h"

#include <stddef.h>
#include <string.h>

#define WIRE_FAULTS                                                         \
    ((1u << SIM_FAULT_MISO_STUCK_HIGH) | (1u << SIM_FAULT_MISO_STUCK_LOW) | \
     (1u << SIM_FAULT_CORRUPT_FRAME))
#define PHYSICS_FAULTS                                               \
    ((1u << SIM_FAULT_FROZEN_OUTPUT) | (1u << SIM_FAULT_BIAS_JUMP) | \
     (1u << SIM_FAULT_NOISE_BURST) | (1u << SIM_FAULT_SATURATION))

static const char *const names[SIM_FAULT_COUNT] = {
    "miso_stuck_high", "miso_stuck_low", "wrong_id",         "busy",      "no_data_ready",
    "corrupt_frame",   "device_error",   "frozen_output",    "stuck_bit", "bias_jump",
    "noise_burst",     "saturation",     "extra_data_ready",
};

const char *sim_fault_name(enum sim_fault f)
{
    return (unsigned)f < (unsigned)SIM_FAULT_COUNT ? names[f] : "?";
}

struct sim_fault_arg sim_fault_default(enum sim_fault f)
{
    struct sim_fault_arg a;
    memset(&a, 0, sizeof(a));
    a.channels = SIM_PART_INERTIAL;
    switch (f) {
    case SIM_FAULT_BUSY: a.duration_ns = 10000000000ull; break; /* 10 s: longer than any retry */
    case SIM_FAULT_CORRUPT_FRAME: a.mask = 0x0001u; break;      /* the LSB of every word */
    case SIM_FAULT_STUCK_BIT:
        a.bit = 0;
        a.level = true;
        break; /* addr: the model's first output register (set by the caller) */
    case SIM_FAULT_BIAS_JUMP: a.value = 1.0; break;     /* 1 deg/s, 1 g */
    case SIM_FAULT_NOISE_BURST: a.value = 0.5; break;   /* sigma 0.5 deg/s, 0.5 g */
    case SIM_FAULT_SATURATION: a.value = 1000.0; break; /* far beyond every range */
    default: break;
    }
    if (f == SIM_FAULT_NOISE_BURST) {
        a.duration_ns = 1000000000ull;
        a.seed = 0x5eedu;
    }
    return a;
}

/* The fields of an input, by channel. */
static double *chan(struct sim_inertial_input *in, unsigned c)
{
    if (c < 3u) {
        return &in->rate_dps[c];
    }
    if (c < 6u) {
        return &in->accel_g[c - 3u];
    }
    return c == SIM_PART_TEMP ? &in->temp_c : &in->supply_v;
}

static bool on_at(const struct sim_part *p, enum sim_fault f, uint64_t t)
{
    if ((p->active & (1u << f)) == 0u) {
        return false;
    }
    return p->arg[f].duration_ns == 0u || t - p->since_ns[f] < p->arg[f].duration_ns;
}

/* The fault stage: the user's error model, then the physics faults. */
static void stage_apply(void *ctx, const struct sim_inertial_input *in,
                        struct sim_inertial_input *out, uint64_t t_ns, double dt_s)
{
    struct sim_part *p = ctx;
    unsigned c;
    if (p->user.apply != NULL) {
        p->user.apply(p->user.ctx, in, out, t_ns, dt_s);
    } else {
        *out = *in;
    }
    if (on_at(p, SIM_FAULT_FROZEN_OUTPUT, t_ns)) {
        if (!p->frozen_valid) {
            p->frozen = *out;
            p->frozen_valid = true;
        }
        *out = p->frozen;
    }
    for (c = 0; c < (unsigned)SIM_PART_CHANNELS; c++) {
        double *v = chan(out, c);
        if (on_at(p, SIM_FAULT_BIAS_JUMP, t_ns) &&
            (p->arg[SIM_FAULT_BIAS_JUMP].channels & (1u << c))) {
            *v += p->arg[SIM_FAULT_BIAS_JUMP].value;
        }
        if (on_at(p, SIM_FAULT_NOISE_BURST, t_ns) &&
            (p->arg[SIM_FAULT_NOISE_BURST].channels & (1u << c))) {
            *v += p->arg[SIM_FAULT_NOISE_BURST].value * sim_rng_gauss(&p->rng);
        }
        if (on_at(p, SIM_FAULT_SATURATION, t_ns) &&
            (p->arg[SIM_FAULT_SATURATION].channels & (1u << c))) {
            *v = p->arg[SIM_FAULT_SATURATION].value;
        }
    }
}

/* The user's hook alone without physics faults (a run without faults is unchanged), the
 * stage in front of it with one. */
static void install_error_model(struct sim_part *p)
{
    if ((p->active & PHYSICS_FAULTS) != 0u) {
        p->stage.apply = stage_apply;
        p->stage.ctx = p;
        p->ops->set_error_model(p->model, &p->stage);
    } else {
        p->ops->set_error_model(p->model, p->user.apply != NULL ? &p->user : NULL);
    }
}

void sim_part_bind(struct sim_part *p, const struct sim_part_ops *ops, void *model,
                   struct sim_clock *clk)
{
    if (p == NULL) {
        return;
    }
    memset(p, 0, sizeof(*p));
    p->ops = ops;
    p->model = model;
    p->clk = clk;
    if (ops != NULL && ops->get_error_model != NULL) {
        ops->get_error_model(model, &p->user);
    }
}

void sim_part_set_input(struct sim_part *p, const struct sim_inertial_input *in)
{
    if (p != NULL && p->ops != NULL && in != NULL) {
        p->ops->set_input(p->model, in);
    }
}

void sim_part_set_physics(struct sim_part *p, const struct sim_physics *phys)
{
    if (p != NULL && p->ops != NULL) {
        p->ops->set_physics(p->model, phys);
    }
}

void sim_part_set_error_model(struct sim_part *p, const struct sim_error_model *e)
{
    if (p == NULL || p->ops == NULL) {
        return;
    }
    if (e != NULL) {
        p->user = *e;
    } else {
        memset(&p->user, 0, sizeof(p->user));
    }
    install_error_model(p);
}

static uint64_t now(const struct sim_part *p)
{
    return p->clk != NULL ? p->clk->now_ns : 0u;
}

static void apply_wire(struct sim_part *p)
{
    struct sim_spi_slave *s = p->ops->slave != NULL ? p->ops->slave(p->model) : NULL;
    if (s == NULL) {
        return;
    }
    if (p->active & (1u << SIM_FAULT_MISO_STUCK_HIGH)) {
        s->miso_stuck = SIM_SPI_MISO_STUCK_HIGH;
    } else if (p->active & (1u << SIM_FAULT_MISO_STUCK_LOW)) {
        s->miso_stuck = SIM_SPI_MISO_STUCK_LOW;
    } else {
        s->miso_stuck = SIM_SPI_MISO_OK;
    }
    s->out_xor = (p->active & (1u << SIM_FAULT_CORRUPT_FRAME))
                     ? p->arg[SIM_FAULT_CORRUPT_FRAME].mask
                     : 0u;
}

int sim_part_inject(struct sim_part *p, enum sim_fault f, const struct sim_fault_arg *arg)
{
    struct sim_fault_arg a;
    const uint32_t bit = 1u << (unsigned)f;
    if (p == NULL || p->ops == NULL) {
        return INC_ERR_NULL;
    }
    if ((unsigned)f >= (unsigned)SIM_FAULT_COUNT) {
        return INC_ERR_INVAL;
    }
    a = arg != NULL ? *arg : sim_fault_default(f);
    if (a.channels == 0u) {
        a.channels = SIM_PART_INERTIAL;
    }
    if (bit & WIRE_FAULTS) {
        if (p->ops->slave == NULL || p->ops->slave(p->model) == NULL) {
            return INC_ERR_UNSUPPORTED;
        }
    } else if ((bit & PHYSICS_FAULTS) == 0u) {
        int err;
        if (p->ops->fault == NULL) {
            return INC_ERR_UNSUPPORTED;
        }
        err = p->ops->fault(p->model, f, &a, true);
        if (err != INC_OK) {
            return err;
        }
    }
    p->active |= bit;
    p->arg[f] = a;
    p->since_ns[f] = now(p);
    if (f == SIM_FAULT_FROZEN_OUTPUT) {
        p->frozen_valid = false;
    }
    if (f == SIM_FAULT_NOISE_BURST) {
        sim_rng_seed(&p->rng, a.seed);
    }
    if (bit & WIRE_FAULTS) {
        apply_wire(p);
    } else if (bit & PHYSICS_FAULTS) {
        install_error_model(p);
    }
    return INC_OK;
}

int sim_part_clear(struct sim_part *p, enum sim_fault f)
{
    const uint32_t bit = 1u << (unsigned)f;
    if (p == NULL || p->ops == NULL) {
        return INC_ERR_NULL;
    }
    if ((unsigned)f >= (unsigned)SIM_FAULT_COUNT) {
        return INC_ERR_INVAL;
    }
    if ((p->active & bit) == 0u) {
        return INC_OK;
    }
    p->active &= ~bit;
    if (bit & WIRE_FAULTS) {
        apply_wire(p);
    } else if (bit & PHYSICS_FAULTS) {
        install_error_model(p);
    } else {
        (void)p->ops->fault(p->model, f, &p->arg[f], false);
    }
    return INC_OK;
}

void sim_part_clear_all(struct sim_part *p)
{
    unsigned f;
    for (f = 0; f < (unsigned)SIM_FAULT_COUNT; f++) {
        (void)sim_part_clear(p, (enum sim_fault)f);
    }
}

bool sim_part_fault_active(const struct sim_part *p, enum sim_fault f)
{
    return p != NULL && (unsigned)f < (unsigned)SIM_FAULT_COUNT && (p->active & (1u << f)) != 0u;
}

uint16_t sim_part_peek(const struct sim_part *p, uint8_t addr)
{
    if (p == NULL || p->ops == NULL || p->ops->peek == NULL) {
        return 0;
    }
    return p->ops->peek(p->model, addr);
}

void sim_part_poke(struct sim_part *p, uint8_t addr, uint16_t value)
{
    if (p != NULL && p->ops != NULL && p->ops->poke != NULL) {
        p->ops->poke(p->model, addr, value);
    }
}

int sim_stuck_bit_fault(struct sim_stuck_bit *s, const struct sim_fault_arg *arg, bool on,
                        uint8_t addr_mask, unsigned width)
{
    if (arg->bit >= width) {
        return INC_ERR_INVAL;
    }
    s->addr = (uint8_t)(arg->addr & addr_mask);
    s->mask = on ? (uint16_t)(1u << arg->bit) : 0u;
    s->set = arg->level ? s->mask : 0u;
    return INC_OK;
}
