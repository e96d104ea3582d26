/*
 * The call wrappers of inclino/sensor.h on a scripted ops table: INC_ERR_NULL for a NULL sensor,
 * ops table, op or output; every wrapper passes dev, its arguments and the op's result through;
 * sensor_read and sensor_next zero the sample on any error (no SENSOR_S_HAVE_* with an error);
 * sensor_next retries a stale read once after the next wait, and only once.
 */
#include <string.h>

#include "inclino/sensor.h"
#include "unit.h"

struct script {
    int wait_err[4]; /* results of the successive waits (then 0) */
    int read_err[4]; /* results of the successive reads (then 0) */
    unsigned waits, reads;
    uint32_t last_timeout;
    const void *last_cfg;
    int other_err;  /* result of read_diag, self_test, identity, info, init */
    unsigned other; /* calls of read_diag, self_test, identity, info */
};

static struct script sc;

/* Every op keeps its state through dev (the wrappers must pass it through unchanged). */
static int s_init(void *dev, const void *cfg)
{
    struct script *p = dev;
    CHECK(p == &sc);
    p->last_cfg = cfg;
    return p->other_err;
}

static int s_wait(void *dev, uint32_t timeout_ns)
{
    struct script *p = dev;
    CHECK(p == &sc);
    p->last_timeout = timeout_ns;
    return p->waits < 4u ? p->wait_err[p->waits++] : (p->waits++, INC_OK);
}

static int s_read(void *dev, struct sensor_sample *out)
{
    struct script *p = dev;
    const int err = p->reads < 4u ? p->read_err[p->reads] : INC_OK;
    CHECK(p == &sc);
    p->reads++;
    /* a driver that writes something before failing: the wrapper must clear it */
    out->accel_g[0] = (int32_t)(1000u + p->reads);
    out->flags = SENSOR_S_HAVE_ACCEL;
    out->missed = p->reads;
    out->t_ns = 42u;
    return err;
}

static int s_diag(void *dev, struct sensor_diag *out)
{
    struct script *p = dev;
    CHECK(p == &sc);
    p->other++;
    out->flags = SENSOR_D_ALARM;
    out->raw = 0x0100u;
    out->supply_v = 5;
    return p->other_err;
}

static int s_identity(void *dev, struct sensor_identity *out)
{
    struct script *p = dev;
    CHECK(p == &sc);
    p->other++;
    memset(out, 0, sizeof *out);
    out->family = SENSOR_FAMILY_SCA3000;
    out->product = 0x0D01u;
    return p->other_err;
}

static int s_info(void *dev, struct sensor_info *out)
{
    struct script *p = dev;
    CHECK(p == &sc);
    p->other++;
    out->accel_fs_g = FX_Q16_INT(3);
    out->gyro_fs_dps = 0;
    out->rate_mhz = 250000u;
    return p->other_err;
}

static const struct sensor_ops full = {s_init, s_wait, s_read, s_diag, s_diag, s_identity, s_info};
static const struct sensor_ops empty = {NULL, NULL, NULL, NULL, NULL, NULL, NULL};

static void reset(void)
{
    memset(&sc, 0, sizeof sc);
}

static void check_zero(const struct sensor_sample *s)
{
    unsigned i;
    for (i = 0; i < 3u; i++) {
        CHECK_EQ_INT(s->accel_g[i], 0);
        CHECK_EQ_INT(s->gyro_dps[i], 0);
    }
    CHECK_EQ_INT(s->temp_c, 0);
    CHECK_EQ_INT(s->flags, 0);
    CHECK_EQ_INT(s->missed, 0);
    CHECK_EQ_INT(s->t_ns, 0);
}

