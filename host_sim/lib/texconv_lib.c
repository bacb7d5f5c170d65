/* host_sim/lib/texconv_lib.c - PNG -> fixel texture chain; see texconv_lib.h. */
#define _POSIX_C_SOURCE 200809L
#include "texconv_lib.h"
#include "outfile.h"

#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>


#define TEXCONV_MAX_SIDE (1u << FXL_TEX_MAX_LOG2)

void texconv_opts_default(texconv_opts_t *o)
{
    memset(o, 0, sizeof *o);
    o->format = FXL_TEXFMT_RGB565;
    o->mips = TEXCONV_MIPS_BOX;
    o->wrap_u = o->wrap_v = FXL_WRAP_REPEAT;
}

uint16_t texconv_rgb565(uint32_t r, uint32_t g, uint32_t b)
{
    return (uint16_t)((((r * 31u + 127u) / 255u) << 11) | (((g * 63u + 127u) / 255u) << 5) |
                      ((b * 31u + 127u) / 255u));
}

uint8_t texconv_luma(uint32_t r, uint32_t g, uint32_t b)
{
    return (uint8_t)((77u * r + 150u * g + 29u * b + 128u) >> 8);
}

static uint32_t expand5(uint32_t c) { return (c << 3) | (c >> 2); }
static uint32_t expand6(uint32_t c) { return (c << 2) | (c >> 4); }

static void expand565(uint32_t c, uint32_t rgb8[3])
{
    rgb8[0] = expand5(c >> 11);
    rgb8[1] = expand6((c >> 5) & 63u);
    rgb8[2] = expand5(c & 31u);
}

/* ---- PNG reading ------------------------------------------------------------ */

struct png_err {
    char msg[160];
};

static void png_err_fn(png_structp png, png_const_charp msg)
{
    struct png_err *e = (struct png_err *)png_get_error_ptr(png);
    snprintf(e->msg, sizeof e->msg, "%s", msg);
    png_longjmp(png, 1);
}

static void png_warn_fn(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg; /* warnings (e.g. unknown chunks) do not stop a conversion */
}

void texconv_image_free(texconv_image_t *img)
{
    if (img != NULL) {
        free(img->rgba);
        img->rgba = NULL;
        img->width = img->height = 0;
    }
}

