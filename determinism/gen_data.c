/* gen_data.c - writes det_data.h: everything the determinism list
 * (det_entries.h) draws, as C arrays, so every build, the Cortex-M ones
 * included, renders exactly the host's inputs:
 * - the gallery scenes' screen-space vertices (the scenes are projected in
 *   double on the host; libm on the target might round differently);
 * - the pipeline scenes (pipe_scenes.h) as the fixed-point front end takes
 *   them: object-space meshes (q16 positions, normals, uv; indices), and
 *   per part the model's rotation angles and q16 translation, texgen,
 *   lighting and camera parameters, which det_pipe_build turns into the
 *   pipeline on the target with the core's own integer code. The host's
 *   scenes compute their constants in double once and store them as q16;
 *   those stored values are read back here from the built scene (angles:
 *   the ones whose fxl_mat4_rotate_* entries are the model's), and the
 *   pipeline det_pipe_build makes from them must equal the host's field by
 *   field, or this program fails;
 * - the textures of both (full mip chains), by texture_id_t, after checking
 *   that fxl_texture_init over the texels gives the host's descriptor.
 * With a golden file it also writes the expected lines of the front-end
 * frames (det_pvariants' golden keys looked up in it), in det_main's
 * format, for determinism.sh to find in every build's list.
 *   gen_data OUT.h [GALLERY_CRC.txt EXPECTED.txt]
 * (linked with fixel_host; see host_sim/scripts/determinism.sh)
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene.h"
#include "textures.h"
#include "det_entries.h"

/* fxl_texture_init over t's texels must describe them as the host does:
 * det_main builds its descriptors that way. */
static int same_descriptor(const host_texture_t *t)
{
    fxl_texture_t d;
    if (fxl_texture_init(&d, t->texels, t->width, t->height, FXL_TEXFMT_RGB565, t->tex.levels) != FXL_OK)
        return 0;
    return d.log2_w == t->tex.log2_w && d.log2_h == t->tex.log2_h && d.levels == t->tex.levels &&
           d.format == t->tex.format && d.wrap_u == t->tex.wrap_u && d.wrap_v == t->tex.wrap_v &&
           d.flags == t->tex.flags && d.reserved == t->tex.reserved && d.key == t->tex.key &&
           d.border == t->tex.border && t->tex.palette == NULL && t->tex.texels == (const void *)t->texels;
}

/* The texture_id_t whose texture_make output has t's texels and
 * descriptor, or -1. */
static int texture_id_of(const host_texture_t *t)
{
    int id;
    for (id = 0; id < (int)TEXTURE_COUNT; id++) {
        host_texture_t c;
        int same;
        if (texture_make(&c, (texture_id_t)id) != 0)
            return -1;
        same = c.width == t->width && c.height == t->height && c.texel_count == t->texel_count &&
               c.tex.levels == t->tex.levels && c.tex.wrap_u == t->tex.wrap_u && c.tex.wrap_v == t->tex.wrap_v &&
               c.tex.flags == t->tex.flags && c.tex.key == t->tex.key && c.tex.border == t->tex.border &&
               memcmp(c.texels, t->texels, (size_t)t->texel_count * sizeof(uint16_t)) == 0;
        texture_free(&c);
        if (same)
            return id;
    }
    return -1;
}

static int same_mat(const fxl_mat4_t *a, const fxl_mat4_t *b)
{
    return memcmp(a->m, b->m, sizeof a->m) == 0;
}

/* Field by field (fxl_light_t has padding): what a draw reads. */
static const char *pipe_difference(const fxl_pipeline_t *a, const fxl_pipeline_t *b)
{
    int k;
    if (!same_mat(&a->model, &b->model))
        return "model";
    if (!same_mat(&a->view, &b->view))
        return "view";
    if (!same_mat(&a->proj, &b->proj))
        return "proj";
    if (a->near_q16 != b->near_q16 || a->far_q16 != b->far_q16)
        return "near/far";
    if (a->vp_x != b->vp_x || a->vp_y != b->vp_y || a->vp_w != b->vp_w || a->vp_h != b->vp_h)
        return "viewport";
    if (a->cull != b->cull || a->lighting != b->lighting || a->material != b->material)
        return "cull/lighting/material";
    if (a->light.dir.x != b->light.dir.x || a->light.dir.y != b->light.dir.y || a->light.dir.z != b->light.dir.z)
        return "light.dir";
    for (k = 0; k < 3; k++)
        if (a->light.ambient[k] != b->light.ambient[k] || a->light.diffuse[k] != b->light.diffuse[k])
            return "light intensities";
    if (a->texgen.mode != b->texgen.mode || a->texgen.space != b->texgen.space ||
        a->texgen.plane != b->texgen.plane || a->texgen.axis != b->texgen.axis ||
        a->texgen.scale_u != b->texgen.scale_u || a->texgen.scale_v != b->texgen.scale_v ||
        a->texgen.offset_u != b->texgen.offset_u || a->texgen.offset_v != b->texgen.offset_v)
        return "texgen";
    if (a->vcache != NULL || b->vcache != NULL)
        return "vertex cache";
    return NULL;
}

