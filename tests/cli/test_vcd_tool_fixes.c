/* test_vcd_tool_fixes.c - the VCD converter's defects found through vcd2trace (issue 13): a CS
 * period still open at the end of the capture is written, half a word there is refused, and a
 * cs pin the trace reader would refuse is refused at conversion; every trace written reads back
 * through trace_parse_next. */
#include "inclino/error.h"
#include "inclino/sim/trace.h"
#include "unit.h"

#include <stdio.h>
#include <string.h>

#ifndef VCD_FILE
#error "VCD_FILE (tests/cli/data/spi_open_end.vcd) must be defined"
#endif

static const struct trace_vcd_opts opts8 = {"sclk", "mosi", "miso", "cs0", 3, 8, 3};

/* Converts text (the whole VCD) into buf; returns trace_from_vcd's result. */
static int convert(const char *vcd, const struct trace_vcd_opts *o, char *buf, size_t size,
                   char *msg)
{
    FILE *in = fmemopen((void *)vcd, strlen(vcd), "r");
    FILE *out = fmemopen(buf, size, "w");
    int n;
    memset(buf, 0, size);
    if (in == NULL || out == NULL) return -100;
    n = trace_from_vcd(in, out, o, msg, TRACE_MSG_LEN);
    fclose(in);
    fclose(out);
    return n;
}

static size_t read_all(char *buf, size_t size)
{
    FILE *f = fopen(VCD_FILE, "r");
    size_t n;
    if (f == NULL) return 0;
    n = fread(buf, 1, size - 1u, f);
    fclose(f);
    buf[n] = '\0';
    return n;
}

static void open_period_at_end_is_written(void)
{
    static char vcd[16384], trace[4096];
    static struct trace_record r;
    char msg[TRACE_MSG_LEN] = "";
    unsigned line = 0;
    FILE *f;
    REQUIRE(read_all(vcd, sizeof vcd) > 0u);
    CHECK_EQ_INT(convert(vcd, &opts8, trace, sizeof trace, msg), 2);
    f = fmemopen(trace, strlen(trace), "r");
    REQUIRE(f != NULL);
    CHECK_EQ_INT(trace_parse_next(f, &line, &r, msg, sizeof msg), 1);
    CHECK_EQ_HEX(r.mosi[0], 0xA5);
    CHECK_EQ_HEX(r.miso[0], 0x3C);
    CHECK_EQ_INT(trace_parse_next(f, &line, &r, msg, sizeof msg), 1); /* the open one */
    CHECK_EQ_INT((int)r.n, 1);
    CHECK_EQ_HEX(r.mosi[0], 0x5A);
    CHECK_EQ_HEX(r.miso[0], 0xC3);
    CHECK_EQ_INT((int)r.t_ns, 1100);
    CHECK_EQ_INT(trace_parse_next(f, &line, &r, msg, sizeof msg), 0);
    fclose(f);
}

static void half_word_at_end_is_refused(void)
{
    static char vcd[16384], trace[4096];
    char msg[TRACE_MSG_LEN] = "";
    char *cut;
    REQUIRE(read_all(vcd, sizeof vcd) > 0u);
    /* drop the last two clock edges: the open period ends with 7 bits */
    cut = strrchr(vcd, '#');
    REQUIRE(cut != NULL);
    *cut = '\0';
    cut = strrchr(vcd, '#');
    REQUIRE(cut != NULL);
    *cut = '\0';
    CHECK_ERR(convert(vcd, &opts8, trace, sizeof trace, msg), INC_ERR_FORMAT);
    CHECK(strstr(msg, "capture ends mid-word") != NULL);
}

static void cs_pin_beyond_the_reader_is_refused(void)
{
    static char vcd[16384], trace[4096];
    static struct trace_record r;
    char msg[TRACE_MSG_LEN] = "";
    struct trace_vcd_opts o = opts8;
    unsigned line = 0;
    FILE *f;
    REQUIRE(read_all(vcd, sizeof vcd) > 0u);
    o.cs_pin = TRACE_PIN_MAX + 1u;
    CHECK_ERR(convert(vcd, &o, trace, sizeof trace, msg), INC_ERR_INVAL);
    o.cs_pin = 70000u;
    CHECK_ERR(convert(vcd, &o, trace, sizeof trace, msg), INC_ERR_INVAL);
    o.cs_pin = TRACE_PIN_MAX; /* the largest the reader takes: written and read back */
    CHECK_EQ_INT(convert(vcd, &o, trace, sizeof trace, msg), 2);
    f = fmemopen(trace, strlen(trace), "r");
    REQUIRE(f != NULL);
    CHECK_EQ_INT(trace_parse_next(f, &line, &r, msg, sizeof msg), 1);
    CHECK_EQ_INT((int)r.pin, (int)TRACE_PIN_MAX);
    fclose(f);
}

int main(void)
{
    UNIT_RUN(open_period_at_end_is_written);
    UNIT_RUN(half_word_at_end_is_refused);
    UNIT_RUN(cs_pin_beyond_the_reader_is_refused);
    return unit_report();
}
