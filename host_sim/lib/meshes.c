/* meshes.c - host-side mesh builders; see meshes.h. */
#define _POSIX_C_SOURCE 200809L
#include "meshes.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

static fxl_q16_t q16(double v) { return (fxl_q16_t)lround(v * 65536.0); }

static fxl_vec3_t v3(double x, double y, double z)
{
    fxl_vec3_t v;
    v.x = q16(x); v.y = q16(y); v.z = q16(z);
    return v;
}

/* Allocate the arrays of a mesh with normals and texture coordinates. */
static int alloc_mesh(fxl_mesh_t *m, uint32_t verts, uint32_t tris, fxl_vec3_t **pos,
                      fxl_vec3_t **nrm, fxl_texcoord_t **uv, uint16_t **idx)
{
    memset(m, 0, sizeof *m);
    if (verts == 0 || verts > 65535u || tris == 0) return -1;
    *pos = calloc(verts, sizeof **pos);
    *nrm = calloc(verts, sizeof **nrm);
    *uv = calloc(verts, sizeof **uv);
    *idx = calloc((size_t)tris * 3, sizeof **idx);
    if (!*pos || !*nrm || !*uv || !*idx) {
        free(*pos); free(*nrm); free(*uv); free(*idx);
        return -1;
    }
    m->pos = *pos; m->normal = *nrm; m->uv = *uv; m->idx = *idx;
    m->vert_count = verts;
    m->tri_count = tris;
    return 0;
}

/* Two counter-clockwise triangles for the quad a b c d (in that order
 * around, counter-clockwise seen from the front). */
static uint16_t *quad(uint16_t *o, uint32_t a, uint32_t b, uint32_t c, uint32_t d)
{
    o[0] = (uint16_t)a; o[1] = (uint16_t)b; o[2] = (uint16_t)c;
    o[3] = (uint16_t)a; o[4] = (uint16_t)c; o[5] = (uint16_t)d;
    return o + 6;
}

int meshes_sphere(fxl_mesh_t *m, double radius, int slices, int stacks)
{
    fxl_vec3_t *pos, *nrm;
    fxl_texcoord_t *uv;
    uint16_t *idx, *o;
    uint32_t ring = (uint32_t)slices + 1, verts, tris, i, j;
    if (!m || radius <= 0 || slices < 3 || stacks < 2) return -1;
    /* two poles + (stacks - 1) rings of slices + 1 (duplicated seam) */
    verts = 2 + (uint32_t)(stacks - 1) * ring;
    tris = 2 * (uint32_t)slices * (uint32_t)(stacks - 1);
    if (alloc_mesh(m, verts, tris, &pos, &nrm, &uv, &idx) != 0) return -1;
    /* vertex 0: north pole (+y), 1: south pole, then rings from the north */
    pos[0] = v3(0, radius, 0); nrm[0] = v3(0, 1, 0); uv[0].u = q16(0.5); uv[0].v = 0;
    pos[1] = v3(0, -radius, 0); nrm[1] = v3(0, -1, 0); uv[1].u = q16(0.5); uv[1].v = q16(1);
    for (i = 1; i < (uint32_t)stacks; i++) {
        double phi = PI * i / stacks;
        for (j = 0; j < ring; j++) {
            /* theta measured as texgen does about y: a = z, b = x */
            double th = 2 * PI * j / slices;
            double x = sin(phi) * sin(th), y = cos(phi), z = sin(phi) * cos(th);
            uint32_t k = 2 + (i - 1) * ring + j;
            pos[k] = v3(radius * x, radius * y, radius * z);
            nrm[k] = v3(x, y, z);
            uv[k].u = q16((double)j / slices);
            uv[k].v = q16((double)i / stacks);
        }
    }
    o = idx;
    for (j = 0; j < (uint32_t)slices; j++) {
        uint32_t a = 2 + j, b = 2 + j + 1;
        uint32_t c = 2 + (uint32_t)(stacks - 2) * ring + j, d = c + 1;
        /* theta grows from +z toward +x: seen from outside, counter-clockwise
         * is pole -> current -> next for the north cap */
        o[0] = 0; o[1] = (uint16_t)a; o[2] = (uint16_t)b; o += 3;
        o[0] = 1; o[1] = (uint16_t)d; o[2] = (uint16_t)c; o += 3;
    }
    for (i = 1; i + 1 < (uint32_t)stacks; i++)
        for (j = 0; j < (uint32_t)slices; j++) {
            uint32_t a = 2 + (i - 1) * ring + j, b = a + 1, c = a + ring + 1, d = a + ring;
            o = quad(o, a, d, c, b);
        }
    return 0;
}