/* The camera of pipe_scenes.h (60 degrees, aspect = W / H as q16
 * rounded to nearest, the scene's near and far): det_pipe_build must
 * reproduce the host's projection from it, which pipe_difference checks. */
static void camera_of(const pscene_t *ps, det_pscene_t *cam)
{
    memset(cam, 0, sizeof *cam);
    cam->name = ps->name;
    cam->fovy = FXL_ANGLE_DEG(60);
    cam->aspect = (fxl_q16_t)(((int64_t)ps->width * 65536 + ps->height / 2) / ps->height);
    cam->near_q16 = ps->part[0].pipe.near_q16;
    cam->far_q16 = ps->part[0].pipe.far_q16;
}

/* Part i of ps as det_ppart_t (mesh pointers left to the caller). The
 * model is translate(t) rot_y rot_x (model_trs): its translation column is
 * t exactly (the rotations have none and fxl_mat4_mul's products with 1.0
 * and 0 are exact), its row 1 is rot_x's and its column 0 rot_y's; every
 * angle whose builder gives those entries is tried. Returns 0, or -1 with
 * a message when no (rot_x, rot_y) rebuilds the host's pipeline. */
static int part_of(const pscene_t *ps, int i, const det_pscene_t *cam, det_ppart_t *pt)
{
    const fxl_pipeline_t *hp = &ps->part[i].pipe;
    const fxl_mat4_t *m = &hp->model;
    static fxl_angle_t ax[64], ay[64];
    int nx = 0, ny = 0, jx, jy;
    uint32_t a;
    const char *why = "no rotation angles";
    memset(pt, 0, sizeof *pt);
    for (a = 0; a < 65536u; a++) {
        fxl_mat4_t r;
        fxl_mat4_rotate_x(&r, (fxl_angle_t)a);
        if (nx < 64 && r.m[1][1] == m->m[1][1] && r.m[1][2] == m->m[1][2])
            ax[nx++] = (fxl_angle_t)a;
        fxl_mat4_rotate_y(&r, (fxl_angle_t)a);
        if (ny < 64 && r.m[0][0] == m->m[0][0] && r.m[2][0] == m->m[2][0])
            ay[ny++] = (fxl_angle_t)a;
    }
    pt->t.x = m->m[0][3];
    pt->t.y = m->m[1][3];
    pt->t.z = m->m[2][3];
    pt->texgen = hp->texgen;
    pt->cull = hp->cull;
    pt->lighting = hp->lighting;
    pt->material = hp->material;
    pt->light = hp->light;
    pt->lit = ps->part[i].lit;
    for (jx = 0; jx < nx; jx++) {
        for (jy = 0; jy < ny; jy++) {
            fxl_pipeline_t p;
            pt->rot_x = ax[jx];
            pt->rot_y = ay[jy];
            if (det_pipe_build(cam, pt, &p) != FXL_OK) {
                why = "det_pipe_build failed";
                continue;
            }
            why = pipe_difference(&p, hp);
            if (why == NULL)
                return 0;
        }
    }
    fprintf(stderr, "gen_data: %s part %d: det_pipe_build cannot rebuild the host's pipeline (%s differs)\n",
            ps->name, i, why);
    return -1;
}

