/*
 * link_check_main.c - main() of the link-check image inclino_all (cmake/inclino_cross.cmake).
 *
 * inclino_all links every freestanding module whole (--whole-archive, no --gc-sections), so
 * every function of every module must resolve every symbol it uses; that image never runs.
 * This main only gives the startup something to call.
 */
int main(void)
{
    return 0;
}
