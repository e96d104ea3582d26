/*
 * unit.h - the project's minimal unit-test harness.
 *
 * A test program is a main() that runs cases with UNIT_RUN() and returns unit_report(). Every
 * CHECK prints the file, line, expression and the values involved when it fails, counts the
 * failure and lets the case continue; REQUIRE variants return from the case. CHECK_OK and
 * CHECK_ERR compare error codes (base/error) and print them by name (inc_err_name). The exit
 * status is the number of failed checks (capped at 125), so CTest sees a failure on the host and,
 * through QEMU's semihosting exit code, on the emulated MCU.
 *
 * Command line (docs/build.md, "Running one test case"): `--case NAME` runs only the case NAME
 * (the name given to UNIT_RUN, i.e. the function's name; repeat the option for several), and
 * `--list` prints the case names without running any. A --case that names no case fails the
 * program. Other arguments are left to the test. On the host the options are read before main()
 * runs (a glibc constructor, so no test's main() has to pass them on); a test whose main() has
 * argc/argv may also hand them over with unit_args(), which is how a target without that
 * constructor (the QEMU boards call main() without arguments) would get them.
 *
 * Works with any hosted C library (glibc on the host, newlib under QEMU).
 */
#ifndef INCLINO_UNIT_H
#define INCLINO_UNIT_H

#include <stdint.h>
#include <stdbool.h>
#include <inttypes.h>

#include "inclino/error.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Where instructions are expensive - under QEMU (Arm, RISC-V: emulated, soft-float libm) and in
 * the sanitizer build (ASan + UBSan, several times slower; its job is undefined behaviour on the
 * same code paths) - long sweeps and simulations run a reduced size: UNIT_SIZE(full, reduced).
 * The plain host build always runs the full size, so every stated bound is proven there at full
 * density; each test says where it uses the reduced size.
 */
#if defined(__arm__) || defined(__riscv)
#define UNIT_ON_TARGET 1
#else
#define UNIT_ON_TARGET 0
#endif
#if defined(INCLINO_SANITIZE_BUILD) || defined(__SANITIZE_ADDRESS__)
#define UNIT_SANITIZED 1
#else
#define UNIT_SANITIZED 0
#endif
#define UNIT_REDUCED (UNIT_ON_TARGET || UNIT_SANITIZED)
#define UNIT_SIZE(full, reduced) (UNIT_REDUCED ? (reduced) : (full))

/* xorshift32 (Marsaglia): a seeded pseudo-random sequence, the same on every target, for test
 * inputs and benchmark operands. *state must not be 0 (0 stays 0). */
static inline uint32_t unit_rand32(uint32_t *state)
{
    uint32_t x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *state = x;
    return x;
}

/* Exact round(n / d), ties away from zero, for d > 0 and |n| < 2^62: a reference for tests,
 * independent of base/fx (floor division with a non-negative remainder, then compare
 * 2 * rem with d). */
static inline int64_t unit_round_div(int64_t n, int64_t d)
{
    int64_t q = n / d, rem = n % d;
    if (rem < 0) {
        q -= 1;
        rem += d;
    }
    if (2 * rem > d || (2 * rem == d && n >= 0)) {
        q += 1;
    }
    return q;
}

extern unsigned unit_checks;
extern unsigned unit_failures;

void unit_fail(const char *file, int line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/* Whether the case `name` runs (it is selected, or there is no --case and no --list); the case
 * becomes the current one for the failure messages either way. */
bool unit_begin(const char *name);
/* Reads --case NAME (repeatable) and --list out of argv; other arguments are ignored. */
void unit_args(int argc, char **argv);
int unit_report(void);
/* The failure message of CHECK_OK / CHECK_ERR: both codes by name and value. */
void unit_fail_err(const char *file, int line, const char *expr, const char *want_expr,
                   long long got, long long want);

#define UNIT_RUN(fn)               \
    do {                           \
        if (unit_begin(#fn)) fn(); \
    } while (0)

#define CHECK(cond)                                                     \
    do {                                                                \
        unit_checks++;                                                  \
        if (!(cond)) unit_fail(__FILE__, __LINE__, "CHECK(%s)", #cond); \
    } while (0)

#define REQUIRE(cond)                                            \
    do {                                                         \
        unit_checks++;                                           \
        if (!(cond)) {                                           \
            unit_fail(__FILE__, __LINE__, "REQUIRE(%s)", #cond); \
            return;                                              \
        }                                                        \
    } while (0)

#define CHECK_EQ_INT(a, b)                                                                     \
    do {                                                                                       \
        long long unit_a_ = (long long)(a), unit_b_ = (long long)(b);                          \
        unit_checks++;                                                                         \
        if (unit_a_ != unit_b_)                                                                \
            unit_fail(__FILE__, __LINE__, "%s == %s: %lld != %lld", #a, #b, unit_a_, unit_b_); \
    } while (0)

#define CHECK_EQ_HEX(a, b)                                                                         \
    do {                                                                                           \
        unsigned long long unit_a_ = (unsigned long long)(a), unit_b_ = (unsigned long long)(b);   \
        unit_checks++;                                                                             \
        if (unit_a_ != unit_b_)                                                                    \
            unit_fail(__FILE__, __LINE__, "%s == %s: 0x%llx != 0x%llx", #a, #b, unit_a_, unit_b_); \
    } while (0)

/* |a - b| <= tol, in integers (64-bit). */
#define CHECK_NEAR_INT(a, b, tol)                                                                 \
    do {                                                                                          \
        long long unit_a_ = (long long)(a), unit_b_ = (long long)(b), unit_t_ = (long long)(tol); \
        long long unit_d_ = unit_a_ > unit_b_ ? unit_a_ - unit_b_ : unit_b_ - unit_a_;            \
        unit_checks++;                                                                            \
        if (unit_d_ > unit_t_)                                                                    \
            unit_fail(__FILE__, __LINE__, "%s ~ %s: %lld vs %lld, |diff| %lld > %lld", #a, #b,    \
                      unit_a_, unit_b_, unit_d_, unit_t_);                                        \
    } while (0)

/* |a - b| <= tol, in double (tests only; firmware never uses floating point). */
#define CHECK_NEAR(a, b, tol)                                                                  \
    do {                                                                                       \
        double unit_a_ = (double)(a), unit_b_ = (double)(b), unit_t_ = (double)(tol);          \
        double unit_d_ = unit_a_ > unit_b_ ? unit_a_ - unit_b_ : unit_b_ - unit_a_;            \
        unit_checks++;                                                                         \
        if (!(unit_d_ <= unit_t_))                                                             \
            unit_fail(__FILE__, __LINE__, "%s ~ %s: %.9g vs %.9g, |diff| %.3g > %.3g", #a, #b, \
                      unit_a_, unit_b_, unit_d_, unit_t_);                                     \
    } while (0)

/* An error code (enum inc_err) against the expected one; a failure prints both by name, e.g.
 * "f(x) == INC_ERR_RANGE: ERR_BUS (-4) != ERR_RANGE (-10)". */
#define CHECK_ERR(expr, err)                                                                      \
    do {                                                                                          \
        long long unit_a_ = (long long)(expr), unit_b_ = (long long)(err);                        \
        unit_checks++;                                                                            \
        if (unit_a_ != unit_b_) unit_fail_err(__FILE__, __LINE__, #expr, #err, unit_a_, unit_b_); \
    } while (0)
#define CHECK_OK(expr) CHECK_ERR((expr), INC_OK)

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_UNIT_H */