static void emit_mesh(FILE *f, const char *stem, const fxl_mesh_t *m)
{
    uint32_t k;
    fprintf(f, "static const fxl_vec3_t %s_pos[%u] = {", stem, (unsigned)m->vert_count);
    for (k = 0; k < m->vert_count; k++)
        fprintf(f, "%s{%ld,%ld,%ld},", k % 4 ? "" : "\n", (long)m->pos[k].x, (long)m->pos[k].y,
                (long)m->pos[k].z);
    fprintf(f, "};\n");
    if (m->normal != NULL) {
        fprintf(f, "static const fxl_vec3_t %s_normal[%u] = {", stem, (unsigned)m->vert_count);
        for (k = 0; k < m->vert_count; k++)
            fprintf(f, "%s{%ld,%ld,%ld},", k % 4 ? "" : "\n", (long)m->normal[k].x, (long)m->normal[k].y,
                    (long)m->normal[k].z);
        fprintf(f, "};\n");
    }
    if (m->uv != NULL) {
        fprintf(f, "static const fxl_texcoord_t %s_uv[%u] = {", stem, (unsigned)m->vert_count);
        for (k = 0; k < m->vert_count; k++)
            fprintf(f, "%s{%ld,%ld},", k % 6 ? "" : "\n", (long)m->uv[k].u, (long)m->uv[k].v);
        fprintf(f, "};\n");
    }
    if (m->color != NULL) {
        fprintf(f, "static const uint16_t %s_color[%u] = {", stem, (unsigned)m->vert_count);
        for (k = 0; k < m->vert_count; k++)
            fprintf(f, "%s0x%04X,", k % 12 ? "" : "\n", m->color[k]);
        fprintf(f, "};\n");
    }
    fprintf(f, "static const uint16_t %s_idx[%u] = {", stem, (unsigned)(3u * m->tri_count));
    for (k = 0; k < 3u * m->tri_count; k++)
        fprintf(f, "%s%u,", k % 18 ? "" : "\n", (unsigned)m->idx[k]);
    fprintf(f, "};\n");
}

/* Writes the det_ppart_t initialiser of part pt whose arrays emit_mesh
 * wrote under `stem`. */
static void emit_part(FILE *f, const char *stem, const fxl_mesh_t *m, const det_ppart_t *pt)
{
    const fxl_texgen_t *g = &pt->texgen;
    const fxl_light_t *l = &pt->light;
    fprintf(f, "{{%s_pos, ", stem);
    if (m->uv != NULL)
        fprintf(f, "%s_uv, ", stem);
    else
        fprintf(f, "NULL, ");
    if (m->color != NULL)
        fprintf(f, "%s_color, ", stem);
    else
        fprintf(f, "NULL, ");
    if (m->normal != NULL)
        fprintf(f, "%s_normal, ", stem);
    else
        fprintf(f, "NULL, ");
    fprintf(f, "%uu, %s_idx, %uu},\n", (unsigned)m->vert_count, stem, (unsigned)m->tri_count);
    fprintf(f, " %u, %u, {%ld, %ld, %ld},\n", (unsigned)pt->rot_x, (unsigned)pt->rot_y, (long)pt->t.x,
            (long)pt->t.y, (long)pt->t.z);
    fprintf(f, " {%u, %u, %u, %u, %ld, %ld, %ld, %ld},\n", g->mode, g->space, g->plane, g->axis, (long)g->scale_u,
            (long)g->scale_v, (long)g->offset_u, (long)g->offset_v);
    fprintf(f, " %u, %u, 0x%04X, {{%ld, %ld, %ld}, {%u, %u, %u}, {%u, %u, %u}}, %d, %d},\n", pt->cull,
            pt->lighting, pt->material, (long)l->dir.x, (long)l->dir.y, (long)l->dir.z, l->ambient[0],
            l->ambient[1], l->ambient[2], l->diffuse[0], l->diffuse[1], l->diffuse[2], pt->tex, pt->lit);
}

/* The pipeline scenes: meshes, parts, scene table. Marks the textures
 * they use in used[]. */
