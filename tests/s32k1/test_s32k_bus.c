/* The simulated S32K1 bus: mapping, dispatch by address and width, unmapped accesses, hook. */
#include "inclino/s32k_mmio.h"
#include "inclino/sim/s32k_bus.h"
#include "unit.h"

#include <stddef.h>

struct regfile {
    uint32_t last_offset;
    uint32_t last_value;
    unsigned last_width;
    uint32_t reads;
};

static uint32_t rf_read(void *ctx, uint32_t offset, unsigned width)
{
    struct regfile *r = ctx;
    r->reads++;
    r->last_offset = offset;
    r->last_width = width;
    return 0xA5000000u | offset;
}

static void rf_write(void *ctx, uint32_t offset, uint32_t value, unsigned width)
{
    struct regfile *r = ctx;
    r->last_offset = offset;
    r->last_value = value;
    r->last_width = width;
}

static const struct s32k_bus_region_ops rf_ops = {rf_read, rf_write};

static void count_hook(void *ctx)
{
    (*(unsigned *)ctx)++;
}

static void test_map_rejects_bad_regions(void)
{
    struct regfile a = {0};
    s32k_bus_reset();
    CHECK_ERR(s32k_bus_map(0x4002C000u, 0x1000u, NULL, &a), INC_ERR_NULL);
    CHECK_ERR(s32k_bus_map(0x4002C000u, 0u, &rf_ops, &a), INC_ERR_INVAL);
    CHECK_ERR(s32k_bus_map(0xFFFFF000u, 0x2000u, &rf_ops, &a), INC_ERR_INVAL);
    CHECK_OK(s32k_bus_map(0x4002C000u, 0x1000u, &rf_ops, &a));
    CHECK_ERR(s32k_bus_map(0x4002CFFCu, 0x10u, &rf_ops, &a), INC_ERR_INVAL);
    CHECK_OK(s32k_bus_map(0x4002B000u, 0x1000u, &rf_ops, &a)); /* adjacent is fine */
    for (uint32_t i = 2; i < S32K_BUS_MAX_REGIONS; i++) {
        CHECK_OK(s32k_bus_map(0x50000000u + i * 0x100u, 0x100u, &rf_ops, &a));
    }
    CHECK_ERR(s32k_bus_map(0x60000000u, 0x100u, &rf_ops, &a), INC_ERR_NO_SPACE);
}

static void test_dispatch_by_address_and_width(void)
{
    struct regfile a = {0}, b = {0};
    unsigned hooks = 0;
    s32k_bus_reset();
    CHECK_OK(s32k_bus_map(0x4002C000u, 0x1000u, &rf_ops, &a));
    CHECK_OK(s32k_bus_map(0x40020000u, 0x1000u, &rf_ops, &b));
    s32k_bus_set_hook(count_hook, &hooks);

    CHECK_EQ_HEX(s32k_mmio_read32(0x4002C010u), 0xA5000010u);
    CHECK_EQ_HEX(a.last_offset, 0x10u);
    CHECK_EQ_HEX(a.last_width, 4u);
    s32k_mmio_write8(0x40020007u, 0x5Au);
    CHECK_EQ_HEX(b.last_offset, 7u);
    CHECK_EQ_HEX(b.last_value, 0x5Au);
    CHECK_EQ_HEX(b.last_width, 1u);
    CHECK_EQ_HEX(s32k_mmio_read16(0x40020002u), 0x0002u); /* truncated to the width */
    s32k_mmio_set32(0x4002C004u, 0x3u);
    CHECK_EQ_HEX(a.last_value, 0xA5000007u);
    s32k_mmio_modify32(0x4002C008u, 0xFFu, 0x1234u);
    CHECK_EQ_HEX(a.last_value, 0xA5000034u);
    CHECK_EQ_HEX(hooks, 7u);
    CHECK_EQ_HEX(s32k_bus_stats()->unmapped_reads, 0u);
    CHECK_EQ_HEX(s32k_bus_stats()->misaligned, 0u);
}

static void test_unmapped_and_misaligned_are_counted(void)
{
    struct regfile a = {0};
    s32k_bus_reset();
    CHECK_OK(s32k_bus_map(0x4002C000u, 0x1000u, &rf_ops, &a));
    CHECK_EQ_HEX(s32k_mmio_read32(0x40030000u), 0u);
    s32k_mmio_write32(0x4002CFFEu, 1u); /* straddles the end of the region */
    CHECK_EQ_HEX(s32k_bus_stats()->unmapped_reads, 1u);
    CHECK_EQ_HEX(s32k_bus_stats()->unmapped_writes, 1u);
    CHECK_EQ_HEX(s32k_bus_stats()->last_unmapped, 0x4002CFFEu);
    CHECK_EQ_HEX(s32k_bus_stats()->misaligned, 1u);
    CHECK_EQ_HEX(a.reads, 0u);
    s32k_bus_reset();
    CHECK_EQ_HEX(s32k_bus_stats()->unmapped_writes, 0u);
}

int main(void)
{
    UNIT_RUN(test_map_rejects_bad_regions);
    UNIT_RUN(test_dispatch_by_address_and_width);
    UNIT_RUN(test_unmapped_and_misaligned_are_counted);
    return unit_report();
}
