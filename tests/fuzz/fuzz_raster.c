/* fuzz_raster.c - libFuzzer entry point for fxl_draw_triangle.
 *
 * The same case decoder and checks as fixel-fuzz (fuzz_case.h): any input
 * bytes are a case; a violated check prints the reason and the decoded case
 * and aborts, so libFuzzer saves the input as a crash file. Build (needs
 * clang): cmake --build <build> --target fuzz_raster, then e.g.
 *   <build>/bin/fuzz_raster -max_len=256 -runs=1000000 corpus/
 * A saved input replays with fixel-fuzz --replay $(xxd -p -c 1000 crash-...).
 */
#include "fuzz_case.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static fz_state st;
    static int ready;
    fz_case c;
    fz_outcome o;
    char msg[FZ_MSG];

    if (!ready) {
        if (fz_state_init(&st) != 0)
            abort();
        ready = 1;
    }
    fz_prepare(data, size, &c);
    if (fz_run_case(&st, &c, &o, msg)) {
        fprintf(stderr, "fuzz_raster: %s\n", msg);
        fz_print_case(stderr, &c);
        abort();
    }
    return 0;
}