static void test_null_handling(void)
{
    const struct sensor none = {NULL, &sc}, hollow = {&empty, &sc}, ok = {&full, &sc};
    struct sensor_sample s;
    struct sensor_diag d;
    struct sensor_identity id;
    struct sensor_info info;
    const struct sensor *bad[3] = {NULL, &none, &hollow};
    unsigned k;
    reset();
    for (k = 0; k < 3u; k++) {
        memset(&s, 0x5A, sizeof s);
        CHECK_ERR(sensor_init(bad[k], NULL), INC_ERR_NULL);
        CHECK_ERR(sensor_wait_ready(bad[k], 0u), INC_ERR_NULL);
        CHECK_ERR(sensor_read(bad[k], &s), INC_ERR_NULL);
        check_zero(&s);
        memset(&s, 0x5A, sizeof s);
        CHECK_ERR(sensor_next(bad[k], 0u, &s), INC_ERR_NULL);
        check_zero(&s);
        CHECK_ERR(sensor_read_diag(bad[k], &d), INC_ERR_NULL);
        CHECK_ERR(sensor_self_test(bad[k], &d), INC_ERR_NULL);
        CHECK_ERR(sensor_get_identity(bad[k], &id), INC_ERR_NULL);
        CHECK_ERR(sensor_get_info(bad[k], &info), INC_ERR_NULL);
    }
    /* NULL outputs, with a complete table: the op is not called */
    CHECK_ERR(sensor_read(&ok, NULL), INC_ERR_NULL);
    CHECK_ERR(sensor_next(&ok, 0u, NULL), INC_ERR_NULL);
    CHECK_ERR(sensor_read_diag(&ok, NULL), INC_ERR_NULL);
    CHECK_ERR(sensor_self_test(&ok, NULL), INC_ERR_NULL);
    CHECK_ERR(sensor_get_identity(&ok, NULL), INC_ERR_NULL);
    CHECK_ERR(sensor_get_info(&ok, NULL), INC_ERR_NULL);
    CHECK_EQ_INT(sc.reads, 0);
    CHECK_EQ_INT(sc.waits, 0); /* sensor_next checks its output before it waits */
    CHECK_EQ_INT(sc.other, 0);
}

static void test_pass_through(void)
{
    const struct sensor ok = {&full, &sc};
    static const int cfg = 7;
    struct sensor_sample s;
    struct sensor_diag d;
    struct sensor_identity id;
    struct sensor_info info;
    reset();
    CHECK_OK(sensor_init(&ok, &cfg));
    CHECK(sc.last_cfg == &cfg);
    CHECK_OK(sensor_wait_ready(&ok, 1234u));
    CHECK_EQ_INT(sc.last_timeout, 1234);
    CHECK_OK(sensor_read(&ok, &s));
    CHECK_EQ_INT(s.accel_g[0], 1001);
    CHECK_EQ_INT(s.flags, SENSOR_S_HAVE_ACCEL);
    CHECK_OK(sensor_read_diag(&ok, &d));
    CHECK_EQ_INT(d.flags, SENSOR_D_ALARM);
    CHECK_OK(sensor_self_test(&ok, &d));
    CHECK_OK(sensor_get_identity(&ok, &id));
    CHECK_EQ_INT(id.family, SENSOR_FAMILY_SCA3000);
    CHECK_OK(sensor_get_info(&ok, &info));
    CHECK_EQ_INT(info.rate_mhz, 250000);
    CHECK_EQ_INT(sc.other, 4);
    sc.other_err = INC_ERR_BUS;
    CHECK_ERR(sensor_init(&ok, &cfg), INC_ERR_BUS);
    CHECK_ERR(sensor_read_diag(&ok, &d), INC_ERR_BUS);
    CHECK_ERR(sensor_self_test(&ok, &d), INC_ERR_BUS);
    CHECK_ERR(sensor_get_identity(&ok, &id), INC_ERR_BUS);
    CHECK_ERR(sensor_get_info(&ok, &info), INC_ERR_BUS);
    /* a failed read: the op's error, the sample zeroed */
    reset();
    sc.read_err[0] = INC_ERR_DEVICE;
    CHECK_ERR(sensor_read(&ok, &s), INC_ERR_DEVICE);
    check_zero(&s);
}

