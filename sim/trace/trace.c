/* trace.c - register-traffic record and replay (see sim/trace.h, docs/traces.md). */
#include "inclino/sim/trace.h"

#include <ctype.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "inclino/sim/line.h"

#define TRACE_HEADER "# inclino-trace 1"

/* ------------------------------------------------------------------ format */

int trace_write_record(FILE *f, const struct trace_record *r)
{
    unsigned i;
    int w = 4;
    if (f == NULL || r == NULL) {
        return INC_ERR_NULL;
    }
    if (r->kind == TRACE_IRQ) {
        return fprintf(f, "I t=%llu pin=%u\n", (unsigned long long)r->t_ns, r->pin) < 0 ? INC_ERR_IO
                                                                                        : INC_OK;
    }
    if (r->bits == 8u) {
        w = 2;
    }
    if (fprintf(f, "F t=%llu cs=%u bits=%u mosi=", (unsigned long long)r->t_ns, r->pin, r->bits) <
        0) {
        return INC_ERR_IO;
    }
    for (i = 0; i < r->n; i++) {
        fprintf(f, i ? ",%0*X" : "%0*X", w, r->mosi[i]);
    }
    fprintf(f, " miso=");
    for (i = 0; i < r->n; i++) {
        fprintf(f, i ? ",%0*X" : "%0*X", w, r->miso[i]);
    }
    return fprintf(f, "\n") < 0 ? INC_ERR_IO : INC_OK;
}

static int fail_msg(char *msg, size_t len, unsigned line, const char *what)
{
    if (msg != NULL && len > 0) {
        snprintf(msg, len, "trace line %u: %s", line, what);
    }
    return INC_ERR_FORMAT;
}

static bool is_blank(char c)
{
    return c == ' ' || c == '\t';
}

/*
 * Parse blanks (at least one: fields are separated, docs/traces.md), "key=", then an unsigned
 * decimal number <= max. Digits are accumulated here rather than with strtoull, which would
 * saturate a value beyond 64 bits to UINT64_MAX and let it pass as a valid time.
 */
static const char *parse_num(const char *p, const char *key, unsigned long long max,
                             unsigned long long *out)
{
    size_t kl = strlen(key);
    unsigned long long v = 0;
    if (!is_blank(*p)) {
        return NULL;
    }
    while (is_blank(*p))
        p++;
    if (strncmp(p, key, kl) != 0 || !isdigit((unsigned char)p[kl])) {
        return NULL;
    }
    p += kl;
    while (isdigit((unsigned char)*p)) {
        const unsigned d = (unsigned)(*p - '0');
        if (v > (max - d) / 10u) {
            return NULL; /* beyond max (or beyond 64 bits) */
        }
        v = v * 10u + d;
        p++;
    }
    *out = v;
    return p;
}

