/*
 * The startup initialised memory: every .data object holds its initial value, every .bss
 * object is zero. On the QEMU boards the startup is the image startup of hal/rt, so this
 * proves the .data copy (from its load address in flash) and the .bss loop of the firmware
 * images; on the host it checks the same C guarantees against the native startup.
 */
#include <stddef.h>
#include <stdint.h>

#include "unit.h"
#ifdef INCLINO_QEMU_BOARD
#include "board.h"
#endif

/* .data: several sizes and alignments, so a copy that is off by a word or a byte shows. */
static volatile uint32_t board_data_word = 0xC0FFEE42u;
static volatile uint8_t board_data_bytes[7] = {1, 2, 3, 4, 5, 6, 7};
static volatile uint64_t board_data_dword = 0x0123456789ABCDEFull;
static volatile struct {
    int16_t a;
    int32_t b;
    char c[3];
} board_data_struct = {-1234, -56789012, {'i', 'n', 'c'}};

/* .bss: large enough that a loop stopping early would leave garbage somewhere. */
static volatile uint32_t board_bss_words[257];
static volatile uint8_t board_bss_byte;

static void test_data_is_initialised(void)
{
    size_t i;
    CHECK_EQ_HEX(board_data_word, 0xC0FFEE42u);
    for (i = 0; i < sizeof(board_data_bytes); i++) {
        CHECK_EQ_INT(board_data_bytes[i], i + 1u);
    }
    CHECK_EQ_HEX(board_data_dword, 0x0123456789ABCDEFull);
    CHECK_EQ_INT(board_data_struct.a, -1234);
    CHECK_EQ_INT(board_data_struct.b, -56789012);
    CHECK_EQ_INT(board_data_struct.c[0], 'i');
    CHECK_EQ_INT(board_data_struct.c[2], 'c');
}

static void test_data_is_writable(void)
{
    board_data_word += 1u;
    CHECK_EQ_HEX(board_data_word, 0xC0FFEE43u);
}

static void test_bss_is_zero(void)
{
    size_t i;
    uint32_t any = 0u;
    for (i = 0; i < sizeof(board_bss_words) / sizeof(board_bss_words[0]); i++) {
        any |= board_bss_words[i];
    }
    CHECK_EQ_HEX(any, 0u);
    CHECK_EQ_INT(board_bss_byte, 0);
}

static void test_static_local_is_initialised(void)
{
    static volatile int32_t counter = 41;
    counter++;
    CHECK_EQ_INT(counter, 42);
}

#ifdef INCLINO_QEMU_BOARD
/* The stack was painted at reset: some of it is in use, most of it never was. */
static void test_stack_is_painted(void)
{
    size_t used = board_stack_high_water();
    CHECK(used > 0u);
    CHECK(used < board_stack_size() / 2u);
}
#endif

int main(void)
{
    UNIT_RUN(test_data_is_initialised);
    UNIT_RUN(test_data_is_writable);
    UNIT_RUN(test_bss_is_zero);
    UNIT_RUN(test_static_local_is_initialised);
#ifdef INCLINO_QEMU_BOARD
    UNIT_RUN(test_stack_is_painted);
#endif
    return unit_report();
}
