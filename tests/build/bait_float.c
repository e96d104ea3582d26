/*
 * Deliberately breaks the freestanding rules, for the self-test of the no-float check only: it is
 * never part of a module or an image. Soft-float targets reference __aeabi_fmul/__mulsf3 here,
 * the M4F emits VFP instructions; the check must report either.
 */
float bait_float_scale(float a, float b);

float bait_float_scale(float a, float b)
{
    return a * b + 1.5f;
}
