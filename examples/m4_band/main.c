/* main.c - the firmware example: fixel on a Cortex-M4 (qemu-system-arm
 * -M mps2-an386) rendering the rotating cube and the front-end scenes in
 * 320 x 24 bands through the ST7789 driver into a mock SPI (examples/common/
 * fw_app.h), printing the CRC-32 of each frame's wire bytes over semihosting.
 *
 * Output, one line per frame, in the format of examples/expected_crc.txt
 * after the "crc " prefix:
 *   crc <scene> <frame> 0x<wire crc>
 * plus an informational line each, and "status ok" (exit code 0) at the end.
 * No libc and no floating point: startup.c provides the start-up code,
 * semihosting and the memcpy/memset the compiler may call.
 */
#include "fw_app.h"

#include "mps2.h"

static fw_app_t app; /* ~115 KB: bands, depth band, triangle store, textures, vertex cache */

static void out(const char *s)
{
    fw_semihost_write0(s);
}

static void out_hex(uint32_t v)
{
    char b[11];
    int i;
    b[0] = '0';
    b[1] = 'x';
    for (i = 0; i < 8; i++) b[2 + i] = "0123456789abcdef"[(v >> (28 - 4 * i)) & 0xFu];
    b[10] = 0;
    out(b);
}

static void out_dec(uint32_t v)
{
    char b[11];
    int i = 10;
    b[i] = 0;
    do {
        b[--i] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v != 0);
    out(b + i);
}

static void out_crc(const char *name, uint32_t frame, uint32_t crc)
{
    out("crc ");
    out(name);
    out(" ");
    out_dec(frame);
    out(" ");
    out_hex(crc);
    out("\n");
}

int main(void)
{
    fw_result_t r;
    fxl_status_t st = fw_app_init(&app);
    uint32_t i;
    out("fixel m4_band: st7789 320x240, bands of 24 rows, mock SPI\n");
    if (st == FXL_OK) out_crc("init", 0, app.init_crc);
    for (i = 0; st == FXL_OK && i < fw_frame_count; i++) {
        uintptr_t top;
        uint32_t depth;
        /* the frame's stack depth below main (mps2.h): front end, band
         * renderer, driver and mock SPI together */
        fw_stack_paint();
        top = fw_stack_sp();
        st = fw_app_frame(&app, fw_frames[i].scene, fw_frames[i].frame, &r);
        depth = (uint32_t)(top - fw_stack_low());
        out_crc(fw_scene_name(fw_frames[i].scene), fw_frames[i].frame, r.wire_crc);
        out("  tris ");
        out_dec(r.screen_tris);
        out(", pixels ");
        out_dec(r.stats.pixels);
        out(", wire bytes ");
        out_dec(r.wire_bytes);
        out(", pixel crc ");
        out_hex(r.pixel_crc);
        out(", stack ");
        out_dec(depth);
        out(" B");
        out(r.bins_overflowed ? ", bins overflowed\n" : "\n");
    }
    out(st == FXL_OK ? "status ok\n" : "status error\n");
    return st == FXL_OK ? 0 : 1;
}
