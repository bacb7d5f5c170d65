/* meshes.h - host-side builders of fixel meshes (fxl_mesh_t, pipeline.h):
 * UV sphere, cylinder / tunnel, cube, floor grid. Positions, normals and
 * texture coordinates are computed in double and stored as q16; arrays are
 * malloc'd (host only) and released with meshes_free().
 *
 * Winding: front faces are counter-clockwise seen from the side the normals
 * point to (OpenGL convention), so draw them with FXL_CULL_CW. The tunnel is
 * the inside of a cylinder: its normals point to the axis.
 * Texture coordinates are the natural parametric ones (sphere: u = theta,
 * v = phi / pi, with a duplicated seam column; cylinder: u around, v along
 * the axis; cube: 0..1 per face, v = 0 at the face's top; floor: u = x /
 * period, v = z / period); texgen in the pipeline may replace them.
 * All builders return 0 on success, -1 on bad arguments or out of memory
 * (and then leave *m empty).
 */
#ifndef FIXEL_HOST_MESHES_H
#define FIXEL_HOST_MESHES_H

#include "fixel/pipeline.h"

/* Sphere of `radius` about the origin, axis y, slices >= 3 around,
 * stacks >= 2 from pole to pole. Pole rows are single vertices shared by a
 * fan, so texgen's pole handling applies. */
int meshes_sphere(fxl_mesh_t *m, double radius, int slices, int stacks);
/* Cylinder about the y axis from y = y0 to y1, `slices` around, `rings`
 * quads along; inside != 0 makes a tunnel (faces and normals inward). */
int meshes_cylinder(fxl_mesh_t *m, double radius, double y0, double y1, int slices, int rings,
                    int inside);
/* Axis-aligned cube of half-size h about the origin: 24 vertices (flat
 * normals per face), 12 triangles. */
int meshes_cube(fxl_mesh_t *m, double h);
/* Floor in the plane y = y, x in [x0, x1], z in [z0, z1], nx x nz quads,
 * facing +y; u = x / period, v = z / period. */
int meshes_floor(fxl_mesh_t *m, double y, double x0, double x1, double z0, double z1, int nx,
                 int nz, double period);
/* Per-vertex colours (RGB565) for an existing mesh: all `rgb565`. */
int meshes_set_color(fxl_mesh_t *m, uint16_t rgb565);
void meshes_free(fxl_mesh_t *m);

#endif
