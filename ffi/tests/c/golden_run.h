/* Runs every golden case through the C API and emits one line per run in the format of
   the generator's expected.txt (ffi/examples/golden_c.rs):
     impact f32 NAME ok HEX...    or    impact f32 NAME err CODE
   Shared by the host C test and the C firmware; no libc beyond memcpy. */
#ifndef CARRY_GOLDEN_RUN_H
#define CARRY_GOLDEN_RUN_H

/* Receives each NUL-terminated line (with its '\n'). */
typedef void (*carry_golden_emit)(const char *line);

/* Runs the cases of one precision ("f32" or "f64"; others: both); returns the number of runs. */
int carry_golden_run(const char *precision, carry_golden_emit emit);

#endif