static int emit_pscenes(FILE *f, int used[TEXTURE_COUNT])
{
    size_t i, n = pscene_count();
    uint32_t cache_max = 0;
    for (i = 0; i < n; i++) {
        pscene_t ps;
        det_pscene_t cam;
        det_ppart_t pt[PSCENE_MAX_PARTS];
        char stem[64];
        uint32_t cache = 0;
        int k;
        if (pscene_build(pscene_name(i), DET_W, DET_H, 0, &ps) != SCENE_OK) {
            fprintf(stderr, "gen_data: pipeline scene %s failed\n", pscene_name(i));
            return -1;
        }
        camera_of(&ps, &cam);
        for (k = 0; k < ps.parts; k++) {
            if (part_of(&ps, k, &cam, &pt[k]) != 0) {
                pscene_free(&ps);
                return -1;
            }
            pt[k].tex = texture_id_of(&ps.tex[ps.part[k].tex]);
            if (pt[k].tex < 0 || !same_descriptor(&ps.tex[ps.part[k].tex])) {
                fprintf(stderr, "gen_data: %s part %d: texture is not a texture_make one\n", ps.name, k);
                pscene_free(&ps);
                return -1;
            }
            used[pt[k].tex] = 1;
            if (ps.part[k].mesh.vert_count > cache)
                cache = ps.part[k].mesh.vert_count;
            snprintf(stem, sizeof stem, "det_p%u_%d", (unsigned)i, k);
            emit_mesh(f, stem, &ps.part[k].mesh);
        }
        fprintf(f, "static const det_ppart_t det_p%u_parts[%d] = {\n", (unsigned)i, ps.parts);
        for (k = 0; k < ps.parts; k++) {
            snprintf(stem, sizeof stem, "det_p%u_%d", (unsigned)i, k);
            emit_part(f, stem, &ps.part[k].mesh, &pt[k]);
        }
        fprintf(f, "};\n");
        if (cache > cache_max)
            cache_max = cache;
        pscene_free(&ps);
    }
    fprintf(f, "\nstatic const det_pscene_t det_pscenes[%u] = {\n", (unsigned)n);
    for (i = 0; i < n; i++) {
        pscene_t ps;
        det_pscene_t cam;
        uint32_t cache = 0;
        int k;
        if (pscene_build(pscene_name(i), DET_W, DET_H, 0, &ps) != SCENE_OK)
            return -1;
        camera_of(&ps, &cam);
        for (k = 0; k < ps.parts; k++)
            if (ps.part[k].mesh.vert_count > cache)
                cache = ps.part[k].mesh.vert_count;
        fprintf(f, "{\"%s\", %u, %ld, %ld, %ld, det_p%u_parts, %d, %uu},\n", ps.name, (unsigned)cam.fovy,
                (long)cam.aspect, (long)cam.near_q16, (long)cam.far_q16, (unsigned)i, ps.parts, (unsigned)cache);
        pscene_free(&ps);
    }
    fprintf(f, "};\n#define DET_NPSCENES %u\n#define DET_PIPE_CACHE_MAX %uu /* largest cache_entries */\n",
            (unsigned)n, (unsigned)cache_max);
    return 0;
}

/* Looks up the golden CRC of every front-end frame with a golden key and
 * writes "<scene> <variant> FXL_OK <crc32 hex>" (det_main's line) for each
 * found. Returns the number written, or -1 when a file cannot be used. */
static int emit_expected(const char *golden_path, const char *expected_path)
{
    FILE *g = fopen(golden_path, "r"), *e;
    char line[256];
    size_t i;
    int k, written = 0;
    if (g == NULL) {
        perror(golden_path);
        return -1;
    }
    e = fopen(expected_path, "w");
    if (e == NULL) {
        perror(expected_path);
        fclose(g);
        return -1;
    }
    for (i = 0; i < pscene_count(); i++) {
        for (k = 0; k < DET_NPVARIANTS; k++) {
            const det_pvariant_t *pv = &det_pvariants[k];
            char key[160];
            size_t len;
            int found = 0;
            if (pv->golden_key == NULL)
                continue;
            len = (size_t)snprintf(key, sizeof key, "%s%s %s 0x", pv->golden_prefix, pscene_name(i),
                                   pv->golden_key);
            rewind(g);
            while (!found && fgets(line, sizeof line, g) != NULL) {
                unsigned long crc;
                if (strncmp(line, key, len) == 0 && sscanf(line + len, "%lx", &crc) == 1) {
                    fprintf(e, "%s %s FXL_OK %08lx\n", pscene_name(i), pv->v.name, crc);
                    found = 1;
                    written++;
                }
            }
        }
    }
    fclose(g);
    fclose(e);
    return written;
}

