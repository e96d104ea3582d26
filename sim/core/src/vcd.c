/* vcd.c - see sim/vcd.h. */
#include "inclino/sim/vcd.h"

#include <string.h>

/* VCD identifier of pin i: one printable character from '!' on. */
static char vcd_id(unsigned pin)
{
    return (char)('!' + pin);
}

static void put_time(struct sim_vcd *v, uint64_t t)
{
    if (!v->time_written || t != v->last_t) {
        if (fprintf(v->f, "#%llu\n", (unsigned long long)t) < 0) {
            v->io_error = true;
        }
        v->last_t = t;
        v->time_written = true;
    }
}

static void on_change(void *arg, unsigned pin, bool level, uint64_t t)
{
    struct sim_vcd *v = arg;
    if (v->f == NULL) {
        return;
    }
    put_time(v, t);
    if (fprintf(v->f, "%c%c\n", level ? '1' : '0', vcd_id(pin)) < 0) {
        v->io_error = true;
    }
    v->changes++;
}

int sim_vcd_start(struct sim_vcd *v, FILE *f, struct sim_pinbus *bus, uint32_t pin_mask)
{
    unsigned i;
    uint32_t mask = 0;
    uint64_t t0;
    if (v == NULL || f == NULL || bus == NULL) {
        return INC_ERR_NULL;
    }
    memset(v, 0, sizeof(*v));
    for (i = 0; i < SIM_PINBUS_MAX_PINS; i++) {
        if ((pin_mask & SIM_PIN_MASK(i)) && bus->pin[i].name != NULL) {
            mask |= SIM_PIN_MASK(i);
        }
    }
    if (mask == 0) {
        return INC_ERR_INVAL;
    }
    v->f = f;
    v->bus = bus;
    v->mask = mask;
    t0 = bus->clk != NULL ? bus->clk->now_ns : 0;
    fprintf(v->f, "$version Inclino simulated board $end\n");
    fprintf(v->f, "$timescale 1 ns $end\n");
    fprintf(v->f, "$scope module board $end\n");
    for (i = 0; i < SIM_PINBUS_MAX_PINS; i++) {
        if (mask & SIM_PIN_MASK(i)) {
            fprintf(v->f, "$var wire 1 %c %s $end\n", vcd_id(i), bus->pin[i].name);
        }
    }
    fprintf(v->f, "$upscope $end\n$enddefinitions $end\n");
    put_time(v, t0);
    fprintf(v->f, "$dumpvars\n");
    for (i = 0; i < SIM_PINBUS_MAX_PINS; i++) {
        if (mask & SIM_PIN_MASK(i)) {
            fprintf(v->f, "%c%c\n", bus->pin[i].level ? '1' : '0', vcd_id(i));
        }
    }
    if (fprintf(v->f, "$end\n") < 0) {
        v->io_error = true;
    }
    v->listener.fn = on_change;
    v->listener.arg = v;
    v->listener.mask = mask;
    return sim_pinbus_listen(bus, &v->listener);
}

int sim_vcd_open(struct sim_vcd *v, const char *path, struct sim_pinbus *bus, uint32_t pin_mask)
{
    FILE *f;
    int err;
    if (v == NULL || path == NULL || bus == NULL) {
        return INC_ERR_NULL;
    }
    f = fopen(path, "w");
    if (f == NULL) {
        memset(v, 0, sizeof(*v));
        return INC_ERR_IO;
    }
    err = sim_vcd_start(v, f, bus, pin_mask);
    if (err != INC_OK) {
        (void)fclose(f);
        v->f = NULL;
        return err;
    }
    v->owns_file = true;
    return INC_OK;
}

int sim_vcd_stop(struct sim_vcd *v)
{
    int err = INC_OK;
    if (v == NULL) {
        return INC_ERR_NULL;
    }
    if (v->f == NULL) {
        return INC_ERR_STATE;
    }
    sim_pinbus_unlisten(v->bus, &v->listener);
    /* A last time stamp so viewers show the final levels for a while. */
    if (v->bus->clk != NULL) {
        put_time(v, v->bus->clk->now_ns + 1000u);
    }
    if (fflush(v->f) != 0 || ferror(v->f) || v->io_error) {
        err = INC_ERR_IO;
    }
    if (v->owns_file && fclose(v->f) != 0) {
        err = INC_ERR_IO;
    }
    v->f = NULL;
    return err;
}

int sim_vcd_close(struct sim_vcd *v)
{
    return sim_vcd_stop(v);
}
