/* Arm semihosting (QEMU -semihosting-config enable=on,target=native): console output and
   exit with a status. */
#ifndef CARRY_SEMIHOST_H
#define CARRY_SEMIHOST_H

/* Writes a NUL-terminated string to the host's stdout. */
void semihost_write0(const char *s);

/* Ends the emulation; QEMU exits with `status` (0 = success). */
__attribute__((noreturn)) void semihost_exit(int status);

#endif
