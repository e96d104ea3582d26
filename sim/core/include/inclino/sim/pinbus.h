/*
 * sim/pinbus.h - the wires of the simulated board.
 *
 * Each pin has one resolved logic level, computed from who drives it:
 *   - the master (the firmware, through the sim HAL port) drives a pin once it writes it;
 *   - device models drive pins by device id (MISO while selected, data-ready lines);
 *   - with no driver the pull decides: up -> 1, down -> 0, keeper -> the last level.
 * Two drivers that disagree are a contention, reported to the violation log; the pin then reads
 * 0 (a wired-AND, like a weak-high short). Every change of a resolved level is announced, with
 * the virtual time, to the listeners registered for that pin (SPI-slave decoders, the VCD
 * writer, the HAL's interrupt hooks). Listeners run synchronously and may drive pins themselves.
 */
#ifndef INCLINO_SIM_PINBUS_H
#define INCLINO_SIM_PINBUS_H

#include <stdbool.h>
#include <stdint.h>

#include "inclino/error.h"
#include "inclino/sim/clock.h"
#include "inclino/sim/violation.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SIM_PINBUS_MAX_PINS 32u
#define SIM_PINBUS_MAX_DEVICES 16u
#define SIM_PIN_MASK(pin) (1u << (pin))

enum sim_pull {
    SIM_PULL_KEEPER = 0, /* holds the last level (bus keeper) */
    SIM_PULL_UP = 1,
    SIM_PULL_DOWN = 2,
};

typedef void (*sim_pin_change_fn)(void *arg, unsigned pin, bool level, uint64_t t_ns);

/* Caller-owned listener node; register it once, keep it alive while the bus lives. */
struct sim_pin_listener {
    sim_pin_change_fn fn;
    void *arg;
    uint32_t mask; /* pins of interest: SIM_PIN_MASK(a) | SIM_PIN_MASK(b) */
    struct sim_pin_listener *next;
};

struct sim_pin {
    const char *name; /* NULL: pin not defined */
    enum sim_pull pull;
    bool level; /* resolved level */
    bool master_drives;
    bool master_level;
    uint16_t dev_mask;  /* devices driving */
    uint16_t dev_level; /* their levels */
};

struct sim_pinbus {
    struct sim_clock *clk;
    struct sim_violation_log *log; /* contention reports; may be NULL */
    struct sim_pin pin[SIM_PINBUS_MAX_PINS];
    struct sim_pin_listener *listeners;
    unsigned devices;
    uint64_t changes; /* resolved-level changes so far (statistics) */
};

void sim_pinbus_init(struct sim_pinbus *bus, struct sim_clock *clk, struct sim_violation_log *log);

/* Name a pin and set its pull; its level starts at the pull's level (keeper: initial). */
int sim_pinbus_define(struct sim_pinbus *bus, unsigned pin, const char *name, enum sim_pull pull,
                      bool initial);

/* A new device id for sim_pinbus_device_drive(); INC_ERR_NO_SPACE after SIM_PINBUS_MAX_DEVICES. */
int sim_pinbus_add_device(struct sim_pinbus *bus);

int sim_pinbus_listen(struct sim_pinbus *bus, struct sim_pin_listener *l);
int sim_pinbus_unlisten(struct sim_pinbus *bus, struct sim_pin_listener *l);

void sim_pinbus_master_write(struct sim_pinbus *bus, unsigned pin, bool level);
void sim_pinbus_master_release(struct sim_pinbus *bus, unsigned pin);
void sim_pinbus_device_drive(struct sim_pinbus *bus, unsigned dev, unsigned pin, bool level);
void sim_pinbus_device_release(struct sim_pinbus *bus, unsigned dev, unsigned pin);

/* The resolved level (false for an undefined pin). */
bool sim_pinbus_read(const struct sim_pinbus *bus, unsigned pin);

/* Pin number by name, or -1. */
int sim_pinbus_find(const struct sim_pinbus *bus, const char *name);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_SIM_PINBUS_H */
