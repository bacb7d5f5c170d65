/* test_vertex.h - vertices for the rasterizer tests, from doubles.
 * Positions in frame pixels and u, v in texture periods become q16; inv_w
 * (a fraction of the near plane's 1/w, in (0, 1]) becomes u0.32, never 0. */
#ifndef FXL_TEST_VERTEX_H
#define FXL_TEST_VERTEX_H

#include "fixel/raster.h"

fxl_vertex_t test_vertex(double x, double y, double inv_w, double u, double v, uint16_t color);

/* A view-space point (camera looking down -z, near plane at w = 1) through
 * the scenes' projection: 60 degree vertical field of view, 320x240, white. */
fxl_vertex_t test_project(double x, double y, double z, double u, double v);

#endif