static int hex_digit(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

/* Parse blanks (at least one), "key=", then comma-separated words of 1..4 hex digits (no "0x"). */
static const char *parse_words(const char *p, const char *key, unsigned bits, uint16_t *w,
                               unsigned *n)
{
    size_t kl = strlen(key);
    const unsigned max = bits == 8u ? 0xFFu : 0xFFFFu;
    unsigned k = 0;
    if (!is_blank(*p)) {
        return NULL;
    }
    while (is_blank(*p))
        p++;
    if (strncmp(p, key, kl) != 0) {
        return NULL;
    }
    p += kl;
    for (;;) {
        unsigned v = 0, digits = 0;
        while (hex_digit(*p) >= 0) {
            if (++digits > 4u) {
                return NULL;
            }
            v = v * 16u + (unsigned)hex_digit(*p);
            p++;
        }
        if (digits == 0 || v > max || k == TRACE_MAX_WORDS) {
            return NULL;
        }
        w[k++] = (uint16_t)v;
        if (*p != ',') {
            break;
        }
        p++;
    }
    *n = k;
    return p;
}

static bool rest_is_blank(const char *p)
{
    while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n')
        p++;
    return *p == '\0';
}

int trace_parse_next(FILE *f, unsigned *line, struct trace_record *r, char *msg, size_t msg_len)
{
    char buf[TRACE_LINE_MAX + 1u];
    int got;
    if (f == NULL || line == NULL || r == NULL) {
        return INC_ERR_NULL;
    }
    while ((got = sim_read_line(f, buf, sizeof(buf))) != SIM_LINE_EOF) {
        const char *p = buf;
        unsigned long long v;
        (*line)++;
        if (got == SIM_LINE_TOO_LONG) {
            return fail_msg(msg, msg_len, *line, "line too long");
        }
        if (got == SIM_LINE_NUL) {
            return fail_msg(msg, msg_len, *line, "NUL byte in the line");
        }
        if (got == SIM_LINE_IO) {
            if (msg != NULL && msg_len > 0) {
                snprintf(msg, msg_len, "trace line %u: read error", *line);
            }
            return INC_ERR_IO;
        }
        while (is_blank(*p))
            p++;
        if (*p == '#' || rest_is_blank(p)) {
            continue;
        }
        memset(r, 0, offsetof(struct trace_record, mosi));
        r->line = *line;
        if (p[0] == 'I' && p[1] == ' ') {
            r->kind = TRACE_IRQ;
            p = parse_num(p + 1, "t=", UINT64_MAX, &v);
            if (p == NULL) return fail_msg(msg, msg_len, *line, "bad or missing t=");
            r->t_ns = v;
            p = parse_num(p, "pin=", TRACE_PIN_MAX, &v);
            if (p == NULL) return fail_msg(msg, msg_len, *line, "bad or missing pin=");
            r->pin = (unsigned)v;
        } else if (p[0] == 'F' && p[1] == ' ') {
            unsigned n2 = 0;
            r->kind = TRACE_PERIOD;
            p = parse_num(p + 1, "t=", UINT64_MAX, &v);
            if (p == NULL) return fail_msg(msg, msg_len, *line, "bad or missing t=");
            r->t_ns = v;
            p = parse_num(p, "cs=", TRACE_PIN_MAX, &v);
            if (p == NULL) return fail_msg(msg, msg_len, *line, "bad or missing cs=");
            r->pin = (unsigned)v;
            p = parse_num(p, "bits=", 16u, &v);
            if (p == NULL || (v != 8u && v != 16u)) {
                return fail_msg(msg, msg_len, *line, "bits= must be 8 or 16");
            }
            r->bits = (unsigned)v;
            p = parse_words(p, "mosi=", r->bits, r->mosi, &r->n);
            if (p == NULL) return fail_msg(msg, msg_len, *line, "bad mosi= words");
            p = parse_words(p, "miso=", r->bits, r->miso, &n2);
            if (p == NULL) return fail_msg(msg, msg_len, *line, "bad miso= words");
            if (n2 != r->n)
                return fail_msg(msg, msg_len, *line, "mosi= and miso= differ in length");
        } else {
            return fail_msg(msg, msg_len, *line, "record must start with 'F ' or 'I '");
        }
        if (!rest_is_blank(p)) {
            return fail_msg(msg, msg_len, *line, "unexpected text at the end");
        }
        return 1;
    }
    return 0;
}

/* ------------------------------------------------------------------ recorder */

static int rec_transfer(void *ctx, struct spi_dev *dev, const uint16_t *tx, uint16_t *rx, size_t n,
                        enum spi_cs_policy cs)
{
    struct trace_rec *rec = ctx;
    struct trace_record r;
    size_t done = 0;
    int err = INC_OK;
    /* One record per CS period: a toggled transfer goes through the inner bus frame by frame
     * (the engine keeps the stall between transfers, so the bus traffic is the same). */
    while (done < n && err == INC_OK) {
        const size_t chunk = cs == SPI_CS_TOGGLE ? 1u : n;
        size_t i;
        r.kind = TRACE_PERIOD;
        r.t_ns = hal_now_ns(rec->inner_hal);
        r.pin = dev->cfg.cs;
        r.bits = dev->cfg.bits;
        r.n = (unsigned)chunk;
        for (i = 0; i < chunk; i++) {
            r.mosi[i] = tx != NULL ? tx[done + i] : 0u;
        }
        err = rec->inner->ops->transfer(rec->inner->ctx, dev, tx != NULL ? tx + done : NULL, r.miso,
                                        chunk, cs);
        if (err == INC_OK) {
            if (rx != NULL) {
                memcpy(rx + done, r.miso, chunk * sizeof(uint16_t));
            }
            if (trace_write_record(rec->f, &r) != INC_OK) {
                rec->io_error = true;
            }
            rec->periods++;
            rec->words += (uint32_t)chunk;
        }
        done += chunk;
    }
    return err;
}

static int rec_attach(void *ctx, struct spi_dev *dev)
{
    struct trace_rec *rec = ctx;
    return rec->inner->ops->attach != NULL ? rec->inner->ops->attach(rec->inner->ctx, dev) : INC_OK;
}

static const struct spi_bus_ops rec_bus_ops = {rec_transfer, rec_attach};

/* The recording HAL passes everything through and logs interrupts. */
static void r_pin_write(void *c, hal_pin_t p, bool l)
{
    const struct trace_rec *rec = c;
    hal_pin_write(rec->inner_hal, p, l);
}
static bool r_pin_read(void *c, hal_pin_t p)
{
    const struct trace_rec *rec = c;
    return hal_pin_read(rec->inner_hal, p);
}
static uint64_t r_now(void *c)
{
    const struct trace_rec *rec = c;
    return hal_now_ns(rec->inner_hal);
}
static void r_delay(void *c, uint32_t ns)
{
    const struct trace_rec *rec = c;
    hal_delay_ns(rec->inner_hal, ns);
}
static void r_irq_tramp(void *arg)
{
    struct trace_rec_irq *q = arg;
    struct trace_rec *rec = q->rec;
    struct trace_record r;
    r.kind = TRACE_IRQ;
    r.t_ns = hal_now_ns(rec->inner_hal);
    r.pin = q->pin;
    if (trace_write_record(rec->f, &r) != INC_OK) {
        rec->io_error = true;
    }
    rec->irqs++;
    q->cb(q->arg);
}
static int r_irq_attach(void *c, hal_pin_t pin, enum hal_edge edge, hal_irq_cb cb, void *arg)
{
    struct trace_rec *rec = c;
    struct trace_rec_irq *slot = NULL;
    unsigned i;
    for (i = 0; i < TRACE_MAX_IRQS; i++) {
        if (rec->irq[i].cb != NULL && rec->irq[i].pin == pin) {
            slot = &rec->irq[i];
            break;
        }
        if (rec->irq[i].cb == NULL && slot == NULL) {
            slot = &rec->irq[i];
        }
    }
    if (slot == NULL) {
        return INC_ERR_NO_SPACE;
    }
    if (cb == NULL) {
        slot->cb = NULL;
        return hal_irq_attach(rec->inner_hal, pin, edge, NULL, NULL);
    }
    slot->rec = rec;
    slot->pin = pin;
    slot->cb = cb;
    slot->arg = arg;
    return hal_irq_attach(rec->inner_hal, pin, edge, r_irq_tramp, slot);
}
static int r_irq_wait(void *c, uint64_t deadline)
{
    const struct trace_rec *rec = c;
    return hal_irq_wait(rec->inner_hal, deadline);
}
static uint32_t r_crit_enter(void *c)
{
    const struct trace_rec *rec = c;
    return hal_crit_enter(rec->inner_hal);
}
static void r_crit_exit(void *c, uint32_t k)
{
    const struct trace_rec *rec = c;
    hal_crit_exit(rec->inner_hal, k);
}

static const struct hal_ops rec_hal_ops = {r_pin_write,  r_pin_read, r_now,        r_delay,
                                           r_irq_attach, r_irq_wait, r_crit_enter, r_crit_exit};

int trace_rec_open(struct trace_rec *rec, const char *path, const struct spi_bus *inner,
                   const struct hal *inner_hal)
{
    if (rec == NULL || path == NULL || inner == NULL || inner->ops == NULL ||
        inner->ops->transfer == NULL || hal_check(inner_hal) != INC_OK) {
        return INC_ERR_NULL;
    }
    memset(rec, 0, sizeof(*rec));
    rec->f = fopen(path, "w");
    if (rec->f == NULL) {
        return INC_ERR_IO;
    }
    rec->inner = inner;
    rec->inner_hal = inner_hal;
    rec->bus.ops = &rec_bus_ops;
    rec->bus.ctx = rec;
    rec->hal.ops = &rec_hal_ops;
    rec->hal.ctx = rec;
    if (fprintf(rec->f,
                "%s\n# F t=<ns> cs=<pin> bits=<8|16> mosi=<hex,...> miso=<hex,...>"
                "  |  I t=<ns> pin=<pin>\n",
                TRACE_HEADER) < 0) {
        rec->io_error = true;
    }
    return INC_OK;
}

int trace_rec_comment(struct trace_rec *rec, const char *text)
{
    if (rec == NULL || text == NULL) {
        return INC_ERR_NULL;
    }
    if (rec->f == NULL) {
        return INC_ERR_STATE;
    }
    if (strchr(text, '\n') != NULL) {
        return INC_ERR_INVAL;
    }
    if (fprintf(rec->f, "# %s\n", text) < 0) {
        rec->io_error = true;
        return INC_ERR_IO;
    }
    return INC_OK;
}

int trace_rec_close(struct trace_rec *rec)
{
    int err;
    unsigned i;
    if (rec == NULL) {
        return INC_ERR_NULL;
    }
    if (rec->f == NULL) {
        return INC_ERR_STATE;
    }
    for (i = 0; i < TRACE_MAX_IRQS; i++) {
        if (rec->irq[i].cb != NULL) {
            /* Hand interrupts back to their owner: the trampoline must not outlive the file. */
            hal_irq_attach(rec->inner_hal, rec->irq[i].pin, HAL_EDGE_RISING, NULL, NULL);
            rec->irq[i].cb = NULL;
        }
    }
    err = (fclose(rec->f) != 0 || rec->io_error) ? INC_ERR_IO : INC_OK;
    rec->f = NULL;
    return err;
}

/* ------------------------------------------------------------------ replay */

static void set_error(struct trace_replay *rp, int err, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static void set_error(struct trace_replay *rp, int err, const char *fmt, ...)
{
    va_list ap;
    if (rp->status != INC_OK) {
        return; /* keep the first */
    }
    rp->status = err;
    va_start(ap, fmt);
    vsnprintf(rp->msg, sizeof(rp->msg), fmt, ap);
    va_end(ap);
}

static void advance(struct trace_replay *rp)
{
    int r = trace_parse_next(rp->f, &rp->line, &rp->next, rp->msg, sizeof(rp->msg));
    rp->have_next = r == 1;
    if (r < 0 && rp->status == INC_OK) {
        rp->status = r; /* msg already written by the parser */
    }
}

static bool fire_next_irq(struct trace_replay *rp);

static int rp_transfer(void *ctx, struct spi_dev *dev, const uint16_t *tx, uint16_t *rx, size_t n,
                       enum spi_cs_policy cs)
{
    struct trace_replay *rp = ctx;
    size_t done = 0;
    while (done < n) {
        const size_t chunk = cs == SPI_CS_TOGGLE ? 1u : n;
        const struct trace_record *e = &rp->next;
        size_t i;
        if (rp->status != INC_OK) {
            return INC_ERR_MISMATCH;
        }
        /* Interrupts recorded before this CS period ran while the driver was busy (inside a
         * delay or a transfer): run them now, in the recorded order. */
        while (rp->status == INC_OK && rp->have_next && rp->next.kind == TRACE_IRQ) {
            if (!fire_next_irq(rp)) {
                return INC_ERR_MISMATCH;
            }
        }
        if (rp->status != INC_OK) {
            return INC_ERR_MISMATCH;
        }
        if (!rp->have_next) {
            set_error(rp, INC_ERR_MISMATCH,
                      "frame %lu: the driver sent %04X but the trace has ended",
                      (unsigned long)rp->frame, tx != NULL ? tx[done] : 0u);
            return INC_ERR_MISMATCH;
        }
        if (e->pin != dev->cfg.cs || e->bits != dev->cfg.bits || e->n != chunk) {
            set_error(
                rp, INC_ERR_MISMATCH,
                "frame %lu (trace line %u): expected a CS period on cs=%u of %u %u-bit words, "
                "the driver made one on cs=%u of %lu %u-bit words",
                (unsigned long)rp->frame, e->line, e->pin, e->n, e->bits, (unsigned)dev->cfg.cs,
                (unsigned long)chunk, (unsigned)dev->cfg.bits);
            return INC_ERR_MISMATCH;
        }
        for (i = 0; i < chunk; i++) {
            const uint16_t got = tx != NULL ? tx[done + i] : 0u;
            if (got != e->mosi[i]) {
                set_error(
                    rp, INC_ERR_MISMATCH,
                    "frame %lu (trace line %u, word %lu): expected MOSI %04X, driver sent %04X",
                    (unsigned long)(rp->frame + i), e->line, (unsigned long)i, e->mosi[i], got);
                return INC_ERR_MISMATCH;
            }
        }
        if (rx != NULL) {
            memcpy(rx + done, e->miso, chunk * sizeof(uint16_t));
        }
        if (e->t_ns > rp->now_ns) {
            rp->now_ns = e->t_ns;
        }
        rp->frame += (uint32_t)chunk;
        rp->periods++;
        done += chunk;
        advance(rp);
    }
    return INC_OK;
}

static const struct spi_bus_ops rp_bus_ops = {rp_transfer, NULL};

static void p_pin_write(void *c, hal_pin_t p, bool l)
{
    (void)c;
    (void)p;
    (void)l;
}
static bool p_pin_read(void *c, hal_pin_t p)
{
    (void)c;
    (void)p;
    return false;
}
static uint64_t p_now(void *c)
{
    const struct trace_replay *rp = c;
    return rp->now_ns;
}
static void p_delay(void *c, uint32_t ns)
{
    struct trace_replay *rp = c;
    rp->now_ns += ns;
}
static int p_irq_attach(void *c, hal_pin_t pin, enum hal_edge edge, hal_irq_cb cb, void *arg)
{
    struct trace_replay *rp = c;
    struct trace_replay_irq *slot = NULL;
    unsigned i;
    (void)edge;
    for (i = 0; i < TRACE_MAX_IRQS; i++) {
        if (rp->irq[i].cb != NULL && rp->irq[i].pin == pin) {
            slot = &rp->irq[i];
            break;
        }
        if (rp->irq[i].cb == NULL && slot == NULL) {
            slot = &rp->irq[i];
        }
    }
    if (slot == NULL) {
        return INC_ERR_NO_SPACE;
    }
    slot->pin = pin;
    slot->cb = cb;
    slot->arg = arg;
    return INC_OK;
}

/* Fire the recorded interrupt at the head of the trace. */
static bool fire_next_irq(struct trace_replay *rp)
{
    unsigned i;
    if (!rp->have_next || rp->next.kind != TRACE_IRQ) {
        return false;
    }
    for (i = 0; i < TRACE_MAX_IRQS; i++) {
        if (rp->irq[i].cb != NULL && rp->irq[i].pin == rp->next.pin) {
            if (rp->next.t_ns > rp->now_ns) {
                rp->now_ns = rp->next.t_ns;
            }
            advance(rp);
            rp->fired++;
            rp->irq[i].cb(rp->irq[i].arg);
            return true;
        }
    }
    set_error(rp, INC_ERR_MISMATCH,
              "trace line %u: interrupt on pin %u, but the driver has no "
              "callback attached there",
              rp->next.line, rp->next.pin);
    return false;
}

static int p_irq_wait(void *c, uint64_t deadline)
{
    struct trace_replay *rp = c;
    if (rp->fired > 0) {
        rp->fired = 0;
        return INC_OK;
    }
    if (rp->status == INC_OK && rp->have_next && rp->next.kind == TRACE_IRQ &&
        rp->next.t_ns <= deadline) {
        if (fire_next_irq(rp)) {
            rp->fired = 0;
            return INC_OK;
        }
    }
    /* No interrupt recorded before the deadline: the recorded run timed out here too. */
    if (deadline > rp->now_ns) {
        rp->now_ns = deadline;
    }
    return INC_ERR_TIMEOUT;
}
static uint32_t p_crit_enter(void *c)
{
    struct trace_replay *rp = c;
    return rp->crit_depth++;
}
static void p_crit_exit(void *c, uint32_t k)
{
    struct trace_replay *rp = c;
    rp->crit_depth = k;
}

static const struct hal_ops rp_hal_ops = {p_pin_write,  p_pin_read, p_now,        p_delay,
                                          p_irq_attach, p_irq_wait, p_crit_enter, p_crit_exit};

int trace_replay_open(struct trace_replay *rp, const char *path)
{
    char head[64];
    if (rp == NULL || path == NULL) {
        return INC_ERR_NULL;
    }
    memset(rp, 0, sizeof(*rp));
    rp->bus.ops = &rp_bus_ops;
    rp->bus.ctx = rp;
    rp->hal.ops = &rp_hal_ops;
    rp->hal.ctx = rp;
    rp->f = fopen(path, "r");
    if (rp->f == NULL) {
        snprintf(rp->msg, sizeof(rp->msg), "cannot open %s", path);
        rp->status = INC_ERR_IO;
        return INC_ERR_IO;
    }
    /* The header line exactly (trailing blanks or a CR allowed): "# inclino-trace 12" or a
     * header with more text is another format, not version 1. */
    if (sim_read_line(rp->f, head, sizeof(head)) != SIM_LINE_OK ||
        strncmp(head, TRACE_HEADER, strlen(TRACE_HEADER)) != 0 ||
        !rest_is_blank(head + strlen(TRACE_HEADER))) {
        snprintf(rp->msg, sizeof(rp->msg), "trace line 1: not an inclino trace (expected '%s')",
                 TRACE_HEADER);
        rp->status = INC_ERR_FORMAT;
        return INC_ERR_FORMAT;
    }
    rp->line = 1;
    advance(rp);
    return rp->status;
}

int trace_replay_finish(struct trace_replay *rp)
{
    if (rp == NULL) {
        return INC_ERR_NULL;
    }
    if (rp->status == INC_OK && rp->have_next) {
        set_error(rp, INC_ERR_MISMATCH,
                  "frame %lu: the driver stopped, the trace goes on at line %u",
                  (unsigned long)rp->frame, rp->next.line);
    }
    if (rp->f != NULL) {
        fclose(rp->f);
        rp->f = NULL;
    }
    return rp->status;
}

const char *trace_replay_message(const struct trace_replay *rp)
{
    return rp != NULL ? rp->msg : "";
}
