/* See semihost.h. */
#include <stdint.h>

#include "semihost.h"

static uint32_t call(uint32_t op, const void *arg) {
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt #0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void semihost_write0(const char *s) { call(0x04u, s); /* SYS_WRITE0 */ }

void semihost_exit(int status) {
    /* SYS_EXIT_EXTENDED: ADP_Stopped_ApplicationExit with the status code. */
    const uint32_t block[2] = {0x20026u, (uint32_t)status};
    call(0x20u, block);
    for (;;) {
    }
}
