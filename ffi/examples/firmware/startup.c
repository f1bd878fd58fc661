/* Bare-metal start-up for the mps2-an386 (Cortex-M4F): vector table, .data/.bss
   initialisation, FPU on, main(), and semihosting exit with main's status. */
#include <stdint.h>

#include "semihost.h"

extern uint32_t _sidata, _sdata, _edata, _sbss, _ebss, _stack_top;
int main(void);

void reset_handler(void);
static void fault_handler(void);

__attribute__((section(".vector_table"), used)) static void (*const vectors[16])(void) = {
    (void (*)(void))(&_stack_top), reset_handler, fault_handler, fault_handler,
    fault_handler, fault_handler, fault_handler, 0, 0, 0, 0, fault_handler, fault_handler,
    0, fault_handler, fault_handler,
};

void reset_handler(void) {
    for (uint32_t *s = &_sidata, *d = &_sdata; d < &_edata;) *d++ = *s++;
    for (uint32_t *d = &_sbss; d < &_ebss;) *d++ = 0;
    /* CPACR: full access to CP10 and CP11 (the single-precision FPU). */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    __asm__ volatile("dsb\n isb" ::: "memory");
    semihost_exit(main());
}

static void fault_handler(void) {
    semihost_write0("fault: the C firmware took an exception\n");
    semihost_exit(3);
}
