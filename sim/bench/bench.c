/* bench.c - see sim/bench.h. */
#include "inclino/sim/bench.h"

#include <string.h>

void sim_bench_adis16255_cfg(struct sim_board *b, unsigned slot, struct sim_adis16255_cfg *c)
{
    memset(c, 0, sizeof(*c));
    c->name = "adis16255";
    c->bus = &b->bus;
    c->cs = SIM_BOARD_CS(slot);
    c->sclk = SIM_BOARD_SCLK;
    c->mosi = SIM_BOARD_MOSI;
    c->miso = SIM_BOARD_MISO;
    c->dio0 = (int)SIM_BOARD_DR(slot);
    c->dio1 = slot < 3u ? (int)SIM_BOARD_DR(slot + 1u) : -1;
    c->axis = 2;
    c->log = &b->log;
    c->seed = 16255;
    c->endurance = 0x0010;
}

void sim_bench_adis_imu_cfg(struct sim_board *b, unsigned slot, enum sim_adis_imu_variant v,
                            struct sim_adis_imu_cfg *c)
{
    memset(c, 0, sizeof(*c));
    c->variant = v;
    c->bus = &b->bus;
    c->cs = SIM_BOARD_CS(slot);
    c->sclk = SIM_BOARD_SCLK;
    c->mosi = SIM_BOARD_MOSI;
    c->miso = SIM_BOARD_MISO;
    c->dio1 = SIM_BOARD_DR(slot);
    c->dio2 = slot < 3u ? SIM_BOARD_DR(slot + 1u) : SIM_ADIS_IMU_NO_PIN;
    c->log = &b->log;
    c->seed = 1234u + (uint64_t)v;
    c->power_on_busy = true;
}

void sim_bench_sca3000_cfg(struct sim_board *b, unsigned slot, enum sim_sca3000_variant v,
                           struct sim_sca3000_cfg *c)
{
    memset(c, 0, sizeof(*c));
    c->bus = &b->bus;
    c->cs = SIM_BOARD_CS(slot);
    c->sclk = SIM_BOARD_SCLK;
    c->mosi = SIM_BOARD_MOSI;
    c->miso = SIM_BOARD_MISO;
    c->int_pin = SIM_BOARD_DR(slot);
    c->variant = v;
    c->log = &b->log;
}

void sim_bench_loopback_cfg(struct sim_board *b, unsigned slot, struct sim_loopback_cfg *c)
{
    memset(c, 0, sizeof(*c));
    c->bus = &b->bus;
    c->cs = SIM_BOARD_CS(slot);
    c->sclk = SIM_BOARD_SCLK;
    c->mosi = SIM_BOARD_MOSI;
    c->miso = SIM_BOARD_MISO;
    c->mode = 3;
    c->bits = 16;
    c->log = &b->log;
}

int sim_bench_init(struct sim_bench *b)
{
    if (b == NULL) {
        return INC_ERR_NULL;
    }
    memset(b, 0, sizeof(*b));
    return sim_board_init(&b->board);
}

int sim_bench_add_adis16255(struct sim_bench *b, const struct sim_adis16255_cfg *c)
{
    int err = sim_adis16255_init(&b->m.adis16255, c);
    if (err == INC_OK) {
        b->kind = SIM_BENCH_ADIS16255;
        sim_adis16255_part(&b->m.adis16255, &b->part);
    }
    return err;
}

int sim_bench_add_adis_imu(struct sim_bench *b, const struct sim_adis_imu_cfg *c)
{
    int err = sim_adis_imu_init(&b->m.adis_imu, c);
    if (err == INC_OK) {
        b->kind = SIM_BENCH_ADIS_IMU;
        sim_adis_imu_part(&b->m.adis_imu, &b->part);
    }
    return err;
}

int sim_bench_add_sca3000(struct sim_bench *b, const struct sim_sca3000_cfg *c)
{
    int err = sim_sca3000_init(&b->m.sca3000, c);
    if (err == INC_OK) {
        b->kind = SIM_BENCH_SCA3000;
        sim_sca3000_part(&b->m.sca3000, &b->part);
    }
    return err;
}

void sim_bench_wait_ns(struct sim_bench *b, uint64_t ns)
{
    sim_clock_advance_to(&b->board.clk, b->board.clk.now_ns + ns);
}
