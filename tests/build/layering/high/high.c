/* high.c - a module of the layering test (tests/build/layering). */
int layering_high(void);
int layering_high(void)
{
    return 2;
}
