/* det_main.c - render the determinism list and print one CRC per frame.
 *
 * The same file is built for the host (-DDET_HOST: stdio) and bare-metal
 * Cortex-M4 (semihosting, see examples/common/mps2_startup.c). No libc on the target: formatting
 * is done here. Output lines: "<scene> <variant> <status> <crc32 hex>",
 * then "done". Data (vertices, textures) comes from det_data.h, generated on
 * the host by gen_data.c.
 */
#include <stdint.h>

#include "fixel/fixel.h"
#include "det_entries.h"
#include "det_data.h"

#ifdef DET_HOST
#include <stdio.h>
static void out(const char *s)
{
    fputs(s, stdout);
}
#else
void fw_semihost_write0(const char *s);   /* examples/common/mps2_startup.c */
static void out(const char *s)
{
    fw_semihost_write0(s);
}
#endif

static uint16_t frame[DET_W * DET_H];
static uint16_t depth[DET_W * DET_H];

/* CRC-32 (IEEE, reflected 0xEDB88320), bitwise: the same value as the host's
 * crc32_update / fxl_host_crc_target on a little-endian machine. */
static uint32_t crc32_bytes(uint32_t crc, const uint8_t *p, uint32_t n)
{
    uint32_t i;
    int k;
    crc = ~crc;
    for (i = 0; i < n; i++) {
        crc ^= p[i];
        for (k = 0; k < 8; k++)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

static char *put_str(char *p, const char *s)
{
    while (*s)
        *p++ = *s++;
    return p;
}

static char *put_hex(char *p, uint32_t v)
{
    int i;
    for (i = 7; i >= 0; i--)
        *p++ = "0123456789abcdef"[(v >> (4 * i)) & 15u];
    return p;
}

int main(void)
{
    int s, k, failures = 0;
    for (s = 0; s < (int)DET_NSCENES; s++) {
        const det_scene_t *sc = &det_scenes[s];
        fxl_texture_t tex;
        int t = sc->tex;
        if (fxl_texture_init(&tex, det_tex_texels[t], det_tex_dims[t][0], det_tex_dims[t][1], FXL_TEXFMT_RGB565,
                             det_tex_dims[t][2]) != FXL_OK)
            return 1;
        for (k = 0; k < DET_NVARIANTS; k++) {
            fxl_target_t tg;
            fxl_draw_t d;
            fxl_status_t st = FXL_OK;
            uint32_t i, crc;
            char line[160], *p = line;
            det_draw_settings(&det_variants[k], &d);
            d.texture = &tex;
            fxl_target_init(&tg, frame, DET_W, DET_H, DET_W, FXL_PIXFMT_RGB565);
            fxl_target_set_depth(&tg, depth);
            fxl_target_clear(&tg, 0);
            fxl_target_clear_depth(&tg);
            for (i = 0; i < sc->tris && st == FXL_OK; i++)
                st = fxl_draw_triangle(&tg, &d, &sc->verts[3 * i], 0);
            if (st != FXL_OK)
                failures++;
            crc = crc32_bytes(0, (const uint8_t *)frame, (uint32_t)sizeof frame);
            p = put_str(p, sc->name);
            p = put_str(p, " ");
            p = put_str(p, det_variants[k].name);
            p = put_str(p, " ");
            p = put_str(p, fxl_status_name(st));
            p = put_str(p, " ");
            p = put_hex(p, crc);
            p = put_str(p, "\n");
            *p = 0;
            out(line);
        }
    }
    out("done\n");
    /* on the target, the start-up passes this to SYS_EXIT_EXTENDED */
    return failures ? 1 : 0;
}