int texconv_read_png(const char *path, texconv_image_t *img, char *err, size_t err_size)
{
    FILE *f;
    unsigned char sig[8];
    png_structp png = NULL;
    png_infop info = NULL;
    struct png_err perr;
    uint8_t *volatile pixels = NULL;
    png_bytep *volatile rows = NULL;
    png_uint_32 w, h, y;
    int color, depth;

    memset(img, 0, sizeof *img);
    perr.msg[0] = '\0';
    f = fopen(path, "rb");
    if (f == NULL) {
        snprintf(err, err_size, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    if (fread(sig, 1, sizeof sig, f) != sizeof sig || png_sig_cmp(sig, 0, sizeof sig) != 0) {
        snprintf(err, err_size, "%s: not a PNG file", path);
        fclose(f);
        return -1;
    }
    png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &perr, png_err_fn, png_warn_fn);
    if (png != NULL)
        info = png_create_info_struct(png);
    if (png == NULL || info == NULL) {
        snprintf(err, err_size, "%s: out of memory", path);
        png_destroy_read_struct(&png, &info, NULL);
        fclose(f);
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        snprintf(err, err_size, "%s: corrupt or truncated PNG (libpng: %s)", path,
                 perr.msg[0] != '\0' ? perr.msg : "error");
        png_destroy_read_struct(&png, &info, NULL);
        free(rows);
        free(pixels);
        fclose(f);
        return -1;
    }
    png_init_io(png, f);
    png_set_sig_bytes(png, (int)sizeof sig);
    png_read_info(png, info);
    w = png_get_image_width(png, info);
    h = png_get_image_height(png, info);
    color = png_get_color_type(png, info);
    depth = png_get_bit_depth(png, info);
    if (w == 0 || h == 0 || w > TEXCONV_MAX_SIDE || h > TEXCONV_MAX_SIDE) {
        snprintf(err, err_size, "%s: %lux%lu is outside the texture size range 1..%u", path,
                 (unsigned long)w, (unsigned long)h, TEXCONV_MAX_SIDE);
        png_destroy_read_struct(&png, &info, NULL);
        fclose(f);
        return -1;
    }
    /* Every colour type and depth -> 8-bit RGBA. */
    if (color == PNG_COLOR_TYPE_PALETTE)
        png_set_palette_to_rgb(png);
    if (color == PNG_COLOR_TYPE_GRAY && depth < 8)
        png_set_expand_gray_1_2_4_to_8(png);
    if (png_get_valid(png, info, PNG_INFO_tRNS))
        png_set_tRNS_to_alpha(png);
    else if ((color & PNG_COLOR_MASK_ALPHA) == 0)
        png_set_filler(png, 0xFF, PNG_FILLER_AFTER);
    if (depth == 16) {
        /* Round like png_io.c (v8 = (v16 * 255 + 32767) / 65535): strip_16
         * keeps the high byte, so 0xFF00 became 255 instead of 254. */
#ifdef PNG_READ_SCALE_16_TO_8_SUPPORTED
        png_set_scale_16(png);
#else
        png_set_strip_16(png);
#endif
    }
    if (color == PNG_COLOR_TYPE_GRAY || color == PNG_COLOR_TYPE_GRAY_ALPHA)
        png_set_gray_to_rgb(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    if (png_get_rowbytes(png, info) != (size_t)w * 4u) {
        snprintf(err, err_size, "%s: unsupported PNG layout", path);
        png_destroy_read_struct(&png, &info, NULL);
        fclose(f);
        return -1;
    }
    pixels = (uint8_t *)malloc((size_t)w * h * 4u);
    rows = (png_bytep *)malloc(sizeof(png_bytep) * h);
    if (pixels == NULL || rows == NULL)
        png_error(png, "out of memory");
    for (y = 0; y < h; y++)
        rows[y] = pixels + (size_t)y * w * 4u;
    png_read_image(png, rows);
    png_read_end(png, NULL);
    png_destroy_read_struct(&png, &info, NULL);
    free(rows);
    fclose(f);
    img->width = w;
    img->height = h;
    img->rgba = pixels;
    return 0;
}

/* ---- I8 palette --------------------------------------------------------------- */

typedef struct qcolor {
    uint16_t c565;
    uint32_t count;
} qcolor_t;

static int g_sort_channel; /* qsort has no context argument; tool is single-threaded */

static int cmp_channel(const void *pa, const void *pb)
{
    const qcolor_t *a = (const qcolor_t *)pa, *b = (const qcolor_t *)pb;
    uint32_t ca[3], cb[3];
    expand565(a->c565, ca);
    expand565(b->c565, cb);
    if (ca[g_sort_channel] != cb[g_sort_channel])
        return ca[g_sort_channel] < cb[g_sort_channel] ? -1 : 1;
    return a->c565 < b->c565 ? -1 : a->c565 > b->c565; /* deterministic order */
}

typedef struct qbox {
    uint32_t first, count;
} qbox_t;

/* Widest channel of a box (8-bit expanded), -1 when it holds one colour. */
static int box_widest(const qcolor_t *col, const qbox_t *b, uint32_t *extent)
{
    uint32_t lo[3] = {255, 255, 255}, hi[3] = {0, 0, 0}, i, k, c[3];
    int best = -1;
    *extent = 0;
    for (i = 0; i < b->count; i++) {
        expand565(col[b->first + i].c565, c);
        for (k = 0; k < 3; k++) {
            if (c[k] < lo[k]) lo[k] = c[k];
            if (c[k] > hi[k]) hi[k] = c[k];
        }
    }
    if (b->count < 2)
        return -1;
    for (k = 0; k < 3; k++)
        if (hi[k] - lo[k] > *extent || best < 0) {
            *extent = hi[k] - lo[k];
            best = (int)k;
        }
    return best;
}

/* Median cut over distinct RGB565 colours weighted by pixel count: split the
 * box with the widest channel extent at its weighted median until `cap` boxes;
 * each entry is the count-weighted mean colour of its box. */
static uint32_t median_cut(qcolor_t *col, uint32_t ncol, uint16_t *out, uint32_t cap)
{
    qbox_t *box = (qbox_t *)malloc(sizeof(qbox_t) * cap);
    uint32_t nbox = 1, i, k;
    if (box == NULL)
        return 0;
    box[0].first = 0;
    box[0].count = ncol;
    while (nbox < cap) {
        uint32_t best = 0, best_ext = 0, ext, total = 0, acc = 0, split;
        int ch = -1, c;
        for (i = 0; i < nbox; i++) {
            c = box_widest(col, &box[i], &ext);
            if (c >= 0 && (ch < 0 || ext > best_ext)) {
                ch = c;
                best = i;
                best_ext = ext;
            }
        }
        if (ch < 0)
            break; /* every box holds one colour */
        g_sort_channel = ch;
        qsort(col + box[best].first, box[best].count, sizeof(qcolor_t), cmp_channel);
        for (i = 0; i < box[best].count; i++)
            total += col[box[best].first + i].count;
        for (split = 0; split < box[best].count - 1u; split++) {
            acc += col[box[best].first + split].count;
            if (2u * acc >= total)
                break;
        }
        /* first colour of the upper half: 1 .. count-1. Without the test a
         * last colour holding over half the box's pixels left the loop at
         * count-1 and made the upper half empty (then a division by its
         * zero pixel count below). */
        if (split < box[best].count - 1u)
            split++;
        box[nbox].first = box[best].first + split;
        box[nbox].count = box[best].count - split;
        box[best].count = split;
        nbox++;
    }
    for (i = 0; i < nbox; i++) {
        uint64_t sum[3] = {0, 0, 0}, n = 0;
        uint32_t c[3];
        for (k = 0; k < box[i].count; k++) {
            const qcolor_t *q = &col[box[i].first + k];
            expand565(q->c565, c);
            sum[0] += (uint64_t)c[0] * q->count;
            sum[1] += (uint64_t)c[1] * q->count;
            sum[2] += (uint64_t)c[2] * q->count;
            n += q->count;
        }
        out[i] = texconv_rgb565((uint32_t)((sum[0] + n / 2) / n), (uint32_t)((sum[1] + n / 2) / n),
                                (uint32_t)((sum[2] + n / 2) / n));
    }
    free(box);
    return nbox;
}

/* Nearest palette entry in [first, used) to RGB565 colour c; ties lowest. */
static uint32_t nearest_entry(const uint16_t *pal, uint32_t first, uint32_t used, uint32_t c)
{
    uint32_t i, best = first, best_d = UINT32_MAX, a[3], b[3];
    expand565(c, a);
    for (i = first; i < used; i++) {
        int32_t d0, d1, d2;
        uint32_t d;
        expand565(pal[i], b);
        d0 = (int32_t)a[0] - (int32_t)b[0];
        d1 = (int32_t)a[1] - (int32_t)b[1];
        d2 = (int32_t)a[2] - (int32_t)b[2];
        d = (uint32_t)(d0 * d0 + d1 * d1 + d2 * d2);
        if (d < best_d) {
            best_d = d;
            best = i;
        }
    }
    return best;
}

/* ---- conversion --------------------------------------------------------------- */

static int is_transparent(const texconv_opts_t *o, const uint8_t *p)
{
    uint32_t rgb = ((uint32_t)p[0] << 16) | ((uint32_t)p[1] << 8) | p[2];
    return o->has_key && (p[3] < 128u || rgb == o->key_rgb);
}

void texconv_chain_free(texconv_chain_t *c)
{
    if (c != NULL) {
        free(c->texels);
        free(c->palette);
        memset(c, 0, sizeof *c);
    }
}

static int log2_exact(uint32_t v)
{
    int n = 0;
    if (v == 0 || (v & (v - 1u)) != 0)
        return -1;
    while (v > 1u) {
        v >>= 1;
        n++;
    }
    return n;
}

static int build_i8(const texconv_image_t *img, const texconv_opts_t *o, uint16_t key565,
                    uint16_t *pal, uint8_t *dst, uint32_t *used_out)
{
    uint32_t *hist = (uint32_t *)calloc(65536u, sizeof(uint32_t));
    int32_t *map = (int32_t *)malloc(65536u * sizeof(int32_t));
    qcolor_t *col = NULL;
    uint32_t n = img->width * img->height, i, ncol = 0, first = o->has_key ? 1u : 0u;
    uint32_t cap = 256u - first, used;

    if (hist == NULL || map == NULL) {
        free(hist);
        free(map);
        return -1;
    }
    for (i = 0; i < n; i++) {
        const uint8_t *p = img->rgba + 4u * i;
        if (!is_transparent(o, p))
            hist[texconv_rgb565(p[0], p[1], p[2])]++;
    }
    for (i = 0; i < 65536u; i++)
        ncol += hist[i] != 0;
    col = (qcolor_t *)malloc(sizeof(qcolor_t) * (ncol > 0 ? ncol : 1u));
    if (col == NULL) {
        free(hist);
        free(map);
        return -1;
    }
    ncol = 0;
    for (i = 0; i < 65536u; i++)
        if (hist[i] != 0) {
            col[ncol].c565 = (uint16_t)i;
            col[ncol].count = hist[i];
            ncol++;
        }
    if (o->has_key)
        pal[0] = key565;
    if (ncol <= cap) {
        for (i = 0; i < ncol; i++)
            pal[first + i] = col[i].c565; /* exact: ascending RGB565 order */
        used = first + ncol;
    } else {
        used = first + median_cut(col, ncol, pal + first, cap);
    }
    /* Unused entries repeat the first opaque one (or the key): a nearest
     * search finds the original first, so they are never chosen. */
    for (i = used; i < 256u; i++)
        pal[i] = pal[used > first ? first : 0];
    for (i = 0; i < 65536u; i++)
        map[i] = -1;
    for (i = 0; i < n; i++) {
        const uint8_t *p = img->rgba + 4u * i;
        uint16_t c;
        if (is_transparent(o, p)) {
            dst[i] = 0; /* the key index */
            continue;
        }
        c = texconv_rgb565(p[0], p[1], p[2]);
        if (map[c] < 0)
            map[c] = (int32_t)nearest_entry(pal, first, used > first ? used : first + 1u, c);
        dst[i] = (uint8_t)map[c];
    }
    *used_out = used;
    free(col);
    free(hist);
    free(map);
    return 0;
}

int texconv_convert(const texconv_image_t *img, const texconv_opts_t *o, texconv_chain_t *out,
                    char *err, size_t err_size)
{
    int lw = log2_exact(img->width), lh = log2_exact(img->height);
    uint32_t levels, bytes, n, i, bpp;
    uint16_t key = 0;
    fxl_mip_space_t space;
    fxl_status_t st;

    memset(out, 0, sizeof *out);
    if (img->rgba == NULL || lw < 0 || lh < 0 || lw > FXL_TEX_MAX_LOG2 || lh > FXL_TEX_MAX_LOG2) {
        snprintf(err, err_size,
                 "%lux%lu is not a power-of-two size up to %u (fixel textures need "
                 "power-of-two sides: pad or resample the image)",
                 (unsigned long)img->width, (unsigned long)img->height, TEXCONV_MAX_SIDE);
        return -1;
    }
    bpp = fxl_texfmt_bytes(o->format);
    if (bpp == 0 || o->wrap_u > FXL_WRAP_BORDER || o->wrap_v > FXL_WRAP_BORDER ||
        o->mips > TEXCONV_MIPS_SRGB) {
        snprintf(err, err_size, "invalid conversion options");
        return -1;
    }
    levels = o->mips == TEXCONV_MIPS_NONE ? 1u : fxl_mip_levels(img->width, img->height);
    bytes = fxl_mip_size(img->width, img->height, o->format, levels);
    out->texels = calloc(bytes, 1);
    if (o->format == FXL_TEXFMT_I8)
        out->palette = (uint16_t *)calloc(256u, sizeof(uint16_t));
    if (out->texels == NULL || (o->format == FXL_TEXFMT_I8 && out->palette == NULL)) {
        snprintf(err, err_size, "out of memory");
        texconv_chain_free(out);
        return -1;
    }
    out->bytes = bytes;
    out->texel_count = bytes / bpp;

    n = img->width * img->height;
    if (o->format == FXL_TEXFMT_RGB565) {
        uint16_t *t = (uint16_t *)out->texels;
        key = texconv_rgb565(o->key_rgb >> 16, (o->key_rgb >> 8) & 255u, o->key_rgb & 255u);
        for (i = 0; i < n; i++) {
            const uint8_t *p = img->rgba + 4u * i;
            uint16_t v = texconv_rgb565(p[0], p[1], p[2]);
            if (is_transparent(o, p))
                v = key;
            else if (o->has_key && v == key)
                v ^= 1u; /* opaque: keep it off the key value */
            t[i] = v;
        }
    } else if (o->format == FXL_TEXFMT_L8) {
        uint8_t *t = (uint8_t *)out->texels;
        key = texconv_luma(o->key_rgb >> 16, (o->key_rgb >> 8) & 255u, o->key_rgb & 255u);
        for (i = 0; i < n; i++) {
            const uint8_t *p = img->rgba + 4u * i;
            uint8_t v = texconv_luma(p[0], p[1], p[2]);
            if (is_transparent(o, p))
                v = (uint8_t)key;
            else if (o->has_key && v == key)
                v = (uint8_t)(v == 255u ? 254u : v + 1u);
            t[i] = v;
        }
    } else {
        uint16_t key565 =
            texconv_rgb565(o->key_rgb >> 16, (o->key_rgb >> 8) & 255u, o->key_rgb & 255u);
        key = 0; /* index 0 is reserved for transparent pixels */
        if (build_i8(img, o, key565, out->palette, (uint8_t *)out->texels, &out->palette_used)) {
            snprintf(err, err_size, "out of memory");
            texconv_chain_free(out);
            return -1;
        }
    }

    space = o->mips == TEXCONV_MIPS_GAMMA22 ? FXL_MIP_SPACE_GAMMA22
          : o->mips == TEXCONV_MIPS_SRGB    ? FXL_MIP_SPACE_SRGB
                                            : FXL_MIP_SPACE_STORED;
    st = fxl_mip_build_keyed(out->texels, bytes, img->width, img->height, o->format, levels,
                              out->palette, space, o->has_key ? &key : NULL);
    if (st == FXL_OK)
        st = fxl_texture_init(&out->tex, out->texels, img->width, img->height, o->format, levels);
    if (st != FXL_OK) {
        snprintf(err, err_size, "mip build failed: %s", fxl_status_name(st));
        texconv_chain_free(out);
        return -1;
    }
    out->tex.palette = out->palette;
    out->tex.wrap_u = (uint8_t)o->wrap_u;
    out->tex.wrap_v = (uint8_t)o->wrap_v;
    out->tex.flags = o->has_key ? FXL_TEXF_KEY : 0u;
    out->tex.key = o->has_key ? key : 0u;
    out->tex.border =
        texconv_rgb565(o->border_rgb >> 16, (o->border_rgb >> 8) & 255u, o->border_rgb & 255u);
    st = fxl_texture_validate(&out->tex);
    if (st != FXL_OK) {
        snprintf(err, err_size, "descriptor invalid: %s", fxl_status_name(st));
        texconv_chain_free(out);
        return -1;
    }
    return 0;
}

/* ---- writers ------------------------------------------------------------------- */

static const char *const k_fmt_names[] = {"rgb565", "l8", "i8"};
static const char *const k_wrap_names[] = {"repeat", "mirror", "clamp", "border"};
static const char *const k_wrap_enums[] = {"FXL_WRAP_REPEAT", "FXL_WRAP_MIRROR", "FXL_WRAP_CLAMP",
                                           "FXL_WRAP_BORDER"};
static const char *const k_fmt_enums[] = {"FXL_TEXFMT_RGB565", "FXL_TEXFMT_L8", "FXL_TEXFMT_I8"};
static const char *const k_mips_names[] = {"none", "box", "gamma22", "srgb"};

static void write_comment_text(FILE *f, const char *s)
{
    for (; *s != '\0'; s++) {
        if (s[0] == '*' && s[1] == '/')
            fputs("* ", f); /* never close the comment early */
        else if (*s == '\n' || *s == '\r')
            fputc(' ', f);
        else
            fputc(*s, f);
    }
}

int texconv_write_c(FILE *f, const texconv_chain_t *c, const char *name, const char *command,
                    const texconv_opts_t *o)
{
    const fxl_texture_t *t = &c->tex;
    uint32_t lv, i, w = 1u << t->log2_w, h = 1u << t->log2_h;
    int wide = t->format == FXL_TEXFMT_RGB565;

    fprintf(f, "/* Generated by fixel-texconv; do not edit.\n *   command: ");
    write_comment_text(f, command != NULL ? command : "");
    fprintf(f, "\n *   %lux%lu %s, %u level%s (%lu texels, %lu bytes), mips %s\n *   levels:",
            (unsigned long)w, (unsigned long)h, k_fmt_names[t->format], (unsigned)t->levels,
            t->levels == 1 ? "" : "s", (unsigned long)c->texel_count, (unsigned long)c->bytes,
            k_mips_names[o->mips]);
    for (lv = 0; lv < t->levels; lv++) {
        uint32_t lw = w >> lv, lh = h >> lv;
        fprintf(f, " %lux%lu", (unsigned long)(lw ? lw : 1u), (unsigned long)(lh ? lh : 1u));
    }
    fprintf(f, "\n *   wrap %s/%s, ", k_wrap_names[t->wrap_u], k_wrap_names[t->wrap_v]);
    if (t->flags & FXL_TEXF_KEY)
        fprintf(f, "key 0x%04X (from #%06lX)", (unsigned)t->key, (unsigned long)o->key_rgb);
    else
        fprintf(f, "no key");
    fprintf(f, ", border 0x%04X\n *   use: extern const fxl_texture_t %s;\n */\n", (unsigned)t->border,
            name);
    fprintf(f, "#include <stdint.h>\n#include \"fixel/texture.h\"\n\n");

    fprintf(f, "static const %s %s_texels[%lu] = {", wide ? "uint16_t" : "uint8_t", name,
            (unsigned long)c->texel_count);
    for (i = 0; i < c->texel_count; i++) {
        if (i % (wide ? 12u : 16u) == 0)
            fprintf(f, "\n   ");
        if (wide)
            fprintf(f, " 0x%04X,", (unsigned)((const uint16_t *)c->texels)[i]);
        else
            fprintf(f, " 0x%02X,", (unsigned)((const uint8_t *)c->texels)[i]);
    }
    fprintf(f, "\n};\n\n");
    if (c->palette != NULL) {
        fprintf(f, "static const uint16_t %s_palette[256] = {", name);
        for (i = 0; i < 256u; i++) {
            if (i % 12u == 0)
                fprintf(f, "\n   ");
            fprintf(f, " 0x%04X,", (unsigned)c->palette[i]);
        }
        fprintf(f, "\n};\n\n");
    }
    fprintf(f,
            "const fxl_texture_t %s = {\n"
            "    .texels = %s_texels,\n",
            name, name);
    if (c->palette != NULL)
        fprintf(f, "    .palette = %s_palette,\n", name);
    else
        fprintf(f, "    .palette = 0,\n");
    fprintf(f,
            "    .log2_w = %u,\n    .log2_h = %u,\n    .levels = %u,\n    .format = %s,\n"
            "    .wrap_u = %s,\n    .wrap_v = %s,\n    .flags = %s,\n    .reserved = 0,\n"
            "    .key = 0x%04X,\n    .border = 0x%04X\n};\n",
            (unsigned)t->log2_w, (unsigned)t->log2_h, (unsigned)t->levels, k_fmt_enums[t->format],
            k_wrap_enums[t->wrap_u], k_wrap_enums[t->wrap_v],
            (t->flags & FXL_TEXF_KEY) ? "FXL_TEXF_KEY" : "0", (unsigned)t->key,
            (unsigned)t->border);
    return ferror(f) ? -1 : 0;
}

static void put16(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
}

int texconv_write_bin(FILE *f, const texconv_chain_t *c)
{
    const fxl_texture_t *t = &c->tex;
    uint8_t hdr[TEXCONV_BLOB_HEADER_BYTES], b2[2];
    uint32_t i;

    memset(hdr, 0, sizeof hdr);
    memcpy(hdr, "FXLT", 4);
    put16(hdr + 4, TEXCONV_BLOB_VERSION);
    hdr[6] = t->log2_w;
    hdr[7] = t->log2_h;
    hdr[8] = t->levels;
    hdr[9] = t->format;
    hdr[10] = t->wrap_u;
    hdr[11] = t->wrap_v;
    hdr[12] = t->flags;
    put16(hdr + 14, t->key);
    put16(hdr + 16, t->border);
    put16(hdr + 20, c->texel_count & 0xFFFFu);
    put16(hdr + 22, c->texel_count >> 16);
    fwrite(hdr, 1, sizeof hdr, f);
    if (c->palette != NULL)
        for (i = 0; i < 256u; i++) {
            put16(b2, c->palette[i]);
            fwrite(b2, 1, 2, f);
        }
    if (t->format == FXL_TEXFMT_RGB565) {
        for (i = 0; i < c->texel_count; i++) {
            put16(b2, ((const uint16_t *)c->texels)[i]);
            fwrite(b2, 1, 2, f);
        }
    } else {
        fwrite(c->texels, 1, c->texel_count, f);
    }
    return ferror(f) ? -1 : 0;
}

/* ---- the tool ------------------------------------------------------------------ */

static void usage(FILE *f)
{
    fprintf(f,
            "usage: fixel-texconv in.png [-o out.c] [--name NAME] [--bin out.bin]\n"
            "         [--format rgb565|l8|i8] [--mips none|box|gamma22|srgb]\n"
            "         [--key RRGGBB] [--wrap MODE[,MODE]] [--border RRGGBB]\n"
            "  MODE: repeat|mirror|clamp|border (one for both axes, or u,v)\n"
            "  At least one of -o and --bin. NAME defaults to the input's base name.\n"
            "  With --key, pixels with alpha < 128 or exactly RRGGBB are transparent.\n");
}

static int lookup(const char *s, const char *const *names, int count)
{
    int i;
    for (i = 0; i < count; i++)
        if (strcmp(s, names[i]) == 0)
            return i;
    return -1;
}

/* Exactly six hex digits (an optional leading '#'): strtoul alone also took
 * " +1234", "0x1234" and "-00001" (which wrapped to 0xFFFFFFFF). */
static int parse_rgb(const char *s, uint32_t *out)
{
    uint32_t v = 0;
    int i;
    if (s[0] == '#')
        s++;
    for (i = 0; i < 6; i++) {
        char c = s[i];
        uint32_t d;
        if (c >= '0' && c <= '9')
            d = (uint32_t)(c - '0');
        else if (c >= 'a' && c <= 'f')
            d = (uint32_t)(c - 'a' + 10);
        else if (c >= 'A' && c <= 'F')
            d = (uint32_t)(c - 'A' + 10);
        else
            return -1; /* also the terminator of a short string */
        v = (v << 4) | d;
    }
    if (s[6] != '\0')
        return -1;
    *out = v;
    return 0;
}

/* A C identifier that is not a C99 keyword ("--name int" emitted
 * `const fxl_texture_t int = {`, which does not compile). */
/* Whether identifier s belongs to a name space the generated file's
 * headers use: names ending in _t (POSIX; every <stdint.h> type and
 * fxl_texture_t), fixel's fxl_, FXL_ and FIXEL_ (its include guards), C's
 * reserved _X and __, and the <stdint.h> limit macros (upper case ending
 * in _MAX, _MIN, _WIDTH (C23) or _C, such as UINT16_MAX). Such a --name
 * gave C that did not compile, with exit 0. */
static int reserved_name(const char *s)
{
    const size_t n = strlen(s);
    size_t i;
    int upper = 1;
    if ((n >= 2 && strcmp(s + n - 2, "_t") == 0) || strncmp(s, "fxl_", 4) == 0 || strncmp(s, "FXL_", 4) == 0 ||
        strncmp(s, "FIXEL_", 6) == 0 ||
        (s[0] == '_' && (s[1] == '_' || (s[1] >= 'A' && s[1] <= 'Z'))))
        return 1;
    for (i = 0; i < n; i++)
        if (s[i] >= 'a' && s[i] <= 'z')
            upper = 0;
    return upper && ((n >= 4 && (strcmp(s + n - 4, "_MAX") == 0 || strcmp(s + n - 4, "_MIN") == 0)) ||
                     (n >= 6 && strcmp(s + n - 6, "_WIDTH") == 0) || (n >= 2 && strcmp(s + n - 2, "_C") == 0));
}

static int is_identifier(const char *s)
{
    static const char *const keywords[] = {
        "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else",
        "enum", "extern", "float", "for", "goto", "if", "inline", "int", "long", "register",
        "restrict", "return", "short", "signed", "sizeof", "static", "struct", "switch",
        "typedef", "union", "unsigned", "void", "volatile", "while", "_Bool", "_Complex",
        "_Imaginary",
        /* not a keyword, but an array of that name does not compile with
         * -Werror (-Wmain) and clashes with the program's own */
        "main"};
    const char *p = s;
    size_t k;
    if (*p == '\0' || (*p >= '0' && *p <= '9'))
        return 0;
    for (; *p != '\0'; p++)
        if (!((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') || (*p >= '0' && *p <= '9') ||
              *p == '_'))
            return 0;
    for (k = 0; k < sizeof keywords / sizeof keywords[0]; k++)
        if (strcmp(s, keywords[k]) == 0)
            return 0;
    return !reserved_name(s);
}

/* The directory part of `path` ("." when none) and its last component. */
static int split_path(const char *path, char *dir, size_t dir_size, const char **base)
{
    const char *slash = strrchr(path, '/');
    size_t n;
    if (slash == NULL) {
        snprintf(dir, dir_size, ".");
        *base = path;
        return 0;
    }
    n = (size_t)(slash - path);
    if (n == 0)
        n = 1; /* "/name": the root */
    if (n >= dir_size)
        return -1;
    memcpy(dir, path, n);
    dir[n] = '\0';
    *base = slash + 1;
    return 0;
}

/* 1 when paths a and b name the same file: the same inode when both exist,
 * else the same last component in the same directory. Output paths must not
 * meet each other or the input: "-o x --bin x" left only the blob in x, and
 * "-o in.png" replaced the image with C source, both with exit status 0. */
static int same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    char da[4096], db[4096];
    const char *ba, *bb;
    if (strcmp(a, b) == 0)
        return 1;
    if (stat(a, &sa) == 0 && stat(b, &sb) == 0)
        return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    if (split_path(a, da, sizeof da, &ba) != 0 || split_path(b, db, sizeof db, &bb) != 0 ||
        strcmp(ba, bb) != 0)
        return 0;
    return stat(da, &sa) == 0 && stat(db, &sb) == 0 && sa.st_dev == sb.st_dev &&
           sa.st_ino == sb.st_ino;
}

/* Base name of `path` without extension, made into a C identifier. */
static void default_name(const char *path, char *out, size_t n)
{
    const char *b = strrchr(path, '/');
    size_t i = 0;
    b = b != NULL ? b + 1 : path;
    if (*b >= '0' && *b <= '9' && i + 1 < n)
        out[i++] = '_';
    for (; *b != '\0' && *b != '.' && i + 1 < n; b++)
        out[i++] = ((*b >= 'a' && *b <= 'z') || (*b >= 'A' && *b <= 'Z') ||
                    (*b >= '0' && *b <= '9')) ? *b : '_';
    if (i == 0 && n > 4) {
        memcpy(out, "tex", 3);
        i = 3;
    }
    out[i] = '\0';
}

/* Output file written through a temp file in the same directory. */
int texconv_main(int argc, char **argv)
{
    const char *in = NULL, *out_c = NULL, *out_bin = NULL, *name = NULL;
    char name_buf[64], err[512], *command;
    size_t cmd_len = 1;
    texconv_opts_t o;
    texconv_image_t img;
    texconv_chain_t chain;
    outfile_t fc = {NULL, NULL, NULL}, fb = {NULL, NULL, NULL};
    int i, v, rc = 0, c_in_place;

    texconv_opts_default(&o);
    for (i = 1; i < argc; i++) {
        const char *a = argv[i], *val = i + 1 < argc ? argv[i + 1] : NULL;
        int takes = strcmp(a, "-o") == 0 || strcmp(a, "--name") == 0 || strcmp(a, "--bin") == 0 ||
                    strcmp(a, "--format") == 0 || strcmp(a, "--mips") == 0 ||
                    strcmp(a, "--key") == 0 || strcmp(a, "--wrap") == 0 ||
                    strcmp(a, "--border") == 0;
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            usage(stdout);
            return 0;
        }
        if (takes && (val == NULL || val[0] == '\0')) { /* "-o ''" wrote ".tmp.*" then failed */
            fprintf(stderr, "fixel-texconv: %s needs a value\n", a);
            return 2;
        }
        if (strcmp(a, "-o") == 0) {
            out_c = val;
        } else if (strcmp(a, "--name") == 0) {
            name = val;
        } else if (strcmp(a, "--bin") == 0) {
            out_bin = val;
        } else if (strcmp(a, "--format") == 0) {
            if ((v = lookup(val, k_fmt_names, 3)) < 0) {
                fprintf(stderr, "fixel-texconv: unknown format '%s' (rgb565, l8, i8)\n", val);
                return 2;
            }
            o.format = (fxl_texfmt_t)v;
        } else if (strcmp(a, "--mips") == 0) {
            if ((v = lookup(val, k_mips_names, 4)) < 0) {
                fprintf(stderr, "fixel-texconv: unknown mips '%s' (none, box, gamma22, srgb)\n",
                        val);
                return 2;
            }
            o.mips = (texconv_mips_t)v;
        } else if (strcmp(a, "--key") == 0 || strcmp(a, "--border") == 0) {
            uint32_t rgb;
            if (parse_rgb(val, &rgb) != 0) {
                fprintf(stderr, "fixel-texconv: %s wants RRGGBB hex, got '%s'\n", a, val);
                return 2;
            }
            if (a[2] == 'k') {
                o.has_key = 1;
                o.key_rgb = rgb;
            } else {
                o.border_rgb = rgb;
            }
        } else if (strcmp(a, "--wrap") == 0) {
            char buf[32];
            char *comma;
            int wu, wv;
            snprintf(buf, sizeof buf, "%s", val);
            comma = strchr(buf, ',');
            if (comma != NULL)
                *comma = '\0';
            wu = lookup(buf, k_wrap_names, 4);
            wv = comma != NULL ? lookup(comma + 1, k_wrap_names, 4) : wu;
            if (wu < 0 || wv < 0) {
                fprintf(stderr, "fixel-texconv: bad --wrap '%s' (repeat|mirror|clamp|border"
                                "[,...])\n", val);
                return 2;
            }
            o.wrap_u = (fxl_wrap_t)wu;
            o.wrap_v = (fxl_wrap_t)wv;
        } else if (a[0] == '-' && a[1] != '\0') {
            fprintf(stderr, "fixel-texconv: unknown option '%s'\n", a);
            usage(stderr);
            return 2;
        } else if (in == NULL) {
            in = a;
            continue;
        } else {
            fprintf(stderr, "fixel-texconv: more than one input ('%s', '%s')\n", in, a);
            return 2;
        }
        i++; /* consumed the value */
    }
    if (in == NULL || (out_c == NULL && out_bin == NULL)) {
        usage(stderr);
        return 2;
    }
    if (name == NULL) {
        default_name(in, name_buf, sizeof name_buf);
        name = name_buf;
    }
    if (!is_identifier(name)) {
        fprintf(stderr, "fixel-texconv: %s '%s' is not a C identifier (or is a C keyword or main, or a name "
                        "<stdint.h> or fixel uses: *_t, fxl_*, FXL_*, FIXEL_*, _X*, __*, *_MAX, *_MIN, *_WIDTH, *_C); "
                        "choose another with --name\n",
                name == name_buf ? "the name taken from the input file," : "--name", name);
        return 2;
    }
    if ((out_c != NULL && same_file(out_c, in)) || (out_bin != NULL && same_file(out_bin, in))) {
        fprintf(stderr, "fixel-texconv: the output %s is the input file; name another\n",
                out_c != NULL && same_file(out_c, in) ? out_c : out_bin);
        return 2;
    }
    if (out_c != NULL && out_bin != NULL && same_file(out_c, out_bin)) {
        fprintf(stderr, "fixel-texconv: -o and --bin name the same file (%s); give two paths\n",
                out_c);
        return 2;
    }

    if (texconv_read_png(in, &img, err, sizeof err) != 0) {
        fprintf(stderr, "fixel-texconv: %s\n", err);
        return 1;
    }
    if (texconv_convert(&img, &o, &chain, err, sizeof err) != 0) {
        fprintf(stderr, "fixel-texconv: %s: %s\n", in, err);
        texconv_image_free(&img);
        return 1;
    }
    texconv_image_free(&img);

    /* the command as written below: the tool's own name for argv[0], which
     * may be shorter (a symlink, exec -a) */
    for (i = 0; i < argc; i++)
        cmd_len += strlen(i == 0 ? "fixel-texconv" : argv[i]) + 1;
    command = (char *)malloc(cmd_len);
    if (command == NULL) {
        texconv_chain_free(&chain);
        return 1;
    }
    command[0] = '\0';
    for (i = 0; i < argc; i++) {
        if (i > 0)
            strcat(command, " ");
        strcat(command, i == 0 ? "fixel-texconv" : argv[i]);
    }

    /* Write every output to a temp file first; rename only when all are
     * complete, so an error never leaves a partial or mismatched pair. */
    if (out_c != NULL) {
        if (outfile_open(&fc, out_c) != 0) {
            fprintf(stderr, "fixel-texconv: %s: cannot create: %s\n", out_c, strerror(errno));
            rc = 1;
        } else if (texconv_write_c(fc.f, &chain, name, command, &o) != 0 ||
                   outfile_close(&fc, 0) != 0) {
            fprintf(stderr, "fixel-texconv: %s: write failed\n", out_c);
            rc = 1;
        }
    }
    if (rc == 0 && out_bin != NULL) {
        if (outfile_open(&fb, out_bin) != 0) {
            fprintf(stderr, "fixel-texconv: %s: cannot create: %s\n", out_bin, strerror(errno));
            rc = 1;
        } else if (texconv_write_bin(fb.f, &chain) != 0 || outfile_close(&fb, 0) != 0) {
            fprintf(stderr, "fixel-texconv: %s: write failed\n", out_bin);
            rc = 1;
        }
    }
    c_in_place = fc.tmp == NULL;   /* a device: never unlinked below */
    if (rc == 0 && outfile_commit(&fc) != 0) {
        fprintf(stderr, "fixel-texconv: %s: cannot rename into place: %s\n", out_c,
                strerror(errno));
        rc = 1;
    }
    if (rc == 0 && outfile_commit(&fb) != 0) {
        fprintf(stderr, "fixel-texconv: %s: cannot rename into place: %s\n", out_bin,
                strerror(errno));
        if (out_c != NULL && !c_in_place)
            unlink(out_c); /* do not leave half of the pair */
        rc = 1;
    }
    outfile_abandon(&fc);
    outfile_abandon(&fb);
    free(command);
    texconv_chain_free(&chain);
    return rc;
}