static void test_next_stale_retry(void)
{
    const struct sensor ok = {&full, &sc};
    struct sensor_sample s;
    /* plain: one wait, one read */
    reset();
    CHECK_OK(sensor_next(&ok, 99u, &s));
    CHECK_EQ_INT(sc.waits, 1);
    CHECK_EQ_INT(sc.reads, 1);
    CHECK_EQ_INT(sc.last_timeout, 99);
    CHECK_EQ_INT(s.accel_g[0], 1001);
    /* stale once: a second wait and read, the second sample handed out */
    reset();
    sc.read_err[0] = INC_ERR_STALE;
    CHECK_OK(sensor_next(&ok, 0u, &s));
    CHECK_EQ_INT(sc.waits, 2);
    CHECK_EQ_INT(sc.reads, 2);
    CHECK_EQ_INT(s.accel_g[0], 1002);
    CHECK_EQ_INT(s.missed, 2);
    /* stale twice: retried only once, the error returned, the sample zeroed */
    reset();
    sc.read_err[0] = sc.read_err[1] = INC_ERR_STALE;
    CHECK_ERR(sensor_next(&ok, 0u, &s), INC_ERR_STALE);
    CHECK_EQ_INT(sc.waits, 2);
    CHECK_EQ_INT(sc.reads, 2);
    check_zero(&s);
    /* stale, then the second wait times out: nothing read, the timeout returned */
    reset();
    sc.read_err[0] = INC_ERR_STALE;
    sc.wait_err[1] = INC_ERR_TIMEOUT;
    CHECK_ERR(sensor_next(&ok, 0u, &s), INC_ERR_TIMEOUT);
    CHECK_EQ_INT(sc.reads, 1);
    check_zero(&s);
    /* the first wait times out: no read at all */
    reset();
    sc.wait_err[0] = INC_ERR_TIMEOUT;
    memset(&s, 0x5A, sizeof s);
    CHECK_ERR(sensor_next(&ok, 0u, &s), INC_ERR_TIMEOUT);
    CHECK_EQ_INT(sc.reads, 0);
    check_zero(&s);
    /* another read error is not retried */
    reset();
    sc.read_err[0] = INC_ERR_BUS;
    CHECK_ERR(sensor_next(&ok, 0u, &s), INC_ERR_BUS);
    CHECK_EQ_INT(sc.waits, 1);
    CHECK_EQ_INT(sc.reads, 1);
    check_zero(&s);
}

/* The safe states the ops write on error: everything zero, no flag, family NONE; NULL ignored. */
static void test_clear(void)
{
    struct sensor_sample smp;
    struct sensor_identity id;
    struct sensor_diag d;
    memset(&smp, 0x5A, sizeof smp);
    memset(&id, 0x5A, sizeof id);
    memset(&d, 0x5A, sizeof d);
    sensor_sample_clear(&smp);
    sensor_identity_clear(&id);
    sensor_diag_clear(&d);
    CHECK_EQ_INT(smp.accel_g[0] | smp.accel_g[1] | smp.accel_g[2], 0);
    CHECK_EQ_INT(smp.gyro_dps[0] | smp.gyro_dps[1] | smp.gyro_dps[2] | smp.temp_c, 0);
    CHECK_EQ_INT(smp.flags, 0);
    CHECK_EQ_INT(smp.missed, 0);
    CHECK_EQ_INT(smp.t_ns, 0);
    CHECK_EQ_INT(id.family, SENSOR_FAMILY_NONE);
    CHECK_EQ_INT(id.product | id.revision | id.serial | id.lot_id1 | id.lot_id2, 0);
    CHECK_EQ_INT(d.flags | d.raw, 0);
    CHECK_EQ_INT(d.supply_v, 0);
    sensor_sample_clear(NULL);
    sensor_identity_clear(NULL);
    sensor_diag_clear(NULL);
}

int main(void)
{
    UNIT_RUN(test_clear);
    UNIT_RUN(test_null_handling);
    UNIT_RUN(test_pass_through);
    UNIT_RUN(test_next_stale_retry);
    return unit_report();
}
