#!/usr/bin/env python3
"""Generate the constant tables of base/fx (fx_trig.c) in exact decimal arithmetic.

Run: python3 tests/fx/gen_fx_consts.py
The output is pasted into base/fx/fx_trig.c; the tests (tests/fx/) check the resulting
functions against libm, so a wrong constant cannot pass silently. Standard library only.
"""
from decimal import Decimal as D, getcontext, ROUND_HALF_EVEN

getcontext().prec = 80

PI = D("3.14159265358979323846264338327950288419716939937510582097494459230781640628620899863")


def atan(x):
    """Taylor series of atan for 0 <= x <= 1/2 (converges as x^2)."""
    s, term, k, x2 = D(0), x, 0, x * x
    while True:
        t = term / (2 * k + 1)
        if t < D(10) ** -70:
            return s
        s += t if k % 2 == 0 else -t
        term *= x2
        k += 1


def rnd(v):
    return int(v.to_integral_value(rounding=ROUND_HALF_EVEN))


def fact(n):
    f = 1
    for i in range(2, n + 1):
        f *= i
    return f


# --- CORDIC arctangent table: atan(2^-i) in degrees, Q24 (unit 2^-24 degree) ---------------
N_CORDIC = 28
print("/* atan(2^-i) in degrees, Q24, i = 0..%d */" % (N_CORDIC - 1))
vals = []
for i in range(N_CORDIC):
    a = D(45) if i == 0 else atan(D(1) / (D(2) ** i)) * 180 / PI
    vals.append(rnd(a * (D(2) ** 24)))
for i in range(0, N_CORDIC, 4):
    print("    " + " ".join("%du," % v for v in vals[i:i + 4]))

# --- sin/cos polynomials in u = t / 2^22, t = angle in Q16 degrees, u in [0, 0.703125] -------
# sin(a u) and cos(a u) with a = 64 degrees in radians = 16 pi / 45.
A = PI * 16 / 45
LIM = D(2) ** 32


def q(name, v, f):
    r = rnd(v * (D(2) ** f))
    assert 0 < r < LIM, (name, r)
    print("#define %-14s %11du /* %s, Q%d (%.3e) */" % (name, r, name.lower(), f, float(v)))


c = {k: A ** k / fact(k) for k in range(1, 14)}
print("/* sin(a u) = u (1 + R), R = (a-1) - s (c3 - s (c5 - s (c7 - s (c9 - s c11)))), s = u^2 */")
q("FX_SIN_A1", A - 1, 35)
q("FX_SIN_C3", c[3], 34)
q("FX_SIN_C5", c[5], 38)
q("FX_SIN_C7", c[7], 43)
q("FX_SIN_C9", c[9], 48)
q("FX_SIN_C11", c[11], 55)
print("/* cos(a u) = 1 - s/2 - s e2 + s^2 (c4 - s (c6 - s (c8 - s (c10 - s c12)))), e2 = c2 - 1/2 */")
q("FX_COS_E2", c[2] - D("0.5"), 35)
q("FX_COS_C4", c[4], 35)
q("FX_COS_C6", c[6], 40)
q("FX_COS_C8", c[8], 45)
q("FX_COS_C10", c[10], 51)
q("FX_COS_C12", c[12], 58)
umax = D(2949120) / D(2) ** 22
print("/* truncation: sin term u^13 %.2e, cos term u^14 %.2e at u = %.6f */"
      % (float(c[13] * umax ** 13), float(A ** 14 / fact(14) * umax ** 14), float(umax)))
