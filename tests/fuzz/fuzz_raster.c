/* fuzz_raster.c - libFuzzer entry point for fxl_draw_triangle and the 3D
 * front end.
 *
 * The same case decoders and checks as fixel-fuzz: any input bytes are a
 * case, a front-end one (fuzz_pipe.h) when bits 3..5 of the last byte are 0,
 * else a triangle (fuzz_case.h); a violated check prints the reason and the
 * decoded case and aborts, so libFuzzer saves the input as a crash file.
 * Build (needs clang): cmake --build <build> --target fuzz_raster, then e.g.
 *   <build>/bin/fuzz_raster -max_len=256 -runs=1000000 corpus/
 * A saved input replays with fixel-fuzz --replay $(xxd -p -c 1000 crash-...).
 */
#include "fuzz_pipe.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static fz_state st;
    static fz_pstate pst;
    static int ready;
    fz_outcome o;
    char msg[FZ_MSG];

    if (!ready) {
        if (fz_state_init(&st) != 0 || fz_pstate_init(&pst, &st) != 0)
            abort();
        ready = 1;
    }
    if (fz_input_run(&pst, data, size, &o, msg, stderr, 0)) {
        fprintf(stderr, "fuzz_raster: %s\n", msg);
        abort();
    }
    return 0;
}
