/* s32k_bus.c - see inclino/sim/s32k_bus.h. */
#include "inclino/sim/s32k_bus.h"

#include <stddef.h>

#include "inclino/s32k_mmio.h"

struct region {
    uint32_t base;
    uint32_t size;
    const struct s32k_bus_region_ops *ops;
    void *ctx;
};

static struct region regions[S32K_BUS_MAX_REGIONS];
static unsigned n_regions;
static struct s32k_bus_stats stats;
static void (*hook_fn)(void *ctx);
static void *hook_ctx;
static const struct s32k_bus_meter *meter;

void s32k_bus_set_meter(const struct s32k_bus_meter *m)
{
    meter = m;
}

void s32k_bus_meter_enter(void)
{
    if (meter != NULL) {
        meter->enter();
    }
}

void s32k_bus_meter_leave(void)
{
    if (meter != NULL) {
        meter->leave();
    }
}

void s32k_bus_reset(void)
{
    meter = NULL;
    n_regions = 0;
    hook_fn = NULL;
    hook_ctx = NULL;
    stats = (struct s32k_bus_stats){0};
}

int s32k_bus_map(uint32_t base, uint32_t size, const struct s32k_bus_region_ops *ops, void *ctx)
{
    if (ops == NULL || ops->read == NULL || ops->write == NULL) {
        return INC_ERR_NULL;
    }
    if (size == 0u || (uint64_t)base + size > (uint64_t)UINT32_MAX + 1u) {
        return INC_ERR_INVAL;
    }
    for (unsigned i = 0; i < n_regions; i++) {
        const struct region *r = &regions[i];
        if ((uint64_t)base < (uint64_t)r->base + r->size &&
            (uint64_t)r->base < (uint64_t)base + size) {
            return INC_ERR_INVAL;
        }
    }
    if (n_regions >= S32K_BUS_MAX_REGIONS) {
        return INC_ERR_NO_SPACE;
    }
    regions[n_regions++] = (struct region){base, size, ops, ctx};
    return 0;
}

void s32k_bus_set_hook(void (*hook)(void *ctx), void *ctx)
{
    hook_fn = hook;
    hook_ctx = ctx;
}

const struct s32k_bus_stats *s32k_bus_stats(void)
{
    return &stats;
}

static const struct region *find(uint32_t addr, unsigned width)
{
    if ((addr & (width - 1u)) != 0u) {
        stats.misaligned++;
    }
    for (unsigned i = 0; i < n_regions; i++) {
        const struct region *r = &regions[i];
        if (addr >= r->base && (uint64_t)addr + width <= (uint64_t)r->base + r->size) {
            return r;
        }
    }
    stats.last_unmapped = addr;
    return NULL;
}

static uint32_t bus_read(uint32_t addr, unsigned width)
{
    stats.reads++;
    const struct region *r = find(addr, width);
    uint32_t v = 0;
    if (r != NULL) {
        v = r->ops->read(r->ctx, addr - r->base, width);
    } else {
        stats.unmapped_reads++;
    }
    if (hook_fn != NULL) {
        hook_fn(hook_ctx);
    }
    return v;
}

static void bus_write(uint32_t addr, uint32_t value, unsigned width)
{
    stats.writes++;
    const struct region *r = find(addr, width);
    if (r != NULL) {
        r->ops->write(r->ctx, addr - r->base, value, width);
    } else {
        stats.unmapped_writes++;
    }
    if (hook_fn != NULL) {
        hook_fn(hook_ctx);
    }
}

uint32_t s32k_mmio_read32(uint32_t addr)
{
    uint32_t v;
    s32k_bus_meter_enter();
    v = bus_read(addr, 4u);
    s32k_bus_meter_leave();
    return v;
}

void s32k_mmio_write32(uint32_t addr, uint32_t value)
{
    s32k_bus_meter_enter();
    bus_write(addr, value, 4u);
    s32k_bus_meter_leave();
}

uint16_t s32k_mmio_read16(uint32_t addr)
{
    uint16_t v;
    s32k_bus_meter_enter();
    v = (uint16_t)bus_read(addr, 2u);
    s32k_bus_meter_leave();
    return v;
}

void s32k_mmio_write16(uint32_t addr, uint16_t value)
{
    s32k_bus_meter_enter();
    bus_write(addr, value, 2u);
    s32k_bus_meter_leave();
}

uint8_t s32k_mmio_read8(uint32_t addr)
{
    uint8_t v;
    s32k_bus_meter_enter();
    v = (uint8_t)bus_read(addr, 1u);
    s32k_bus_meter_leave();
    return v;
}

void s32k_mmio_write8(uint32_t addr, uint8_t value)
{
    s32k_bus_meter_enter();
    bus_write(addr, value, 1u);
    s32k_bus_meter_leave();
}
