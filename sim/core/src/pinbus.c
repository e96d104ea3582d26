/* pinbus.c - see sim/pinbus.h. */
#include "inclino/sim/pinbus.h"

#include <string.h>

void sim_pinbus_init(struct sim_pinbus *bus, struct sim_clock *clk, struct sim_violation_log *log)
{
    if (bus == NULL) {
        return;
    }
    memset(bus, 0, sizeof(*bus));
    bus->clk = clk;
    bus->log = log;
}

int sim_pinbus_define(struct sim_pinbus *bus, unsigned pin, const char *name, enum sim_pull pull,
                      bool initial)
{
    struct sim_pin *p;
    if (bus == NULL || name == NULL) {
        return INC_ERR_NULL;
    }
    if (pin >= SIM_PINBUS_MAX_PINS || pull > SIM_PULL_DOWN) {
        return INC_ERR_INVAL;
    }
    p = &bus->pin[pin];
    memset(p, 0, sizeof(*p));
    p->name = name;
    p->pull = pull;
    p->level = pull == SIM_PULL_UP ? true : pull == SIM_PULL_DOWN ? false : initial;
    return INC_OK;
}

int sim_pinbus_add_device(struct sim_pinbus *bus)
{
    if (bus == NULL) {
        return INC_ERR_NULL;
    }
    if (bus->devices >= SIM_PINBUS_MAX_DEVICES) {
        return INC_ERR_NO_SPACE;
    }
    return (int)bus->devices++;
}

int sim_pinbus_listen(struct sim_pinbus *bus, struct sim_pin_listener *l)
{
    if (bus == NULL || l == NULL || l->fn == NULL) {
        return INC_ERR_NULL;
    }
    /* Append, so listeners hear changes in registration order. */
    l->next = NULL;
    if (bus->listeners == NULL) {
        bus->listeners = l;
    } else {
        struct sim_pin_listener *it = bus->listeners;
        while (it->next != NULL) {
            if (it == l) {
                return INC_ERR_STATE;
            }
            it = it->next;
        }
        if (it == l) {
            return INC_ERR_STATE;
        }
        it->next = l;
    }
    return INC_OK;
}

int sim_pinbus_unlisten(struct sim_pinbus *bus, struct sim_pin_listener *l)
{
    struct sim_pin_listener **pp;
    if (bus == NULL || l == NULL) {
        return INC_ERR_NULL;
    }
    for (pp = &bus->listeners; *pp != NULL; pp = &(*pp)->next) {
        if (*pp == l) {
            *pp = l->next;
            l->next = NULL;
            return INC_OK;
        }
    }
    return INC_ERR_INVAL;
}

static uint64_t now(const struct sim_pinbus *bus)
{
    return bus->clk != NULL ? bus->clk->now_ns : 0;
}

/* Recompute a pin's level from its drivers and announce a change. */
static void resolve(struct sim_pinbus *bus, unsigned pin)
{
    struct sim_pin *p = &bus->pin[pin];
    bool level;
    bool conflict = false;

    if (p->master_drives) {
        level = p->master_level;
        if (p->dev_mask != 0 &&
            (p->dev_level & p->dev_mask) != (p->master_level ? p->dev_mask : 0)) {
            conflict = true;
        }
    } else if (p->dev_mask != 0) {
        uint16_t high = p->dev_level & p->dev_mask;
        if (high == p->dev_mask) {
            level = true;
        } else if (high == 0) {
            level = false;
        } else {
            conflict = true;
            level = false;
        }
    } else if (p->pull == SIM_PULL_UP) {
        level = true;
    } else if (p->pull == SIM_PULL_DOWN) {
        level = false;
    } else {
        level = p->level;
    }
    if (conflict) {
        sim_violation_report(bus->log, SIM_VIOL_CONTENTION, p->name, now(bus), 0, 0);
    }
    if (level != p->level) {
        struct sim_pin_listener *l;
        p->level = level;
        bus->changes++;
        for (l = bus->listeners; l != NULL; l = l->next) {
            if (l->mask & SIM_PIN_MASK(pin)) {
                l->fn(l->arg, pin, level, now(bus));
            }
        }
    }
}

void sim_pinbus_master_write(struct sim_pinbus *bus, unsigned pin, bool level)
{
    if (bus == NULL || pin >= SIM_PINBUS_MAX_PINS || bus->pin[pin].name == NULL) {
        return;
    }
    bus->pin[pin].master_drives = true;
    bus->pin[pin].master_level = level;
    resolve(bus, pin);
}

void sim_pinbus_master_release(struct sim_pinbus *bus, unsigned pin)
{
    if (bus == NULL || pin >= SIM_PINBUS_MAX_PINS || bus->pin[pin].name == NULL) {
        return;
    }
    bus->pin[pin].master_drives = false;
    resolve(bus, pin);
}

void sim_pinbus_device_drive(struct sim_pinbus *bus, unsigned dev, unsigned pin, bool level)
{
    struct sim_pin *p;
    if (bus == NULL || pin >= SIM_PINBUS_MAX_PINS || dev >= SIM_PINBUS_MAX_DEVICES ||
        bus->pin[pin].name == NULL) {
        return;
    }
    p = &bus->pin[pin];
    p->dev_mask = (uint16_t)(p->dev_mask | (1u << dev));
    if (level) {
        p->dev_level = (uint16_t)(p->dev_level | (1u << dev));
    } else {
        p->dev_level = (uint16_t)(p->dev_level & ~(1u << dev));
    }
    resolve(bus, pin);
}

void sim_pinbus_device_release(struct sim_pinbus *bus, unsigned dev, unsigned pin)
{
    struct sim_pin *p;
    if (bus == NULL || pin >= SIM_PINBUS_MAX_PINS || dev >= SIM_PINBUS_MAX_DEVICES ||
        bus->pin[pin].name == NULL) {
        return;
    }
    p = &bus->pin[pin];
    p->dev_mask = (uint16_t)(p->dev_mask & ~(1u << dev));
    resolve(bus, pin);
}

bool sim_pinbus_read(const struct sim_pinbus *bus, unsigned pin)
{
    if (bus == NULL || pin >= SIM_PINBUS_MAX_PINS) {
        return false;
    }
    return bus->pin[pin].level;
}

int sim_pinbus_find(const struct sim_pinbus *bus, const char *name)
{
    unsigned i;
    if (bus == NULL || name == NULL) {
        return -1;
    }
    for (i = 0; i < SIM_PINBUS_MAX_PINS; i++) {
        if (bus->pin[i].name != NULL && strcmp(bus->pin[i].name, name) == 0) {
            return (int)i;
        }
    }
    return -1;
}