int main(int argc, char **argv)
{
    FILE *f;
    size_t i, n = scene_count();
    int t, used[TEXTURE_COUNT] = {0};
    if (argc != 2 && argc != 4) {
        fprintf(stderr, "usage: gen_data OUT.h [GALLERY_CRC.txt EXPECTED.txt]\n");
        return 2;
    }
    if (PANEL_CLEAR_RGB565 != DET_PANEL_CLEAR) {
        fprintf(stderr, "gen_data: DET_PANEL_CLEAR is not scene.h's PANEL_CLEAR_RGB565\n");
        return 1;
    }
    f = fopen(argv[1], "w");
    if (!f) {
        perror(argv[1]);
        return 1;
    }
    fprintf(f, "/* generated by determinism/gen_data.c - do not edit */\n#include <stddef.h>\n#include <stdint.h>\n"
               "#include \"fixel/fixel.h\"\n#include \"det_entries.h\"\n\n");
    for (i = 0; i < n; i++) {
        scene_t s;
        if (scene_build(scene_name(i), DET_W, DET_H, &s) != SCENE_OK) {
            fprintf(stderr, "gen_data: scene %s failed\n", scene_name(i));
            return 1;
        }
        if ((int)s.texture >= 0 && (int)s.texture < (int)TEXTURE_COUNT)
            used[s.texture] = 1;
        scene_free(&s);
    }
    if (emit_pscenes(f, used) != 0)
        return 1;
    for (t = 0; t < (int)TEXTURE_COUNT; t++) {
        host_texture_t ht;
        uint32_t k;
        if (!used[t]) {
            /* not used by a scene: an empty placeholder keeps the ids */
            fprintf(f, "static const uint16_t det_tex%d_texels[1] = {0};\n#define DET_TEX%d_W 1\n"
                       "#define DET_TEX%d_H 1\n#define DET_TEX%d_LEVELS 1\n", t, t, t, t);
            continue;
        }
        if (texture_make(&ht, (texture_id_t)t) != 0) {
            fprintf(stderr, "gen_data: texture %d failed\n", t);
            return 1;
        }
        if (!same_descriptor(&ht)) {
            fprintf(stderr, "gen_data: texture %d: fxl_texture_init gives another descriptor\n", t);
            return 1;
        }
        fprintf(f, "static const uint16_t det_tex%d_texels[%u] = {", t, (unsigned)ht.texel_count);
        for (k = 0; k < ht.texel_count; k++)
            fprintf(f, "%s0x%04X,", k % 12 ? "" : "\n", ht.texels[k]);
        fprintf(f, "};\n#define DET_TEX%d_W %u\n#define DET_TEX%d_H %u\n#define DET_TEX%d_LEVELS %u\n", t,
                (unsigned)ht.width, t, (unsigned)ht.height, t, (unsigned)ht.tex.levels);
        texture_free(&ht);
    }
    fprintf(f, "static const uint16_t *const det_tex_texels[%d] = {", (int)TEXTURE_COUNT);
    for (t = 0; t < (int)TEXTURE_COUNT; t++)
        fprintf(f, "det_tex%d_texels,", t);
    fprintf(f, "};\nstatic const uint32_t det_tex_dims[%d][3] = {", (int)TEXTURE_COUNT);
    for (t = 0; t < (int)TEXTURE_COUNT; t++)
        fprintf(f, "{DET_TEX%d_W, DET_TEX%d_H, DET_TEX%d_LEVELS},", t, t, t);
    fprintf(f, "};\n#define DET_NTEXTURES %d\n\n", (int)TEXTURE_COUNT);
    for (i = 0; i < n; i++) {
        scene_t s;
        uint32_t k;
        if (scene_build(scene_name(i), DET_W, DET_H, &s) != SCENE_OK)
            return 1;
        fprintf(f, "static const fxl_vertex_t det_scene%u_verts[%u] = {", (unsigned)i, (unsigned)(3 * s.tri_count));
        for (k = 0; k < 3 * s.tri_count; k++) {
            const fxl_vertex_t *v = &s.verts[k];
            fprintf(f, "\n{%ld,%ld,%luu,%ld,%ld,0x%04X},", (long)v->x, (long)v->y, (unsigned long)v->inv_w,
                    (long)v->u, (long)v->v, v->color);
        }
        fprintf(f, "};\n");
        scene_free(&s);
    }
    fprintf(f, "\ntypedef struct det_scene { const char *name; const fxl_vertex_t *verts; uint32_t tris; int tex; } det_scene_t;\n");
    fprintf(f, "static const det_scene_t det_scenes[] = {\n");
    for (i = 0; i < n; i++) {
        scene_t s;
        if (scene_build(scene_name(i), DET_W, DET_H, &s) != SCENE_OK)
            return 1;
        fprintf(f, "{\"%s\", det_scene%u_verts, %u, %d},\n", scene_name(i), (unsigned)i, (unsigned)s.tri_count,
                (int)s.texture);
        scene_free(&s);
    }
    fprintf(f, "};\n#define DET_NSCENES %u\n", (unsigned)n);
    fclose(f);
    if (argc == 4) {
        int w = emit_expected(argv[2], argv[3]);
        if (w < 0)
            return 1;
        printf("gen_data: %d front-end frames have a golden CRC in %s\n", w, argv[2]);
    }
    return 0;
}
