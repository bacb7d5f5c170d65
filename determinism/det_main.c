/* det_main.c - render the determinism list and print one CRC per frame.
 *
 * The same file is built for the host (-DDET_HOST: stdio) and bare-metal
 * Cortex-M4 / M0+ and RISC-V (semihosting, see examples/common/
 * mps2_startup.c and virt_rv_startup.c). No libc and no floating point on
 * the target: formatting is done here. Output lines: "<scene> <variant>
 * <status> <crc32 hex>", the screen-space frames first, then the front-end
 * frames (det_entries.h), then one line a DET_STRESS_LINE stress cases
 * (det_stress.h), "stress <first case> ok <cases drawn FXL_OK> <hash hex>"
 * for triangles and "stress_fe ..." for meshes through the front end, then
 * "done". Data
 * (vertices, meshes, front-end parameters, textures) comes from det_data.h,
 * generated on the host by gen_data.c.
 */
#include <stdint.h>

#include "fixel/fixel.h"
#include "det_entries.h"
#include "det_data.h"
#include "det_stress.h"

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
static det_stress_assets_t stress_assets;
static det_stress_fe_case_t stress_fe;
/* pscene_draw's vertex cache: one entry per vertex of the largest part
 * (56 bytes each, 57 KB for the tunnel's 1025 vertices). */
static fxl_vcache_entry_t vcache[DET_PIPE_CACHE_MAX];

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

static char *put_dec(char *p, uint32_t v)
{
    char t[10];
    int n = 0;
    do {
        t[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v != 0u);
    while (n > 0)
        *p++ = t[--n];
    return p;
}

static char *put_hex(char *p, uint32_t v)
{
    int i;
    for (i = 7; i >= 0; i--)
        *p++ = "0123456789abcdef"[(v >> (4 * i)) & 15u];
    return p;
}

static fxl_status_t texture_of(int t, fxl_texture_t *tex)
{
    return fxl_texture_init(tex, det_tex_texels[t], det_tex_dims[t][0], det_tex_dims[t][1], FXL_TEXFMT_RGB565,
                            det_tex_dims[t][2]);
}

/* scene_clear's sky (det_entries.h: DET_CLEAR_SKY): the same integer
 * expression per row, so the frame can match the gallery's golden CRC. */
static void clear_sky(uint16_t *px)
{
    static const int32_t top[3] = {96, 128, 176}, bot[3] = {28, 32, 44};
    const int32_t den = DET_H - 1;
    int32_t x, y;
    for (y = 0; y < DET_H; y++) {
        uint16_t c = FXL_RGB565(top[0] + (bot[0] - top[0]) * y / den, top[1] + (bot[1] - top[1]) * y / den,
                                top[2] + (bot[2] - top[2]) * y / den);
        for (x = 0; x < DET_W; x++)
            px[y * DET_W + x] = c;
    }
}

static void print_frame(const char *scene, const char *variant, fxl_status_t st)
{
    char line[160], *p = line;
    uint32_t crc = crc32_bytes(0, (const uint8_t *)frame, (uint32_t)sizeof frame);
    p = put_str(p, scene);
    p = put_str(p, " ");
    p = put_str(p, variant);
    p = put_str(p, " ");
    p = put_str(p, fxl_status_name(st));
    p = put_str(p, " ");
    p = put_hex(p, crc);
    p = put_str(p, "\n");
    *p = 0;
    out(line);
}

/* One front-end frame, as pscene_draw draws it: every part through
 * fxl_mesh_draw with its own pipeline (det_pipe_build) and draw state,
 * sharing one vertex cache sized to the scene's largest part. */
static fxl_status_t draw_pscene(const det_pscene_t *sc, const det_pvariant_t *pv, fxl_target_t *tg)
{
    int i;
    for (i = 0; i < sc->nparts; i++) {
        const det_ppart_t *pt = &sc->parts[i];
        fxl_pipeline_t pipe;
        fxl_texture_t tex;
        fxl_draw_t d;
        fxl_status_t st = det_pipe_build(sc, pt, &pipe);
        if (st == FXL_OK && pv->cache)
            st = fxl_pipeline_set_vertex_cache(&pipe, vcache, sc->cache_entries);
        if (st == FXL_OK)
            st = texture_of(pt->tex, &tex);
        if (st != FXL_OK)
            return st;
        det_part_draw_settings(pv, pt, &tex, &d);
        st = fxl_mesh_draw(&pipe, tg, &d, &pt->mesh, 0);
        if (st != FXL_OK)
            return st;
    }
    return FXL_OK;
}

int main(void)
{
    int s, k, failures = 0;
    for (s = 0; s < (int)DET_NSCENES; s++) {
        const det_scene_t *sc = &det_scenes[s];
        fxl_texture_t tex;
        if (texture_of(sc->tex, &tex) != FXL_OK)
            return 1;
        for (k = 0; k < DET_NVARIANTS; k++) {
            fxl_target_t tg;
            fxl_draw_t d;
            fxl_status_t st = FXL_OK;
            uint32_t i;
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
            print_frame(sc->name, det_variants[k].name, st);
        }
    }
    for (s = 0; s < (int)DET_NPSCENES; s++) {
        for (k = 0; k < DET_NPVARIANTS; k++) {
            const det_pvariant_t *pv = &det_pvariants[k];
            fxl_target_t tg;
            fxl_status_t st;
            fxl_target_init(&tg, frame, DET_W, DET_H, DET_W, FXL_PIXFMT_RGB565);
            fxl_target_set_depth(&tg, depth);
            if (pv->clear == DET_CLEAR_SKY)
                clear_sky(frame);
            else
                fxl_target_clear(&tg, DET_PANEL_CLEAR);
            fxl_target_clear_depth(&tg);
            st = draw_pscene(&det_pscenes[s], pv, &tg);
            if (st != FXL_OK)
                failures++;
            print_frame(det_pscenes[s].name, pv->v.name, st);
        }
    }
    /* the stress cases, in the frame's buffers (each case refills what it
     * uses), a line a batch so a difference points at its cases: first
     * triangles, then meshes through the front end */
    det_stress_assets_init(&stress_assets);
    for (s = 0; s < DET_STRESS_ALL; s += DET_STRESS_LINE) {
        char line[80], *p = line;
        uint32_t hash = 0, ok = 0, first;
        (void)det_stress_is_mesh((uint32_t)s, &first);
        for (k = s; k < s + DET_STRESS_LINE; k++) {
            det_stress_case_t tri;
            fxl_status_t st;
            (void)det_stress_prepare((uint32_t)k, &stress_assets, frame, depth, &tri, &stress_fe);
            hash = det_stress_run((uint32_t)k, &tri, &stress_fe, hash, &st);
            ok += st == FXL_OK;
        }
        p = put_str(p, det_stress_line_name((uint32_t)s));
        p = put_str(p, " ");
        p = put_dec(p, first);
        p = put_str(p, " ok ");
        p = put_dec(p, ok);
        p = put_str(p, " ");
        p = put_hex(p, hash);
        p = put_str(p, "\n");
        *p = 0;
        out(line);
    }
    out("done\n");
    /* on the target, the start-up passes this to SYS_EXIT_EXTENDED */
    return failures ? 1 : 0;
}
