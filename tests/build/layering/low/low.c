/* low.c - a module of the layering test (tests/build/layering). */
int layering_low(void);
int layering_low(void)
{
    return 1;
}