int meshes_cylinder(fxl_mesh_t *m, double radius, double y0, double y1, int slices, int rings,
                    int inside)
{
    fxl_vec3_t *pos, *nrm;
    fxl_texcoord_t *uv;
    uint16_t *idx, *o;
    uint32_t ring = (uint32_t)slices + 1, verts, tris, i, j;
    double s = inside ? -1 : 1;
    if (!m || radius <= 0 || slices < 3 || rings < 1 || y1 <= y0) return -1;
    verts = ((uint32_t)rings + 1) * ring;
    tris = 2 * (uint32_t)slices * (uint32_t)rings;
    if (alloc_mesh(m, verts, tris, &pos, &nrm, &uv, &idx) != 0) return -1;
    for (i = 0; i <= (uint32_t)rings; i++)
        for (j = 0; j < ring; j++) {
            double th = 2 * PI * j / slices, x = sin(th), z = cos(th);
            uint32_t k = i * ring + j;
            pos[k] = v3(radius * x, y0 + (y1 - y0) * i / rings, radius * z);
            nrm[k] = v3(s * x, 0, s * z);
            uv[k].u = q16((double)j / slices);
            uv[k].v = q16((double)i / rings);
        }
    o = idx;
    for (i = 0; i < (uint32_t)rings; i++)
        for (j = 0; j < (uint32_t)slices; j++) {
            uint32_t a = i * ring + j, b = a + 1, c = a + ring + 1, d = a + ring;
            /* outside: a b c d is counter-clockwise seen from outside */
            o = inside ? quad(o, a, d, c, b) : quad(o, a, b, c, d);
        }
    return 0;
}

int meshes_cube(fxl_mesh_t *m, double h)
{
    /* per face: normal, and the "right" and "up" directions seen from
     * outside (right x up = normal) */
    static const double face[6][3][3] = {
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},  {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},   {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}}};
    static const double corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    fxl_vec3_t *pos, *nrm;
    fxl_texcoord_t *uv;
    uint16_t *idx, *o;
    int f, c;
    if (!m || h <= 0) return -1;
    if (alloc_mesh(m, 24, 12, &pos, &nrm, &uv, &idx) != 0) return -1;
    o = idx;
    for (f = 0; f < 6; f++) {
        const double *n = face[f][0], *r = face[f][1], *u = face[f][2];
        for (c = 0; c < 4; c++) {
            double a = corner[c][0], b = corner[c][1];
            int k = f * 4 + c;
            pos[k] = v3(h * (n[0] + a * r[0] + b * u[0]), h * (n[1] + a * r[1] + b * u[1]),
                        h * (n[2] + a * r[2] + b * u[2]));
            nrm[k] = v3(n[0], n[1], n[2]);
            uv[k].u = q16((a + 1) / 2);
            uv[k].v = q16((1 - b) / 2); /* v = 0 at the face's top */
        }
        o = quad(o, (uint32_t)f * 4, (uint32_t)f * 4 + 1, (uint32_t)f * 4 + 2, (uint32_t)f * 4 + 3);
    }
    return 0;
}

int meshes_floor(fxl_mesh_t *m, double y, double x0, double x1, double z0, double z1, int nx,
                 int nz, double period)
{
    fxl_vec3_t *pos, *nrm;
    fxl_texcoord_t *uv;
    uint16_t *idx, *o;
    uint32_t i, j, row = (uint32_t)nx + 1;
    if (!m || nx < 1 || nz < 1 || x1 <= x0 || z1 <= z0 || period <= 0) return -1;
    if (alloc_mesh(m, row * ((uint32_t)nz + 1), 2 * (uint32_t)nx * (uint32_t)nz, &pos, &nrm, &uv,
                   &idx) != 0)
        return -1;
    for (i = 0; i <= (uint32_t)nz; i++)
        for (j = 0; j < row; j++) {
            double x = x0 + (x1 - x0) * j / nx, z = z0 + (z1 - z0) * i / nz;
            uint32_t k = i * row + j;
            pos[k] = v3(x, y, z);
            nrm[k] = v3(0, 1, 0);
            uv[k].u = q16(x / period);
            uv[k].v = q16(z / period);
        }
    o = idx;
    for (i = 0; i < (uint32_t)nz; i++)
        for (j = 0; j < (uint32_t)nx; j++) {
            uint32_t a = i * row + j, b = a + 1, c = a + row + 1, d = a + row;
            /* seen from +y, x right and z toward the viewer: a (x0, z0)
             * -> d (x0, z0 + dz) -> c -> b is counter-clockwise */
            o = quad(o, a, d, c, b);
        }
    return 0;
}

int meshes_set_color(fxl_mesh_t *m, uint16_t rgb565)
{
    uint16_t *c;
    uint32_t i;
    if (!m || m->vert_count == 0) return -1;
    c = malloc(m->vert_count * sizeof *c);
    if (!c) return -1;
    for (i = 0; i < m->vert_count; i++) c[i] = rgb565;
    free((void *)m->color);
    m->color = c;
    return 0;
}

void meshes_free(fxl_mesh_t *m)
{
    if (!m) return;
    /* the builders own these arrays; the const in fxl_mesh_t is for the core */
    free((void *)m->pos);
    free((void *)m->normal);
    free((void *)m->uv);
    free((void *)m->color);
    free((void *)m->idx);
    memset(m, 0, sizeof *m);
}
