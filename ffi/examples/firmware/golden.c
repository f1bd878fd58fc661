/* The C firmware's golden suite: every golden case of tests/golden, through the C API
   (libcarry_ffi.a, thumbv7em-none-eabihf) in f32 and f64, one line per run on the
   semihosting console in the format of the host's expected.txt; .ci/ffi.sh compares the
   two bit for bit. */
#include "carry.h"
#include "golden_run.h"
#include "semihost.h"

int main(void) {
    semihost_write0("# carry C firmware: golden cases through the C API\n");
    int runs = carry_golden_run(0, semihost_write0);
    semihost_write0(runs > 0 ? "# done\n" : "# no runs\n");
    return runs > 0 ? 0 : 1;
}
